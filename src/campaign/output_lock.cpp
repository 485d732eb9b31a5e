#include "campaign/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "growthuq/core/error.hpp"
#include "growthuq/io/output_file.hpp"

namespace growthuq {
namespace {

std::string system_reason() { return std::strerror(errno); }

// What the holder wrote into the lock file ("pid P on host H"), for the message.
std::string holder_of(int descriptor) {
  std::array<char, 512> text{};
  const ssize_t got = ::pread(descriptor, text.data(), text.size() - 1, 0);
  std::string holder(text.data(), got > 0 ? static_cast<std::size_t>(got) : 0);
  while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
  return holder.empty() ? "a process that has not yet said which" : holder;
}

std::string this_process() {
  std::array<char, 256> host{};
  if (::gethostname(host.data(), host.size() - 1) != 0) std::strcpy(host.data(), "?");
  return "pid " + std::to_string(::getpid()) + " on host " + host.data();
}

bool same_file(int descriptor, const std::string& path) {
  struct stat opened {}, named {};
  return ::fstat(descriptor, &opened) == 0 && ::stat(path.c_str(), &named) == 0 && opened.st_dev == named.st_dev &&
         opened.st_ino == named.st_ino;
}

InputError in_use(const std::string& directory, const std::string& holder, const std::string& lock_file) {
  return InputError(directory, "is in use by another growthuq run (" + holder + ", lock file " + lock_file +
                                   "): wait for it to end or stop it; two runs in one output directory would mix their files");
}

}  // namespace

void refuse_if_in_use(const std::string& directory) {
  const std::string path = (std::filesystem::path(directory) / run_lock_name).string();
  const int descriptor = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (descriptor < 0) return;  // no lock file: no live run (and nothing is created here)
  if (::flock(descriptor, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK) {
    const std::string holder = holder_of(descriptor);
    ::close(descriptor);
    throw in_use(directory, holder, path);
  }
  ::close(descriptor);  // releases the shared lock taken for the test
}

OutputDirectoryLock::OutputDirectoryLock(const std::string& directory)
    : path_((std::filesystem::path(directory) / run_lock_name).string()) {
  // A holder removes the file before it lets go; a file opened just before that removal is
  // locked in vain, so the lock counts only while the path still names the file locked.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int descriptor = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (descriptor < 0) throw WriteError(path_, "cannot create the output directory's lock file: " + system_reason());
    if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::string holder = holder_of(descriptor);
      ::close(descriptor);
      if (error == EWOULDBLOCK) throw in_use(directory, holder, path_);
      // A file system without locks (some network mounts): refused rather than unguarded.
      errno = error;
      throw WriteError(path_, "cannot lock the output directory: " + system_reason());
    }
    if (!same_file(descriptor, path_)) {
      ::close(descriptor);
      continue;
    }
    // Ours; what a dead holder wrote is replaced.
    const std::string record = this_process() + "\n";
    if (::ftruncate(descriptor, 0) != 0 || ::pwrite(descriptor, record.data(), record.size(), 0) != static_cast<ssize_t>(record.size())) {
      const std::string reason = system_reason();
      ::unlink(path_.c_str());
      ::close(descriptor);
      throw WriteError(path_, "cannot write the output directory's lock file: " + reason);
    }
    descriptor_ = descriptor;
    return;
  }
  throw InputError(directory, "its lock file " + path_ + " keeps being replaced: another growthuq run is starting there");
}

OutputDirectoryLock::~OutputDirectoryLock() {
  if (descriptor_ < 0) return;
  ::unlink(path_.c_str());
  ::close(descriptor_);
}

}  // namespace growthuq
