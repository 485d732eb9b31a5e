// Whether two lines' compact letters (stats/compact_letters.hpp) have a letter in common: the
// property a letter display must have exactly for the pairs not found different.
#pragma once

#include <string>

namespace growthuq::testing {

// (A prime marks the letters after the 52nd, "a'": it is not a letter of its own.)
inline bool share_letter(const std::string& a, const std::string& b) {
  for (const char c : a) {
    if (c != '\'' && b.find(c) != std::string::npos) return true;
  }
  return false;
}

}  // namespace growthuq::testing
