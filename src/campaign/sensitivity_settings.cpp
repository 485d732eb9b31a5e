#include "campaign/sensitivity_settings.hpp"

#include <algorithm>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"

namespace growthuq {

SensitivitySettings read_sensitivity_section(const IniDocument& document, const IniSection& section) {
  SensitivitySettings settings;
  constexpr std::string_view allowed = "method, outer, inner, permutations, variance_samples, sobol_samples";
  for (const IniEntry& entry : section.entries) {
    const std::string location = document.location(entry.line);
    if (entry.key == "method") {
      if (entry.value != "first_order" && entry.value != "shapley" && entry.value != "sobol") {
        throw_bad_value(location, entry.key, entry.value, "first_order, shapley or sobol");
      }
      settings.shapley = entry.value == "shapley";
      settings.sobol = entry.value == "sobol";
    } else if (entry.key == "outer") {
      // At least one per section of the interval (Eq. (S5)).
      settings.cost.outer = parse_count(entry.value, location, entry.key, settings.cost.sections, 10000000);
    } else if (entry.key == "inner") {
      settings.cost.inner = parse_count(entry.value, location, entry.key, 2, 1000);
    } else if (entry.key == "permutations") {
      settings.cost.permutations = parse_count(entry.value, location, entry.key, settings.cost.sections, 10000000);
    } else if (entry.key == "variance_samples") {
      settings.cost.variance_samples = parse_count(entry.value, location, entry.key, 2 * settings.cost.sections, 100000000);
    } else if (entry.key == "sobol_samples") {
      settings.sobol_cost.samples = parse_count(entry.value, location, entry.key, 2 * settings.sobol_cost.sections, 100000000);
    } else {
      throw InputError(location, "unknown key '" + entry.key + "' in [sensitivity] (allowed: " + std::string(allowed) + ")");
    }
  }
  return settings;
}

SensitivitySettings sensitivity_settings(const Campaign& campaign) {
  const IniDocument document = parse_ini(campaign.text, campaign.path);
  const IniSection* section = document.find("sensitivity");
  return section == nullptr ? SensitivitySettings{} : read_sensitivity_section(document, *section);
}

}  // namespace growthuq
