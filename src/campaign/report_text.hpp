// Cells of the campaign's tables: numbers for CSV (shortest exact text, empty when undefined) and
// for reading on stdout (four significant digits, "-" when undefined), and padded columns.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "growthuq/core/numbers.hpp"

namespace growthuq {

inline std::string number_cell(double value) { return std::isfinite(value) ? format_double(value) : std::string(); }

inline std::string significant(double value) {
  if (!std::isfinite(value)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

// `text` left-aligned in `width` characters, with at least one blank after it.
inline std::string padded(const std::string& text, std::size_t width) {
  return text.size() >= width ? text + " " : text + std::string(width - text.size(), ' ');
}

}  // namespace growthuq
