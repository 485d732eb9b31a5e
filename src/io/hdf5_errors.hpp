// HDF5 failures as the project's one-line messages, and a file whose write failed (a full disk)
// closed without a crash.
//
// Why this exists (measured with Debian's HDF5 1.10.8, a thread-safe build):
//  - HDF5 keeps its "print the error stack" setting per thread, so H5::Exception::dontPrint()
//    on the main thread left results.h5's writer thread printing ~40 lines of diagnostics on
//    stderr before the project's message.
//  - After a write failed on a full disk, closing the file must still flush metadata to it; that
//    flush fails too, H5Fclose leaves the file half closed, and the next close (the C++ API's
//    destructor, or HDF5's own clean-up at exit) dereferences it: SIGSEGV, exit 139.
// The handler below prints nothing, records the system's reason, and moves the failed file's
// descriptor onto an anonymous in-memory file: what HDF5 still writes while datasets and the
// file are closed then succeeds (a few kB of metadata, in memory), and the owner removes the
// incomplete file on disk.
#pragma once

#include <hdf5.h>

#include <memory>
#include <string>

namespace growthuq::hdf5 {

// Installs the handler on the calling thread (HDF5's setting is per thread); cheap after the
// first call on a thread. Every function that calls HDF5 calls this first.
void use_error_handler();

// While alive, a low-level write that fails on `file` (created or opened as `name`, with HDF5's
// default sec2 driver) abandons it as described above. One per open file, destroyed after the
// file is closed.
class WriteFailureGuard {
 public:
  WriteFailureGuard(hid_t file, std::string name);
  ~WriteFailureGuard();
  WriteFailureGuard(const WriteFailureGuard&) = delete;
  WriteFailureGuard& operator=(const WriteFailureGuard&) = delete;

  // Whether a write failed on the file (its content on disk is incomplete).
  bool failed() const;
  // The system's reason for the first failed write ("No space left on device"), or empty.
  std::string reason() const;

  struct State;

 private:
  std::shared_ptr<State> state_;
};

}  // namespace growthuq::hdf5
