// Writing result files so that a failure never leaves a half-written file that looks
// complete, an existing result is never overwritten unless the user asked for it, and nothing
// but a regular file is ever replaced: --force run as root over /dev/null would otherwise
// rename a regular file over the device node.
#pragma once

#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "growthuq/core/error.hpp"

namespace growthuq {

enum class Overwrite { refuse, allow };

// An InputError raised because a result or a checkpoint could not be written (a full disk, a
// quota, a file system gone read-only): nothing is wrong with the input, and what was kept
// before (a run's checkpoint) stays valid for finishing once there is room.
class WriteError : public InputError {
 public:
  using InputError::InputError;
};

class RemovedOnSignal;  // core/interrupt.hpp

// Writes `content` to `path` through "<path>.partial" and an atomic rename. With
// Overwrite::refuse an existing `path` is an InputError that names it and suggests --force.
// I/O failures are InputErrors naming the path and the system's reason.
void write_file_atomically(const std::string& path, std::string_view content,
                           Overwrite overwrite);

// A file written piece by piece through "<path>.partial" and renamed into place by commit():
// destroyed before commit() (a failure, an interruption), it removes the partial file, so no
// half-written file looks complete; a signal that ends the process removes it too. Whether an
// existing regular file at `path` may be replaced is the caller's to check first
// (check_can_write); a `path` that is not a regular file is refused here already (and again by
// commit(), in case one appeared meanwhile). I/O failures are InputErrors naming the file and
// the reason.
class PartialFile {
 public:
  explicit PartialFile(std::string path);
  PartialFile(const PartialFile&) = delete;
  PartialFile& operator=(const PartialFile&) = delete;
  ~PartialFile();

  void write(std::string_view text);
  // Flushes and closes: InputError (WriteError) when the data did not all reach the file (a
  // full disk shows here at the latest). Nothing is renamed yet.
  void close();
  // close(), then renames to the final path.
  void commit();

 private:
  std::string path_;
  std::string partial_;
  std::ofstream out_;
  std::unique_ptr<RemovedOnSignal> removed_on_signal_;
  bool committed_ = false;
};

struct FileContent {
  std::string path;
  std::string content;
};

// Files that belong together (one refers to another): every one is written in full to its
// partial file first, and only then are they renamed into place, in the order given (a file
// naming the others last). A failure while writing (a full disk) leaves none of them, and none
// of the earlier ones replaced. Overwrite as write_file_atomically.
void write_files_together(const std::vector<FileContent>& files, Overwrite overwrite);

// Whether the folder an output goes into must exist already (most commands), or is created by
// the command (synth's per-line folders, tradeoff's table): then its nearest existing ancestor
// is checked instead.
enum class Folder { must_exist, created_if_missing };

// InputError when `path` exists and overwriting was not allowed, when it exists and is not
// a regular file (a directory, a device, a FIFO, a socket; a symbolic link counts as what it
// points to), whatever `overwrite` says, or when its folder does not exist, is not a folder or
// is not writable (checked before long work starts, so a run does not fail only at its end).
// "-" (standard output, for the commands that print a result there) is an InputError too:
// never a file named "-".
void check_can_write(const std::string& path, Overwrite overwrite, Folder folder = Folder::must_exist);

// The steps every writer shares (PartialFile, results.h5), for one that creates its partial
// file itself:
// Before creating `partial`: removes what an interrupted run left there (a regular file or a
// symbolic link, which would otherwise be written through); InputError when it is anything
// else (a FIFO there would block the open, a device would take the data).
void prepare_partial_file(const std::string& partial);
// The finished `partial` renamed to `path`. InputError, with `partial` removed, when `path`
// exists and is not a regular file (check_can_write) or the rename fails.
void move_into_place(const std::string& partial, const std::string& path);

}  // namespace growthuq
