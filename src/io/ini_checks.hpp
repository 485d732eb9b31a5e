// Checks shared by the strict readers of plant-line INI files (distributions/line_file.cpp,
// rawdata/raw_line_file.cpp): required keys, units of the right dimension, the [line] header
// and nothing before it. Each failure is an InputError naming the file and line at fault.
#pragma once

#include <string>
#include <string_view>

#include "growthuq/core/units.hpp"
#include "io/ini.hpp"

namespace growthuq::detail {

// The non-empty entry `key` of `section`; otherwise "[section] has no 'key': expected
// <expected>" at the section's line.
const IniEntry& required_entry(const IniDocument& document, const IniSection& section, std::string_view key,
                               std::string_view expected);

// The unit `unit_entry` names, which must measure `quantity`; otherwise the error at the
// entry's line lists the units that do.
const Unit& unit_of(const IniDocument& document, const IniEntry& unit_entry, const Quantity& quantity);

// Reads the INI file of a plant line (line file or raw.ini). These open with [line]: an entry
// before the first section is refused.
IniDocument read_plant_line_ini(const std::string& path);

struct LineHeader {
  std::string name;
  std::string description;  // empty when not given
};

// The [line] section's name (required) and description; its other keys are the caller's to check.
LineHeader read_line_header(const IniDocument& document);

}  // namespace growthuq::detail
