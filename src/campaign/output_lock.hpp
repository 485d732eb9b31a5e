// One live run per output directory. A run holds an exclusive lock (flock) on DIR/run.lock from
// before it looks at the directory until it is done; a second run into the same directory
// (a rerun, a --resume, a --force, on any host that shares the file system's locks) is refused
// naming the directory and the holder's pid and host. The kernel drops the lock when its
// holder dies, however it dies (kill -9, a lost node): a lock file left by a dead run is taken
// over without a word. Under mpirun only the coordinator locks (run_campaign_with_outputs).
#pragma once

#include <string>

namespace growthuq {

inline constexpr const char* run_lock_name = "run.lock";

// Without taking the lock or creating anything: the InputError the lock gives when a live run
// holds `directory` (the checks made before the work, and `growthuq check`, say "in use" rather
// than "already exists" or "holds an interrupted run").
void refuse_if_in_use(const std::string& directory);

class OutputDirectoryLock {
 public:
  // Locks `directory` (which must exist), writing "pid P on host H" into its lock file.
  // InputError naming the directory and the holder when another live process holds it, or
  // naming the lock file when it cannot be created.
  explicit OutputDirectoryLock(const std::string& directory);
  // Removes the lock file (while still holding it), then releases the lock.
  ~OutputDirectoryLock();
  OutputDirectoryLock(const OutputDirectoryLock&) = delete;
  OutputDirectoryLock& operator=(const OutputDirectoryLock&) = delete;

 private:
  std::string path_;
  int descriptor_ = -1;
};

}  // namespace growthuq
