// Whole-file read shared by the CSV and INI readers, and the one encoding detail they share.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace growthuq::detail {

// The largest input file read (256 MiB): far above any line, campaign, raw-data or mesh file
// (synth's largest relaxation_curves.csv is about 100 MB), and a bound on the memory a wrong
// path (/dev/zero, a disk image) can take.
inline constexpr std::size_t max_input_file_bytes = std::size_t{256} << 20;

// The file name that means standard input: `growthuq eval --in - ...` reads the table piped in.
inline constexpr std::string_view standard_input = "-";

// `path` as messages name it: "standard input" for "-".
inline std::string source_name(const std::string& path) {
  return path == standard_input ? std::string("standard input") : path;
}

// The bytes of `path` (of standard input for "-"); InputError naming the path and the system's
// reason when it cannot be read, and naming what it is when it is a directory or larger than
// max_input_file_bytes. Every input file a command reads (INI, CSV, mesh, config, checkpoint)
// comes through here.
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
