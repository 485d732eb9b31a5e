// Special files made in a test's scratch folder, for the tests that check a result never
// replaces one: a character device (made with mknod, so only as root: CI runs as root), a FIFO,
// a socket and a folder. Never the machine's own /dev: a device made here has the numbers of
// /dev/null (1, 3) or /dev/full (1, 7) and is removed with the scratch folder.
#pragma once

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace growthuq::testing {

enum class SpecialKind { null_device, full_device, fifo, socket, directory };

// What check_can_write calls each kind in its messages.
inline std::string_view kind_name(SpecialKind kind) {
  switch (kind) {
    case SpecialKind::null_device:
    case SpecialKind::full_device: return "a character device";
    case SpecialKind::fifo: return "a FIFO (named pipe)";
    case SpecialKind::socket: return "a socket";
    case SpecialKind::directory: return "a directory";
  }
  return "";
}

inline std::filesystem::file_type file_type_of(SpecialKind kind) {
  switch (kind) {
    case SpecialKind::null_device:
    case SpecialKind::full_device: return std::filesystem::file_type::character;
    case SpecialKind::fifo: return std::filesystem::file_type::fifo;
    case SpecialKind::socket: return std::filesystem::file_type::socket;
    case SpecialKind::directory: return std::filesystem::file_type::directory;
  }
  return std::filesystem::file_type::none;
}

// Makes a `kind` at `path` (which must not exist); false when this process may not (a device
// needs root). A socket is bound and its descriptor closed: the file stays.
inline bool make_special_file(const std::filesystem::path& path, SpecialKind kind) {
  switch (kind) {
    case SpecialKind::null_device: return ::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0;
    case SpecialKind::full_device: return ::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, 7)) == 0;
    case SpecialKind::fifo: return ::mkfifo(path.c_str(), 0666) == 0;
    case SpecialKind::directory: return std::filesystem::create_directory(path);
    case SpecialKind::socket: {
      sockaddr_un address{};
      address.sun_family = AF_UNIX;
      const std::string text = path.string();
      if (text.size() >= sizeof address.sun_path) return false;
      std::memcpy(address.sun_path, text.c_str(), text.size() + 1);
      const int socket = ::socket(AF_UNIX, SOCK_STREAM, 0);
      if (socket < 0) return false;
      const bool bound = ::bind(socket, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
      ::close(socket);
      return bound;
    }
  }
  return false;
}

// Whether `path` is still (not a symbolic link to) a `kind`: what a test checks afterwards.
inline bool is_special_file(const std::filesystem::path& path, SpecialKind kind) {
  std::error_code error;
  return std::filesystem::symlink_status(path, error).type() == file_type_of(kind);
}

inline std::vector<SpecialKind> every_special_kind() {
  return {SpecialKind::null_device, SpecialKind::fifo, SpecialKind::socket, SpecialKind::directory};
}

}  // namespace growthuq::testing
