// Whole-file read shared by the CSV and INI readers.
#pragma once

#include <string>

namespace growthuq::detail {

// The bytes of `path`; InputError naming the path and the system's reason when it cannot be read.
std::string read_text_file(const std::string& path);

}  // namespace growthuq::detail
