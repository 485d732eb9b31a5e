// A fresh folder under the system's temporary directory for one test case, removed with
// everything in it when the test case ends (also when a REQUIRE fails).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace growthuq::testing {

struct ScratchDirectory {
  std::filesystem::path root;

  // growthuq_test_<name>_<process id>: the process id keeps test runs of several build trees
  // on one machine out of each other's way.
  explicit ScratchDirectory(const std::string& name)
      : root(std::filesystem::temp_directory_path() / ("growthuq_test_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(root);
    std::filesystem::create_directories(root);
  }
  ~ScratchDirectory() { std::filesystem::remove_all(root); }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
};

}  // namespace growthuq::testing
