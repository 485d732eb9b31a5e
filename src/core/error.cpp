#include "growthuq/core/error.hpp"

#include "growthuq/core/printable.hpp"

namespace growthuq {

// Through printable(): whatever of the user's input a message quotes, it is one line that
// cannot act on a terminal.
InputError::InputError(std::string location, std::string problem)
    : std::runtime_error(location.empty() ? printable(problem) : printable(location) + ": " + printable(problem)),
      location_(printable(location)),
      problem_(printable(problem)) {}

void throw_bad_value(std::string_view location, std::string_view key, std::string_view value,
                     std::string_view expected) {
  throw InputError(std::string(location), std::string(key) + " = '" + std::string(value) +
                                              "': expected " + std::string(expected));
}

std::string file_location(std::string_view file, long line) {
  std::string location(file);
  if (line > 0) location += ":" + std::to_string(line);
  return location;
}

}  // namespace growthuq
