#include "hdf5_output_file.hpp"

#include "growthuq/io/output_file.hpp"

namespace growthuq::hdf5 {
namespace {

std::string failure_text(const WriteFailureGuard& guard) {
  const std::string reason = guard.reason();
  return "write failed: " + (reason.empty() ? std::string("the system refused a write") : reason);
}

}  // namespace

OutputFile::OutputFile(const std::string& path) : path_(path) {
  use_error_handler();
  try {
    // No sieve buffer: raw data reach the disk in the write that gives them, so a full disk
    // fails that write (an exception) rather than a later close in a destructor.
    H5::FileAccPropList access;
    H5Pset_sieve_buf_size(access.getId(), 0);
    file_ = std::make_unique<H5::H5File>(path_, H5F_ACC_TRUNC, H5::FileCreatPropList::DEFAULT, access);
  } catch (const H5::Exception& error) {
    throw WriteError(path_, "cannot create the HDF5 file (" + error.getDetailMsg() + ")");
  }
  guard_ = std::make_unique<WriteFailureGuard>(file_->getId(), path_);
}

OutputFile::~OutputFile() {
  if (!file_) return;
  use_error_handler();  // the destructor may run on another thread than the writes
  guard_->abandon();    // not kept: what HDF5 still flushes goes to memory, never to a full disk
  close_without_throwing();
}

bool OutputFile::close_without_throwing() {
  try {
    file_->close();
    file_.reset();
    return true;
  } catch (const H5::Exception&) {
    // HDF5 keeps the file half closed; closing it again (the destructor would) crashes.
    static_cast<void>(file_.release());
    note_file_left_half_closed();
    return false;
  }
}

void OutputFile::close() {
  use_error_handler();
  std::string flush_error;
  try {
    // Everything to the disk while the file is open: a full disk fails here, where the file
    // can still be closed (into memory), not inside the close.
    guard_->require_room_for_flush(file_->getId());
    if (!guard_->failed()) file_->flush(H5F_SCOPE_GLOBAL);
  } catch (const H5::Exception& error) {
    flush_error = error.getDetailMsg();  // a full disk: the guard holds the reason
  }
  if (guard_->failed()) {
    const std::string text = failure_text(*guard_);
    guard_->abandon();
    close_without_throwing();
    throw WriteError(path_, text);
  }
  if (!flush_error.empty()) guard_->abandon();
  const bool closed = close_without_throwing();
  if (guard_->failed()) throw WriteError(path_, failure_text(*guard_));
  if (!flush_error.empty()) throw WriteError(path_, "HDF5 write failed in H5Fflush: " + flush_error);
  if (!closed) throw WriteError(path_, "write failed: HDF5 could not close the file");
}

void OutputFile::rethrow(const H5::Exception& error) const {
  if (guard_->failed()) throw WriteError(path_, failure_text(*guard_));
  throw WriteError(path_, "HDF5 write failed in " + error.getFuncName() + ": " + error.getDetailMsg());
}

void OutputFile::throw_if_failed() const {
  if (guard_->failed()) throw WriteError(path_, failure_text(*guard_));
}

}  // namespace growthuq::hdf5
