// HDF5 failures as the project's one-line messages, and a file whose write failed (a full disk)
// closed without a crash.
//
// Why this exists (measured with Debian's HDF5 1.10.8, a thread-safe build, on a full tmpfs):
//  - HDF5 keeps its "print the error stack" setting per thread, so H5::Exception::dontPrint()
//    on the main thread left results.h5's writer thread printing ~40 lines of diagnostics on
//    stderr before the project's message.
//  - After a write failed on a full disk, closing the file must still flush metadata to it; that
//    flush fails too, H5Fclose leaves the file half closed, and the next close (the C++ API's
//    destructor, or HDF5's own clean-up at exit) dereferences it: SIGSEGV, exit 139.
//  - A write HDF5 buffers (its sieve buffer) fails only when flushed, which can be in a C++
//    destructor (DataSet::~DataSet prints "H5Dclose failed" on std::cerr and carries on).
// So the writer (results_h5.cpp) writes without a sieve buffer, flushes before it closes, and
// moves a file it abandons to memory before closing it; and
// the handler below prints nothing, records the system's reason, and moves the failed file's
// descriptor onto an anonymous in-memory file: what HDF5 still writes while datasets and the
// file are closed then succeeds (a few kB of metadata, in memory), and the owner removes the
// incomplete file on disk.
#pragma once

#include <hdf5.h>

#include <memory>
#include <string>

#include "growthuq/io/hdf5_exit.hpp"

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

  // The file will not be kept: its descriptor is moved to memory now, so closing it (which
  // flushes what HDF5 holds) cannot meet a full disk.
  void abandon();
  // Before the flush of what HDF5 holds in memory (its metadata cache): when the file's file
  // system has less room free than that flush needs (with a margin), the file is abandoned and
  // failed() is true. A flush that fails half way leaves HDF5 unable to close the file at all;
  // this check keeps a disk that is already full from getting there.
  void require_room_for_flush(hid_t file);
  // Whether a write failed on the file (its content on disk is incomplete).
  bool failed() const;
  // The system's reason for the first failed write ("No space left on device"), or empty.
  std::string reason() const;

  struct State;

 private:
  std::shared_ptr<State> state_;
};

}  // namespace growthuq::hdf5
