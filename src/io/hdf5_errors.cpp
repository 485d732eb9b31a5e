#include "hdf5_errors.hpp"

#include <sys/mman.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string_view>
#include <vector>

namespace growthuq::hdf5 {

struct WriteFailureGuard::State {
  std::string name;
  int descriptor = -1;  // the sec2 driver's; -1 when HDF5 did not give it
  bool failed = false;
  bool in_memory = false;  // the descriptor now names an anonymous in-memory file
  std::string reason;
};

namespace {

// The files guarded now. Writers live on several threads (results.h5 is written on its own).
std::mutex registry_mutex;
std::vector<std::shared_ptr<WriteFailureGuard::State>>& registry() {
  static std::vector<std::shared_ptr<WriteFailureGuard::State>> files;
  return files;
}

// The text between `key` and the next quote in `text` ("filename = '", "error message = '").
std::string quoted_after(std::string_view text, std::string_view key) {
  const std::size_t start = text.find(key);
  if (start == std::string_view::npos) return {};
  const std::size_t from = start + key.size();
  const std::size_t end = text.find('\'', from);
  return std::string(text.substr(from, end == std::string_view::npos ? std::string_view::npos : end - from));
}

// What a failed system call in HDF5's sec2 driver says: its file and the system's reason.
struct IoFailure {
  std::string file;
  std::string reason;
};

herr_t find_io_failure(unsigned, const H5E_error2_t* error, void* data) {
  auto* failure = static_cast<IoFailure*>(data);
  if (error->desc == nullptr || !failure->file.empty()) return 0;
  const std::string_view text = error->desc;
  // The driver's own entry ("file write failed: ..., filename = '...', ..., error message = '...'").
  if (text.find("errno = ") == std::string_view::npos) return 0;
  failure->file = quoted_after(text, "filename = '");
  failure->reason = quoted_after(text, "error message = '");
  return 0;
}

// Moves `descriptor` onto an anonymous in-memory file (see the header).
void redirect_to_memory(int descriptor) {
  if (descriptor < 0) return;
  const int memory = ::memfd_create("growthuq-abandoned-hdf5", MFD_CLOEXEC);
  if (memory < 0) return;  // nothing better to do: HDF5 keeps failing on the full disk
  ::dup2(memory, descriptor);
  ::close(memory);
}

// HDF5's automatic error report, replaced: nothing printed (the C++ API's exception carries the
// failure to the caller, which says it in one line); a failed write abandons its guarded file.
herr_t on_error(hid_t stack, void*) {
  IoFailure failure;
  H5Ewalk2(stack, H5E_WALK_DOWNWARD, find_io_failure, &failure);
  if (failure.file.empty()) return 0;
  const std::lock_guard lock(registry_mutex);
  for (const std::shared_ptr<WriteFailureGuard::State>& file : registry()) {
    if (file->name != failure.file || file->failed) continue;
    file->failed = true;
    file->reason = failure.reason;
    if (!file->in_memory) redirect_to_memory(file->descriptor);
    file->in_memory = true;
  }
  return 0;
}

}  // namespace

void use_error_handler() {
  thread_local bool installed = false;
  if (installed) return;
  H5Eset_auto2(H5E_DEFAULT, on_error, nullptr);
  installed = true;
}

WriteFailureGuard::WriteFailureGuard(hid_t file, std::string name) : state_(std::make_shared<State>()) {
  use_error_handler();
  state_->name = std::move(name);
  void* handle = nullptr;
  if (H5Fget_vfd_handle(file, H5P_DEFAULT, &handle) >= 0 && handle != nullptr) {
    state_->descriptor = *static_cast<int*>(handle);
  }
  const std::lock_guard lock(registry_mutex);
  registry().push_back(state_);
}

WriteFailureGuard::~WriteFailureGuard() {
  const std::lock_guard lock(registry_mutex);
  std::erase(registry(), state_);
}

void WriteFailureGuard::abandon() {
  const std::lock_guard lock(registry_mutex);
  if (!state_->in_memory) redirect_to_memory(state_->descriptor);
  state_->in_memory = true;
}

void WriteFailureGuard::require_room_for_flush(hid_t file) {
  std::size_t max_size = 0, min_clean = 0, cached = 0;
  int entries = 0;
  if (H5Fget_mdc_size(file, &max_size, &min_clean, &cached, &entries) < 0) return;
  // What the cache holds (clean entries too: an upper bound of what it writes) and 64 KiB for
  // the metadata accumulator and the superblock. Measured on a full tmpfs: a small campaign's
  // final flush fit in 24 KiB with 56 KiB cached.
  const std::uint64_t needed = static_cast<std::uint64_t>(cached) + (std::uint64_t{64} << 10);
  const std::filesystem::path folder = std::filesystem::path(state_->name).parent_path();
  struct statvfs space {};
  if (::statvfs(folder.empty() ? "." : folder.c_str(), &space) != 0) return;
  const std::uint64_t free = static_cast<std::uint64_t>(space.f_bavail) * space.f_frsize;
  if (free >= needed) return;
  const std::lock_guard lock(registry_mutex);
  state_->failed = true;
  state_->reason = "No space left on device (" + std::to_string(free >> 10) + " KiB free, the file's last " +
                   std::to_string(needed >> 10) + " KiB would not fit)";
  if (!state_->in_memory) redirect_to_memory(state_->descriptor);
  state_->in_memory = true;
}

namespace {
std::atomic<bool> half_closed{false};
}  // namespace

bool file_left_half_closed() { return half_closed.load(); }
void note_file_left_half_closed() { half_closed.store(true); }

bool WriteFailureGuard::failed() const {
  const std::lock_guard lock(registry_mutex);
  return state_->failed;
}

std::string WriteFailureGuard::reason() const {
  const std::lock_guard lock(registry_mutex);
  return state_->reason;
}

}  // namespace growthuq::hdf5
