// An HDF5 file written as a result (results.h5, indent --field's .h5): created without a sieve
// buffer, guarded against a full disk, and closed so that neither a failed write nor a full
// disk ever crashes or prints HDF5's diagnostics (io/hdf5_errors.hpp says why each step).
#pragma once

#include <H5Cpp.h>

#include <memory>
#include <string>

#include "hdf5_errors.hpp"

namespace growthuq::hdf5 {

class OutputFile {
 public:
  // Creates (truncates) `path`. WriteError naming it when HDF5 cannot.
  explicit OutputFile(const std::string& path);
  // Without close(): the file is abandoned (its descriptor moved to memory) and closed; the
  // caller removes it. Never throws.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  H5::H5File& file() { return *file_; }
  const std::string& path() const { return path_; }
  const WriteFailureGuard& guard() const { return *guard_; }

  // Checks the room, flushes and closes: WriteError naming the file ("write failed: No space
  // left on device") when any write failed, now or earlier; the file is then closed (into
  // memory) and the caller removes it.
  void close();
  // WriteError for a caught HDF5 exception: the system's reason when a write failed.
  [[noreturn]] void rethrow(const H5::Exception& error) const;
  // WriteError when a write failed without an exception reaching the caller (in a destructor).
  void throw_if_failed() const;

 private:
  // Whether the close succeeded (a failed one leaves the file to HDF5, half closed).
  bool close_without_throwing();

  std::string path_;
  std::unique_ptr<H5::H5File> file_;
  std::unique_ptr<WriteFailureGuard> guard_;
};

}  // namespace growthuq::hdf5
