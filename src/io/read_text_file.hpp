// Whole-file read shared by the CSV and INI readers.
#pragma once

#include <cstddef>
#include <string>

namespace growthuq::detail {

// The largest input file read (256 MiB): far above any line, campaign, raw-data or mesh file
// (synth's largest relaxation_curves.csv is about 100 MB), and a bound on the memory a wrong
// path (/dev/zero, a disk image) can take.
inline constexpr std::size_t max_input_file_bytes = std::size_t{256} << 20;

// The bytes of `path`; InputError naming the path and the system's reason when it cannot be
// read, and naming what it is when it is a directory or larger than max_input_file_bytes.
// Every input file a command reads (INI, CSV, mesh, config, checkpoint) comes through here.
std::string read_text_file(const std::string& path);

}  // namespace growthuq::detail
