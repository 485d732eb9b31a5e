#include "hdf5_errors.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <mutex>
#include <string_view>
#include <vector>

namespace growthuq::hdf5 {

struct WriteFailureGuard::State {
  std::string name;
  int descriptor = -1;  // the sec2 driver's; -1 when HDF5 did not give it
  bool failed = false;
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
    redirect_to_memory(file->descriptor);
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

bool WriteFailureGuard::failed() const {
  const std::lock_guard lock(registry_mutex);
  return state_->failed;
}

std::string WriteFailureGuard::reason() const {
  const std::lock_guard lock(registry_mutex);
  return state_->reason;
}

}  // namespace growthuq::hdf5
