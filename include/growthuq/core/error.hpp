// The one exception type for bad input (files, options, data). It carries where the problem
// is (file and line, or option key), so `main` can print a single line and exit non-zero.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace growthuq {

// Thrown for anything a user can fix: a malformed file, an out-of-range option, bad data.
// what() reads "<location>: <problem>", e.g.
//   "distributions/wild_type.ini:12: iqr = '-0.3': expected a positive number".
class InputError : public std::runtime_error {
 public:
  InputError(std::string location, std::string problem);

  const std::string& location() const noexcept { return location_; }
  const std::string& problem() const noexcept { return problem_; }

 private:
  std::string location_;
  std::string problem_;
};

// "<location>: <key> = '<value>': expected <expected>" — the usual shape of a bad value.
[[noreturn]] void throw_bad_value(std::string_view location, std::string_view key,
                                  std::string_view value, std::string_view expected);

// "<file>:<line>" for messages; line 0 means the file as a whole.
std::string file_location(std::string_view file, long line);

}  // namespace growthuq
