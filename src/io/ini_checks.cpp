#include "io/ini_checks.hpp"

#include "growthuq/core/error.hpp"

namespace growthuq::detail {

const IniEntry& required_entry(const IniDocument& document, const IniSection& section, std::string_view key,
                               std::string_view expected) {
  const IniEntry* entry = section.find(key);
  if (!entry || entry->value.empty()) {
    throw InputError(document.location(section.line),
                     "[" + section.name + "] has no '" + std::string(key) + "': expected " + std::string(expected));
  }
  return *entry;
}

const Unit& unit_of(const IniDocument& document, const IniEntry& unit_entry, const Quantity& quantity) {
  const Unit& unit = find_unit(unit_entry.value, document.location(unit_entry.line), unit_entry.key);
  if (unit.dimension != quantity.dimension) {
    std::string fitting;
    for (const Unit& candidate : known_units()) {
      if (candidate.dimension != quantity.dimension) continue;
      fitting += (fitting.empty() ? "" : ", ") + std::string(candidate.symbol);
    }
    throw_bad_value(document.location(unit_entry.line), unit_entry.key, unit_entry.value,
                    "a unit of " + std::string(to_string(quantity.dimension)) + " for " + std::string(quantity.name) +
                        " (" + fitting + ")");
  }
  return unit;
}

IniDocument read_plant_line_ini(const std::string& path) {
  IniDocument document = read_ini(path);
  // parse_ini keeps the entries before the first header in a leading section named "".
  if (!document.sections.empty() && document.sections.front().name.empty()) {
    const IniEntry& first = document.sections.front().entries.front();
    throw InputError(document.location(first.line),
                     "'" + first.key + " = " + first.value + "' comes before any [section]: expected [line] first");
  }
  return document;
}

LineHeader read_line_header(const IniDocument& document) {
  const IniSection* header = document.find("line");
  if (!header) throw InputError(document.path, "no [line] section: expected [line] with name = <plant line>");
  LineHeader line{required_entry(document, *header, "name", "name = <plant line>").value, ""};
  if (const IniEntry* description = header->find("description")) line.description = description->value;
  return line;
}

}  // namespace growthuq::detail
