#include "growthuq/io/output_file.hpp"

#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string_view>
#include <utility>
#include <vector>

#include "growthuq/core/interrupt.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/io/read_text_file.hpp"

namespace growthuq {

namespace detail {

std::string read_text_file(const std::string& path) {
  namespace fs = std::filesystem;
  const std::string name = source_name(path);
  const auto too_large = [&] {
    return InputError(name, "is larger than " + std::to_string(max_input_file_bytes >> 20) +
                                " MiB, the limit of an input file: expected a text file (is it the file you meant?)");
  };
  std::ifstream file;
  std::istream* in = &std::cin;
  if (path != standard_input) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    // Opened, a folder reads as an I/O error deep in the stream ("basic_filebuf::underflow").
    if (status.type() == fs::file_type::directory) throw InputError(path, "is a directory: expected a file");
    if (status.type() == fs::file_type::regular) {
      const std::uintmax_t bytes = fs::file_size(path, error);
      if (!error && bytes > max_input_file_bytes) throw too_large();
    }
    file.open(path, std::ios::binary);
    if (!file) throw InputError(path, std::string("cannot open: ") + std::strerror(errno));
    in = &file;
  }
  // Read in blocks up to the limit: a device or a pipe without end (/dev/zero, a stream piped
  // to standard input) is refused instead of filling memory.
  std::string text;
  std::array<char, 1 << 16> block{};
  while (*in) {
    errno = 0;
    in->read(block.data(), block.size());
    const auto got = static_cast<std::size_t>(in->gcount());
    if (text.size() + got > max_input_file_bytes) throw too_large();
    text.append(block.data(), got);
  }
  if (in->bad()) throw InputError(name, std::string("read failed") + (errno != 0 ? std::string(": ") + std::strerror(errno) : ""));
  return text;
}

}  // namespace detail

namespace {

namespace fs = std::filesystem;

// What a file of `type` is, for messages; empty for a regular file and for no file at all.
std::string_view special_kind(fs::file_type type) {
  switch (type) {
    case fs::file_type::directory: return "a directory";
    case fs::file_type::character: return "a character device";
    case fs::file_type::block: return "a block device";
    case fs::file_type::fifo: return "a FIFO (named pipe)";
    case fs::file_type::socket: return "a socket";
    case fs::file_type::regular:
    case fs::file_type::not_found:
    case fs::file_type::none:  // status unknown (no permission to look): the open or rename will say
      return {};
    default: return "not a regular file";
  }
}

// InputError when `path` exists and is not a regular file. The status follows symbolic links,
// so a link to /dev/null is refused like /dev/null itself (a rename would replace only the
// link, but a user who points an output at a device means the device).
void refuse_special_file(const std::string& path) {
  std::error_code error;
  const std::string_view kind = special_kind(fs::status(path, error).type());
  if (kind.empty()) return;
  throw InputError(path, "is " + std::string(kind) +
                             ": expected a regular file or a path that does not exist (results replace only "
                             "regular files, also with --force)");
}

}  // namespace

namespace {

// InputError unless `path`'s folder (or, when it may be created, its nearest existing ancestor)
// is a folder this process can create files in. Checked with the other output checks, before
// any work: without it a missing folder showed only when the result was written, after minutes
// of simulation.
void check_folder_of(const std::string& path, Folder folder) {
  fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) parent = ".";
  std::error_code error;
  if (folder == Folder::created_if_missing) {
    while (!fs::exists(parent, error)) {
      const fs::path up = parent.parent_path();
      if (up == parent) break;  // the root
      parent = up.empty() ? fs::path(".") : up;
    }
  }
  const fs::file_status status = fs::status(parent, error);
  if (status.type() == fs::file_type::not_found) {
    throw InputError(path, "cannot be written: the folder " + parent.string() +
                               " does not exist (expected an existing folder; create it first)");
  }
  if (status.type() != fs::file_type::directory && status.type() != fs::file_type::none) {
    throw InputError(path, "cannot be written: " + parent.string() + " is not a folder");
  }
  // access() answers for this process's user (as root: only a read-only file system refuses).
  if (status.type() == fs::file_type::directory && ::access(parent.c_str(), W_OK | X_OK) != 0) {
    throw InputError(path, "cannot be written: the folder " + parent.string() + " is not writable (" +
                               std::strerror(errno) + ")");
  }
}

}  // namespace

