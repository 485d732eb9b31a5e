// One INI section holding a law of a quantity, in the keys of a line file's variable sections
// (law and its parameters, unit, source, note, tubes; distributions/README.md). Line files use
// it for their measured variables; a campaign for a law of its instrument's probe radius.
#pragma once

#include <string_view>

#include "growthuq/distributions/line_file.hpp"
#include "io/ini.hpp"

namespace growthuq::detail {

// The law of quantity `name` (a known quantity, growthuq/core/units.hpp) that `section` states,
// checked as a line file's variables are; InputError naming the file, line and key otherwise.
LineVariable read_law_section(const IniDocument& document, const IniSection& section, std::string_view name);

}  // namespace growthuq::detail
