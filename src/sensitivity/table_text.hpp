// The text cells of the sensitivity tables (first-order, Shapley, Sobol): one format for the three.
#pragma once

#include <cstdio>
#include <string>

namespace growthuq {

// A value with two decimals, "-0.00" written as "0.00".
inline std::string two_decimals(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return std::string(text) == "-0.00" ? "0.00" : text;
}

inline std::string padded_left(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

}  // namespace growthuq
