// Whole files as strings, for tests that write inputs and read back what the engine or the CLI
// wrote. Binary mode, so that bytes (a torn checkpoint record, CRLF) come back as they are.
#pragma once

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

// The pieces of `text` between `separator`s (a CSV row's cells, a report's lines), empty ones
// kept but for a trailing one.
inline std::vector<std::string> split_text(const std::string& text, char separator) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, separator);) items.push_back(item);
  return items;
}

// The number after "<name>" at the start of a line of a report such as `growthuq eval`'s
// ("  p 0.31 MPa"); NaN when no line starts so, or its value is not a number ("-": flagged).
inline double printed_value(const std::string& report, const std::string& name) {
  for (const std::string& line : split_text(report, '\n')) {
    std::stringstream words(line);
    std::string first, value;
    if (!(words >> first >> value) || first != name) continue;
    char* end = nullptr;
    const double number = std::strtod(value.c_str(), &end);
    return end != value.c_str() && *end == '\0' ? number : std::nan("");
  }
  return std::nan("");
}

}  // namespace growthuq::testing
