// Writing result files so that a failure never leaves a half-written file that looks
// complete, and an existing result is never overwritten unless the user asked for it.
#pragma once

#include <fstream>
#include <string>
#include <string_view>

namespace growthuq {

enum class Overwrite { refuse, allow };

// Writes `content` to `path` through "<path>.partial" and an atomic rename. With
// Overwrite::refuse an existing `path` is an InputError that names it and suggests --force.
// I/O failures are InputErrors naming the path and the system's reason.
void write_file_atomically(const std::string& path, std::string_view content,
                           Overwrite overwrite);

// A file written piece by piece through "<path>.partial" and renamed into place by commit():
// destroyed before commit() (a failure, an interruption), it removes the partial file, so no
// half-written file looks complete. Whether `path` may be replaced is the caller's to check
// first (check_can_write). I/O failures are InputErrors naming the file and the reason.
class PartialFile {
 public:
  explicit PartialFile(std::string path);
  PartialFile(const PartialFile&) = delete;
  PartialFile& operator=(const PartialFile&) = delete;
  ~PartialFile();

  void write(std::string_view text);
  // Flushes, closes and renames to the final path.
  void commit();

 private:
  std::string path_;
  std::string partial_;
  std::ofstream out_;
  bool committed_ = false;
};

// InputError when `path` exists and overwriting was not allowed (checked before long work
// starts, so a run does not fail only at its end).
void check_can_write(const std::string& path, Overwrite overwrite);

}  // namespace growthuq
