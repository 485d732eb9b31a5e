#include "growthuq/io/output_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>

#include "growthuq/core/error.hpp"
#include "read_text_file.hpp"

namespace growthuq {

namespace detail {

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, std::string("cannot open: ") + std::strerror(errno));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path, "read failed");
  return text;
}

}  // namespace detail

void check_can_write(const std::string& path, Overwrite overwrite) {
  std::error_code error;
  if (overwrite == Overwrite::refuse && std::filesystem::exists(path, error)) {
    throw InputError(path, "already exists; choose another output or pass --force to overwrite");
  }
}

PartialFile::PartialFile(std::string path) : path_(std::move(path)), partial_(path_ + ".partial") {
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
  std::error_code error;
  std::filesystem::rename(partial_, path_, error);
  if (error) throw InputError(path_, "cannot move the finished file into place: " + error.message());
  committed_ = true;
}

void write_file_atomically(const std::string& path, std::string_view content, Overwrite overwrite) {
  check_can_write(path, overwrite);
  PartialFile file(path);
  file.write(content);
  file.commit();
}

}  // namespace growthuq
