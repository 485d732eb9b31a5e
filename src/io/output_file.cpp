#include "growthuq/io/output_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string_view>
#include <utility>

#include "growthuq/core/error.hpp"
#include "read_text_file.hpp"

namespace growthuq {

namespace detail {

std::string read_text_file(const std::string& path) {
  if (path == standard_input) {
    std::string text((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
    if (std::cin.bad()) throw InputError(source_name(path), "read failed");
    return text;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, std::string("cannot open: ") + std::strerror(errno));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path, "read failed");
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

void check_can_write(const std::string& path, Overwrite overwrite) {
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
    throw InputError(path, "cannot move the finished file into place: " + error.message());
  }
}

PartialFile::PartialFile(std::string path) : path_(std::move(path)), partial_(path_ + ".partial") {
  refuse_special_file(path_);
  prepare_partial_file(partial_);
  out_.open(partial_, std::ios::binary | std::ios::trunc);
  if (!out_) throw InputError(partial_, std::string("cannot create: ") + std::strerror(errno));
}

PartialFile::~PartialFile() {
  if (committed_) return;
  out_.close();
  std::remove(partial_.c_str());
}

void PartialFile::write(std::string_view text) {
  out_.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out_) throw InputError(partial_, std::string("write failed: ") + std::strerror(errno));
}

void PartialFile::commit() {
  out_.flush();
  out_.close();
  if (!out_) throw InputError(partial_, std::string("write failed: ") + std::strerror(errno));
  committed_ = true;  // move_into_place removes the partial file itself when it fails
  move_into_place(partial_, path_);
}

void write_file_atomically(const std::string& path, std::string_view content, Overwrite overwrite) {
  check_can_write(path, overwrite);
  PartialFile file(path);
  file.write(content);
  file.commit();
}

}  // namespace growthuq
