// Reading and writing plant-line distribution files (format in line_file.hpp and
// distributions/README.md). Validation is strict because these files are typed by hand: every key
// must belong to the section's law, every parameter is checked at its own line, and errors name
// file and line.
#include "growthuq/distributions/line_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/distributions/fit.hpp"
#include "growthuq/distributions/sampled_range.hpp"
#include "distributions/law_section.hpp"
#include "io/ini.hpp"
#include "io/ini_checks.hpp"

namespace growthuq {
namespace {

using detail::required_entry;

constexpr std::array<std::string_view, 7> measured_variables{"k", "h", "d", "d0", "tau", "einf", "v_exp"};
constexpr std::array<std::string_view, 5> common_keys{"law", "unit", "source", "note", "tubes"};
// More tubes than any lab indents; a larger count is a typo, and the bootstrap draws that many
// values per replicate.
constexpr std::uint64_t most_tubes = 100000;

enum class Check { finite, positive, bound };

struct Parameter {
  std::string_view key;
  Check check;
};

struct Law {
  std::string_view name;
  std::vector<std::vector<Parameter>> alternatives;  // accepted parameter sets
  std::string_view keys_text;                         // for messages
};

const std::vector<Law>& laws() {
  static const std::vector<Law> table{
      {"lognormal",
       {{{"median", Check::positive}, {"iqr", Check::positive}},
        {{"mu", Check::finite}, {"sigma", Check::positive}}},
       "median and iqr, or mu and sigma"},
      {"normal", {{{"mean", Check::finite}, {"sd", Check::positive}}}, "mean, sd"},
      {"truncated_normal",
       {{{"mean", Check::finite}, {"sd", Check::positive}, {"lower", Check::bound}, {"upper", Check::bound}}},
       "mean, sd, lower, upper"},
      {"uniform", {{{"lower", Check::finite}, {"upper", Check::finite}}}, "lower, upper"},
      {"gamma", {{{"shape", Check::positive}, {"scale", Check::positive}}}, "shape, scale"},
      {"weibull", {{{"shape", Check::positive}, {"scale", Check::positive}}}, "shape, scale"},
      {"beta", {{{"alpha", Check::positive}, {"beta", Check::positive}}}, "alpha, beta"},
      {"empirical", {{{"values", Check::finite}}}, "values"},
  };
  return table;
}

template <class Range>
std::string joined(const Range& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + std::string(name);
  return text;
}

bool is_parameter_of_any_law(std::string_view key) {
  for (const Law& law : laws()) {
    for (const auto& set : law.alternatives) {
      for (const Parameter& p : set) {
        if (p.key == key) return true;
      }
    }
  }
  return false;
}

double parameter_value(const IniDocument& document, const IniEntry& entry, Check check) {
  const std::string location = document.location(entry.line);
  if (check == Check::bound) {
    if (entry.value == "inf" || entry.value == "+inf") return HUGE_VAL;
    if (entry.value == "-inf") return -HUGE_VAL;
  }
  const double value = parse_double(entry.value, location, entry.key);
  if (check == Check::positive && !(value > 0.0)) {
    throw_bad_value(location, entry.key, entry.value, "a positive number");
  }
  return value;
}

std::vector<double> parse_values(const IniDocument& document, const IniEntry& entry) {
  std::vector<double> values;
  std::string_view rest = entry.value;
  while (true) {
    const std::size_t comma = rest.find(',');
    values.push_back(parse_double(rest.substr(0, comma), document.location(entry.line), entry.key));
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  return values;
}

// `fraction_upper`: where a fraction is 1 in the section's unit (the beta law's upper end).
Distribution make_distribution(const IniDocument& document, const IniSection& section, const Law& law,
                               const IniEntry& law_entry, double fraction_upper) {
  // The parameter set whose first key is present (lognormal has two).
  const std::vector<Parameter>* chosen = nullptr;
  for (const auto& set : law.alternatives) {
    if (!chosen && section.find(set.front().key)) chosen = &set;
  }
  if (!chosen) chosen = &law.alternatives.front();
  for (const IniEntry& entry : section.entries) {
    const bool common = std::find(common_keys.begin(), common_keys.end(), entry.key) != common_keys.end();
    const bool in_set = std::any_of(chosen->begin(), chosen->end(), [&](const Parameter& p) { return p.key == entry.key; });
    if (common || in_set) continue;
    const std::string location = document.location(entry.line);
    if (is_parameter_of_any_law(entry.key)) {
      throw InputError(location, "key '" + entry.key + "' is not a parameter of law = " + std::string(law.name) +
                                     " (line " + std::to_string(law_entry.line) + "): expected " +
                                     std::string(law.keys_text));
    }
    throw InputError(location, "unknown key '" + entry.key + "': expected law, unit, source, note, tubes or " +
                                   std::string(law.keys_text));
  }
  std::vector<double> values;
  for (const Parameter& p : *chosen) {
    const IniEntry* entry = section.find(p.key);
    if (!entry) {
      throw InputError(document.location(section.line),
                       "[" + section.name + "] law = " + std::string(law.name) + " needs '" + std::string(p.key) +
                           "' (parameters: " + std::string(law.keys_text) + ")");
    }
    if (law.name == "empirical") {
      try {
        return Empirical(parse_values(document, *entry));
      } catch (const InputError& error) {
        if (error.location() == "empirical") throw InputError(document.location(entry->line), error.problem());
        throw;
      }
    }
    values.push_back(parameter_value(document, *entry, p.check));
  }
  // Relations between parameters (upper > lower, truncation mass) are checked by the
  // constructors; their message is reported at the section's line.
  try {
    if (law.name == "lognormal") {
      return chosen == &law.alternatives.front() ? Lognormal::from_median_iqr(values[0], values[1])
                                                 : Lognormal(values[0], values[1]);
    }
    if (law.name == "normal") return Normal(values[0], values[1]);
    if (law.name == "truncated_normal") return TruncatedNormal(values[0], values[1], values[2], values[3]);
    if (law.name == "uniform") return Uniform(values[0], values[1]);
    if (law.name == "gamma") return Gamma(values[0], values[1]);
    if (law.name == "beta") return Beta(values[0], values[1], fraction_upper);
    return Weibull(values[0], values[1]);
  } catch (const InputError& error) {
    throw InputError(document.location(section.line), "[" + section.name + "] " + error.what());
  }
}

// tubes = N (optional): the count behind the law, at least 2 (no law is fitted to fewer), and
// only for a law whose family the bootstrap can refit by maximum likelihood; 0 when absent.
std::size_t tubes_of(const IniDocument& document, const IniSection& section, const IniEntry& law_entry) {
  const IniEntry* entry = section.find("tubes");
  if (entry == nullptr) return 0;
  const std::string location = document.location(entry->line);
  const std::size_t tubes = parse_count(entry->value, location, entry->key, 2, most_tubes);
  if (!parse_fit_family(law_entry.value)) {
    throw InputError(location, "tubes = " + entry->value + " with law = " + law_entry.value + " (line " +
                                   std::to_string(law_entry.line) +
                                   "): the data-uncertainty bootstrap refits the stated law's family by maximum "
                                   "likelihood, which exists for lognormal, normal, gamma, weibull and beta only: "
                                   "expected one of those laws, or no tubes (the law then stays fixed)");
  }
  return tubes;
}

}  // namespace

LineVariable detail::read_law_section(const IniDocument& document, const IniSection& section, std::string_view name) {
  const std::string section_location = document.location(section.line);
  const Quantity& quantity = *find_quantity(name);

  const IniEntry& law_entry = required_entry(document, section, "law", "law = " + joined(std::vector<std::string_view>{
      "lognormal", "normal", "truncated_normal", "uniform", "gamma", "weibull", "beta", "empirical"}));
  const auto law = std::find_if(laws().begin(), laws().end(), [&](const Law& l) { return l.name == law_entry.value; });
  if (law == laws().end()) {
    std::vector<std::string_view> names;
    for (const Law& l : laws()) names.push_back(l.name);
    throw_bad_value(document.location(law_entry.line), "law", law_entry.value, "one of " + joined(names));
  }

  const IniEntry& unit_entry =
      required_entry(document, section, "unit", "the unit of the values, e.g. unit = " + std::string(quantity.default_unit));
  const Unit& unit = detail::unit_of(document, unit_entry, quantity);

  const std::string source =
      required_entry(document, section, "source", "source = <citation>, or source = illustrative with a note").value;
  const IniEntry* note = section.find("note");
  if (source == "illustrative" && (!note || note->value.empty())) {
    throw InputError(section_location, "[" + section.name +
                                           "] source = illustrative needs a one-line 'note' saying why the value was chosen");
  }
  const bool fraction = quantity.dimension == Dimension::fraction;
  if (law->name == "beta" && !fraction) {
    throw_bad_value(document.location(law_entry.line), "law", law_entry.value,
                    "a law of " + section.name + " (" + std::string(quantity.description) +
                        "): beta is a law of fractions (einf)");
  }
  Distribution distribution = make_distribution(document, section, *law, law_entry, 1.0 / unit.to_si);
  if (const std::optional<std::string> problem = sampled_range_problem(distribution, unit.to_si)) {
    throw InputError(section_location, "[" + section.name + "] law " + describe(distribution) + " in " +
                                           std::string(unit.symbol) + ": " + *problem + ": expected " +
                                           sampled_range_expectation + ", in the file's unit and in SI units");
  }
  // A fraction outside [0, 1] is no tube's: the law must keep every drawn value inside.
  if (fraction) {
    if (const std::optional<std::string> problem = fraction_range_problem(distribution, 1.0 / unit.to_si)) {
      throw InputError(section_location, "[" + section.name + "] law " + describe(distribution) + " in " +
                                             std::string(unit.symbol) + ": " + *problem +
                                             ": expected a law of values in [0, 1] as a fraction ([0, 100] in %), "
                                             "e.g. law = beta or a truncated_normal with upper = 1 (100 in %)");
    }
  }
  // Every measured variable is a positive quantity. A law whose median is not positive draws
  // mostly impossible values (flagged, left out of the statistics): the few left would pass for
  // the line's.
  if (const double median = quantile(distribution, 0.5); !(median > 0.0)) {
    throw InputError(section_location, "[" + section.name + "] law " + describe(distribution) + " in " +
                                           std::string(unit.symbol) + ": its median " + format_double(median) +
                                           " is not positive: expected a law of positive values for " + section.name +
                                           ", the " + std::string(quantity.description));
  }
  return LineVariable{std::string(name), &unit, std::move(distribution), source, note ? note->value : std::string(),
                      section.line, tubes_of(document, section, law_entry)};
}

namespace {

LineVariable read_variable(const IniDocument& document, const IniSection& section) {
  if (std::find(measured_variables.begin(), measured_variables.end(), section.name) == measured_variables.end()) {
    throw InputError(document.location(section.line), "unknown variable [" + section.name +
                                                          "]: expected [line] or one of the measured variables " +
                                                          joined(measured_variables));
  }
  return detail::read_law_section(document, section, section.name);
}

}  // namespace

const LineVariable* LineDistributions::find(std::string_view variable_name) const {
  for (const LineVariable& variable : variables) {
    if (variable.name == variable_name) return &variable;
  }
  return nullptr;
}

LineDistributions read_line_file(const std::string& path) {
  const IniDocument document = detail::read_plant_line_ini(path);
  LineDistributions line;
  line.path = path;
  for (const IniSection& section : document.sections) {
    if (section.name == "line") {
      for (const IniEntry& entry : section.entries) {
        if (entry.key != "name" && entry.key != "description") {
          throw InputError(document.location(entry.line),
                           "unknown key '" + entry.key + "' in [line]: expected name or description");
        }
      }
      continue;
    }
    line.variables.push_back(read_variable(document, section));
  }
  detail::LineHeader header = detail::read_line_header(document);
  line.name = std::move(header.name);
  line.description = std::move(header.description);
  if (line.variables.empty()) {
    throw InputError(path, "no variable sections: expected at least one of " + joined(measured_variables));
  }
  return line;
}

std::string format_line_variable(const LineVariable& variable) {
  std::string text = "[" + variable.name + "]\nlaw = " + std::string(family_name(variable.distribution)) + "\n";
  const auto entry = [&text](std::string_view key, double value) {
    text += std::string(key) + " = " + format_double(value) + "\n";
  };
  std::visit(
      [&](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, Lognormal>) {
          // mu and sigma round-trip exactly; median and IQR are what readers compare.
          text += "# median = " + format_double(d.median()) + ", iqr = " + format_double(d.iqr()) + "\n";
          entry("mu", d.mu());
          entry("sigma", d.sigma());
        } else if constexpr (std::is_same_v<T, Normal>) {
          entry("mean", d.mean());
          entry("sd", d.sd());
        } else if constexpr (std::is_same_v<T, TruncatedNormal>) {
          entry("mean", d.mean());
          entry("sd", d.sd());
          entry("lower", d.lower());
          entry("upper", d.upper());
        } else if constexpr (std::is_same_v<T, Uniform>) {
          entry("lower", d.lower());
          entry("upper", d.upper());
        } else if constexpr (std::is_same_v<T, Beta>) {
          // upper follows from the unit written below.
          entry("alpha", d.alpha());
          entry("beta", d.beta());
        } else if constexpr (std::is_same_v<T, Gamma> || std::is_same_v<T, Weibull>) {
          entry("shape", d.shape());
          entry("scale", d.scale());
        } else {
          std::string values;
          for (const double v : d.sorted_data()) values += (values.empty() ? "" : ", ") + format_double(v);
          text += "values = " + values + "\n";
        }
      },
      variable.distribution);
  text += "unit = " + std::string(variable.unit ? variable.unit->symbol : "1") + "\n";
  text += "source = " + variable.source + "\n";
  if (!variable.note.empty()) text += "note = " + variable.note + "\n";
  if (variable.tubes > 0) text += "tubes = " + std::to_string(variable.tubes) + "\n";
  return text;
}

}  // namespace growthuq
