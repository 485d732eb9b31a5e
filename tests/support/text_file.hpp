// Whole files as strings, for tests that write inputs and read back what the engine or the CLI
// wrote. Binary mode, so that bytes (a torn checkpoint record, CRLF) come back as they are.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace growthuq::testing {

// The whole content of `path` ("" when it cannot be opened: the test's checks then fail on it).
inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Replaces the content of `path` with `text`.
inline void spit(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

}  // namespace growthuq::testing
