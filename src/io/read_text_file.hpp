// Whole-file read shared by the CSV and INI readers, and the one encoding detail they share.
#pragma once

#include <string>
#include <string_view>

namespace growthuq::detail {

// The file name that means standard input: `growthuq eval --in - ...` reads the table piped in.
inline constexpr std::string_view standard_input = "-";

// `path` as messages name it: "standard input" for "-".
inline std::string source_name(const std::string& path) {
  return path == standard_input ? std::string("standard input") : path;
}

// The bytes of `path` (of standard input for "-"); InputError naming the path and the system's
// reason when it cannot be read.
std::string read_text_file(const std::string& path);

// `text` without a leading UTF-8 byte-order mark (EF BB BF). Excel's "CSV UTF-8" and Windows
// editors start files with one; left in place it would become part of the first column name or
// key, invisible in the message that then says it is not found.
inline std::string_view without_byte_order_mark(std::string_view text) {
  constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";
  if (text.starts_with(byte_order_mark)) text.remove_prefix(byte_order_mark.size());
  return text;
}

}  // namespace growthuq::detail
