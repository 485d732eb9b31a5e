// Reading raw.ini (format in raw_line_file.hpp and distributions/README.md). Every key is checked
// where it stands so that an error names the line a lab has to fix.
#include "growthuq/rawdata/raw_line_file.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <utility>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/forcecurves/window_text.hpp"
#include "io/ini.hpp"
#include "io/ini_checks.hpp"

namespace growthuq {
namespace {

namespace fs = std::filesystem;

using detail::required_entry;

constexpr std::array<std::string_view, 7> measured_variables{"k", "h", "d", "d0", "tau", "einf", "v_exp"};

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

void reject_unknown_keys(const IniDocument& document, const IniSection& section,
                         const std::vector<std::string>& allowed) {
  for (const IniEntry& entry : section.entries) {
    if (std::find(allowed.begin(), allowed.end(), entry.key) == allowed.end()) {
      throw InputError(document.location(entry.line), "unknown key '" + entry.key + "' in [" + section.name +
                                                          "] (allowed: " + joined(allowed) + ")");
    }
  }
}

// A file named in the raw file, relative to the raw file's folder; it must exist.
std::string existing_file(const IniDocument& document, const IniEntry& entry) {
  const fs::path given(entry.value);
  const std::string path =
      given.is_absolute() ? given.string() : (fs::path(document.path).parent_path() / given).lexically_normal().string();
  std::error_code error;
  if (!fs::is_regular_file(path, error)) {
    throw_bad_value(document.location(entry.line), entry.key, entry.value,
                    "an existing file (looked for " + path + "; relative paths start at the raw file's folder)");
  }
  return path;
}

// The families a section lists, or the defaults for a fraction (einf: beta first) or a
// positive quantity.
std::vector<FitFamily> families_of(const IniDocument& document, const IniSection& section, bool fraction) {
  const IniEntry* entry = section.find("families");
  if (!entry && fraction) return {std::begin(fraction_fit_families), std::end(fraction_fit_families)};
  if (!entry) return {std::begin(all_fit_families), std::end(all_fit_families)};
  std::vector<FitFamily> families;
  std::string_view rest = entry->value;
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view name = trim(rest.substr(0, comma));
    const auto family = parse_fit_family(name);
    if (!family) throw_bad_value(document.location(entry->line), "families", name, "lognormal, normal, gamma, weibull or beta (for einf)");
    if (std::find(families.begin(), families.end(), *family) != families.end()) {
      throw_bad_value(document.location(entry->line), "families", name, "each family once");
    }
    families.push_back(*family);
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  return families;
}

RawMeasurement read_measurement(const IniDocument& document, const IniSection& section) {
  RawMeasurement measurement;
  measurement.line = section.line;
  measurement.variable = std::string(trim(std::string_view(section.name).substr(std::string_view("measurement ").size())));
  if (std::find(measured_variables.begin(), measured_variables.end(), measurement.variable) == measured_variables.end()) {
    throw InputError(document.location(section.line),
                     "[" + section.name + "]: expected [measurement V] with V one of k, h, d, d0, tau, einf, v_exp");
  }
  reject_unknown_keys(document, section, {"file", "column", "unit", "families"});
  measurement.file = existing_file(document, required_entry(document, section, "file", "file = <CSV table>"));
  measurement.column = required_entry(document, section, "column", "column = <header name in the table>").value;
  const Quantity& quantity = *find_quantity(measurement.variable);
  const IniEntry& unit = required_entry(document, section, "unit",
                                        "unit = " + std::string(quantity.default_unit) + " (the unit of the column's values)");
  measurement.unit = &detail::unit_of(document, unit, quantity);
  measurement.families = families_of(document, section, quantity.dimension == Dimension::fraction);
  return measurement;
}

RawRelaxation read_relaxation(const IniDocument& document, const IniSection& section) {
  RawRelaxation relaxation;
  relaxation.line = section.line;
  reject_unknown_keys(document, section, {"curves", "meta", "terms", "fit", "families"});
  relaxation.curves =
      existing_file(document, required_entry(document, section, "curves", "curves = <CSV curve,t_s,F_uN>"));
  if (const IniEntry* meta = section.find("meta")) relaxation.meta = existing_file(document, *meta);
  if (const IniEntry* terms = section.find("terms")) {
    relaxation.terms = static_cast<int>(parse_count(terms->value, document.location(terms->line), "terms", 1, 3));
  }
  if (const IniEntry* fit = section.find("fit")) {
    if (fit->value == "ramp_aware") {
      relaxation.ramp_aware = true;
    } else if (fit->value != "step") {
      throw_bad_value(document.location(fit->line), "fit", fit->value, "step or ramp_aware");
    }
  }
  relaxation.families = families_of(document, section, false);
  // One list when given (beta fails for tau, with its reason); by default einf's own.
  relaxation.einf_families = section.find("families") ? relaxation.families : families_of(document, section, true);
  return relaxation;
}

RawForceCurves read_force_curves_section(const IniDocument& document, const IniSection& section) {
  RawForceCurves force_curves;
  force_curves.line = section.line;
  reject_unknown_keys(document, section,
                      {"curves", "sheet", "window", "window_uN", "contact", "measurement_error", "families"});
  force_curves.curves = existing_file(
      document, required_entry(document, section, "curves", "curves = <CSV curve,z_um,F_uN (distributions/README.md)>"));
  force_curves.sheet = existing_file(
      document, required_entry(document, section, "sheet", "sheet = <CSV curve,tube,repetition,rho_um,k_sys_N_per_m>"));
  CurveProcessingOptions& options = force_curves.options;
  WindowConvention convention = WindowConvention::relative;
  if (const IniEntry* window = section.find("window")) {
    if (window->value != "relative" && window->value != "absolute") {
      throw_bad_value(document.location(window->line), "window", window->value, "relative or absolute");
    }
    if (window->value == "absolute") convention = WindowConvention::absolute;
  }
  const IniEntry* forces = section.find("window_uN");
  const std::string defaults = convention == WindowConvention::relative ? "4,0.5" : "0.4,4";
  options.window = window_of(convention, forces ? forces->value : defaults,
                             document.location(forces ? forces->line : section.line), "window_uN");
  if (const IniEntry* contact = section.find("contact")) {
    if (contact->value != "deviation" && contact->value != "piecewise") {
      throw_bad_value(document.location(contact->line), "contact", contact->value, "deviation or piecewise");
    }
    options.contact = contact->value == "deviation" ? ContactMethod::deviation : ContactMethod::piecewise;
  }
  if (const std::string reason = options.invalid_reason(); !reason.empty()) {
    throw InputError(document.location(forces ? forces->line : section.line), "[force_curves]: " + reason);
  }
  if (const IniEntry* error = section.find("measurement_error")) {
    if (error->value != "bootstrap" && error->value != "none") {
      throw_bad_value(document.location(error->line), "measurement_error", error->value, "bootstrap or none");
    }
    force_curves.measurement_error = error->value == "bootstrap";
  }
  force_curves.families = families_of(document, section, false);
  return force_curves;
}

}  // namespace

std::vector<std::string> RawLineFile::variables() const {
  std::vector<std::string> names;
  for (const RawMeasurement& measurement : measurements) names.push_back(measurement.variable);
  if (has_relaxation) {
    names.emplace_back("tau");
    names.emplace_back("einf");
  }
  if (has_force_curves) names.emplace_back("k");
  return names;
}

RawLineFile read_raw_line_file(const std::string& path) {
  const IniDocument document = detail::read_plant_line_ini(path);
  RawLineFile raw;
  raw.path = path;
  for (const IniSection& section : document.sections) {
    if (section.name == "line") {
      reject_unknown_keys(document, section, {"name", "description"});
    } else if (section.name.starts_with("measurement ")) {
      RawMeasurement measurement = read_measurement(document, section);
      for (const RawMeasurement& earlier : raw.measurements) {
        if (earlier.variable == measurement.variable) {
          throw InputError(document.location(section.line), "variable " + measurement.variable + " is measured twice (first at line " +
                                                                std::to_string(earlier.line) + ")");
        }
      }
      raw.measurements.push_back(std::move(measurement));
    } else if (section.name == "relaxation") {
      raw.relaxation = read_relaxation(document, section);
      raw.has_relaxation = true;
    } else if (section.name == "force_curves") {
      raw.force_curves = read_force_curves_section(document, section);
      raw.has_force_curves = true;
    } else {
      throw InputError(document.location(section.line), "unknown section [" + section.name +
                                                             "]: expected [line], [measurement VARIABLE], [relaxation] "
                                                             "or [force_curves]");
    }
  }
  detail::LineHeader header = detail::read_line_header(document);
  raw.name = std::move(header.name);
  raw.description = std::move(header.description);
  if (raw.has_relaxation) {
    for (const RawMeasurement& measurement : raw.measurements) {
      if (measurement.variable == "tau" || measurement.variable == "einf") {
        throw InputError(document.location(measurement.line),
                         "[measurement " + measurement.variable + "] and [relaxation] (line " +
                             std::to_string(raw.relaxation.line) + ") both give " + measurement.variable +
                             ": expected one source per variable");
      }
    }
  }
  if (raw.has_force_curves) {
    for (const RawMeasurement& measurement : raw.measurements) {
      if (measurement.variable == "k") {
        throw InputError(document.location(measurement.line),
                         "[measurement k] and [force_curves] (line " + std::to_string(raw.force_curves.line) +
                             ") both give k: expected one source per variable");
      }
    }
  }
  if (raw.measurements.empty() && !raw.has_relaxation && !raw.has_force_curves) {
    throw InputError(path, "no [measurement VARIABLE], [relaxation] or [force_curves] section: nothing to fit");
  }
  return raw;
}

}  // namespace growthuq