void check_can_write(const std::string& path, Overwrite overwrite, Folder folder) {
  // The commands that can print a result on stdout check "-" themselves (cli/result_output.hpp);
  // one reaching here would otherwise become a file called "-".
  if (path == "-") {
    throw InputError(path, "standard output cannot take this result: expected a file name (./- for a file named -)");
  }
  refuse_special_file(path);
  std::error_code error;
  if (overwrite == Overwrite::refuse && fs::exists(path, error)) {
    throw InputError(path, "already exists; choose another output or pass --force to overwrite");
  }
  check_folder_of(path, folder);
}

void prepare_partial_file(const std::string& partial) {
  std::error_code error;
  const fs::file_type type = fs::symlink_status(partial, error).type();
  if (type == fs::file_type::regular || type == fs::file_type::symlink) {
    fs::remove(partial, error);
    if (error) throw InputError(partial, "cannot remove the temporary file an earlier run left: " + error.message());
    return;
  }
  const std::string_view kind = special_kind(type);
  if (!kind.empty()) {
    throw InputError(partial, "is " + std::string(kind) +
                                  ": expected no file there (the temporary file a result is written to before it "
                                  "is renamed into place)");
  }
}

void move_into_place(const std::string& partial, const std::string& path) {
  try {
    refuse_special_file(path);  // one may have appeared since the writer checked
  } catch (const InputError&) {
    std::remove(partial.c_str());
    throw;
  }
  std::error_code error;
  fs::rename(partial, path, error);
  if (error) {
    std::remove(partial.c_str());
    throw WriteError(path, "cannot move the finished file into place: " + error.message());
  }
}

PartialFile::PartialFile(std::string path) : path_(std::move(path)), partial_(path_ + ".partial") {
  refuse_special_file(path_);
  prepare_partial_file(partial_);
  removed_on_signal_ = std::make_unique<RemovedOnSignal>(partial_);
  out_.open(partial_, std::ios::binary | std::ios::trunc);
  if (!out_) throw WriteError(partial_, std::string("cannot create: ") + std::strerror(errno));
}

PartialFile::~PartialFile() {
  if (committed_) return;
  out_.close();
  std::remove(partial_.c_str());
}

void PartialFile::write(std::string_view text) {
  out_.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out_) throw WriteError(partial_, std::string("write failed: ") + std::strerror(errno));
}

void PartialFile::close() {
  if (!out_.is_open()) return;
  out_.flush();
  out_.close();
  if (!out_) throw WriteError(partial_, std::string("write failed: ") + std::strerror(errno));
}

void PartialFile::commit() {
  close();
  committed_ = true;  // move_into_place removes the partial file itself when it fails
  move_into_place(partial_, path_);
}

void write_files_together(const std::vector<FileContent>& files, Overwrite overwrite) {
  for (const FileContent& file : files) check_can_write(file.path, overwrite);
  std::vector<std::unique_ptr<PartialFile>> written;
  for (const FileContent& file : files) {
    written.push_back(std::make_unique<PartialFile>(file.path));
    written.back()->write(file.content);
    written.back()->close();
  }
  for (const std::unique_ptr<PartialFile>& file : written) file->commit();
}

void write_file_atomically(const std::string& path, std::string_view content, Overwrite overwrite) {
  check_can_write(path, overwrite);
  PartialFile file(path);
  file.write(content);
  file.commit();
}

}  // namespace growthuq
