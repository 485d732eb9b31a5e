// A small tmpfs for the full-disk tests, mounted for one test's lifetime. Mounting needs root
// (CI runs as root): mounted() says whether it worked, and a test that needs it skips, saying so,
// when it did not.
#pragma once

#include <sys/mount.h>
#include <sys/statvfs.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace growthuq::testing {

struct SmallDisk {
  std::filesystem::path where;
  bool ok = false;
  SmallDisk(std::filesystem::path path, int kilobytes) : where(std::move(path)) {
    std::filesystem::create_directories(where);
    ok = ::mount("tmpfs", where.c_str(), "tmpfs", 0, ("size=" + std::to_string(kilobytes) + "k").c_str()) == 0;
  }
  ~SmallDisk() {
    if (ok) ::umount2(where.c_str(), MNT_DETACH);
  }
  SmallDisk(const SmallDisk&) = delete;
  SmallDisk& operator=(const SmallDisk&) = delete;
  bool mounted() const { return ok; }

  // Bytes free for files now.
  std::uint64_t free_bytes() const {
    struct statvfs space {};
    if (::statvfs(where.c_str(), &space) != 0) return 0;
    return static_cast<std::uint64_t>(space.f_bavail) * space.f_frsize;
  }

  // Writes the file `name` so that about `keep` bytes stay free (tmpfs counts whole pages).
  void fill_leaving(const std::string& name, std::uint64_t keep) const {
    const std::uint64_t free = free_bytes();
    std::ofstream out(where / name, std::ios::binary | std::ios::trunc);
    const std::string block(4096, 'x');
    for (std::uint64_t written = 0; written + keep + block.size() <= free; written += block.size()) out << block;
  }
};

}  // namespace growthuq::testing
