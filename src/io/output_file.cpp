#include "growthuq/io/output_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

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

void write_file_atomically(const std::string& path, std::string_view content,
                           Overwrite overwrite) {
  check_can_write(path, overwrite);
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(partial, std::string("cannot create: ") + std::strerror(errno));
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      std::remove(partial.c_str());
      throw InputError(partial, std::string("write failed: ") + std::strerror(errno));
    }
  }
  std::error_code error;
  std::filesystem::rename(partial, path, error);
  if (error) {
    std::remove(partial.c_str());
    throw InputError(path, "cannot move the finished file into place: " + error.message());
  }
}

}  // namespace growthuq
