#include "campaign/parametric_resample.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

#include "growthuq/core/error.hpp"
#include "growthuq/distributions/fit.hpp"
#include "growthuq/distributions/standard_normal.hpp"
#include "growthuq/sampling/random_stream.hpp"

namespace growthuq {

std::vector<double> parametric_resample(const Distribution& law, std::size_t count, std::uint64_t replicate_key,
                                        std::string_view line, std::string_view variable) {
  RandomStream stream(derive_key(replicate_key, std::string(line) + "/" + std::string(variable)));
  std::vector<double> values(count);
  for (double& value : values) value = quantile(law, stream.uniform_open());
  return values;
}

void add_measurement_error(std::vector<double>& values, const std::vector<double>& uncertainties,
                           std::uint64_t replicate_key, std::string_view line, std::string_view variable) {
  if (uncertainties.size() != values.size()) throw std::logic_error("one measurement uncertainty per value expected");
  RandomStream stream(derive_key(replicate_key, std::string(line) + "/" + std::string(variable) + "/measurement_error"));
  // A redraw almost never happens (k - 0 is many u away); the cap only guards a u far above k.
  constexpr int max_draws = 1000;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (uncertainties[i] == 0.0) continue;
    double drawn = 0.0;
    for (int draw = 0; draw < max_draws && !(drawn > 0.0); ++draw) {
      drawn = values[i] + uncertainties[i] * standard_normal_quantile(stream.uniform_open());
    }
    if (!(drawn > 0.0)) {
      throw InputError("data uncertainty, line " + std::string(line),
                       std::string(variable) + " = " + std::to_string(values[i]) + " with measurement uncertainty " +
                           std::to_string(uncertainties[i]) + ": no positive draw in " + std::to_string(max_draws) +
                           " (expected u well below the value)");
    }
    values[i] = drawn;
  }
}

bool states_tubes(const LineDistributions& line) {
  for (const LineVariable& variable : line.variables) {
    if (variable.tubes > 0) return true;
  }
  return false;
}

LineDistributions resampled_stated_line(const LineDistributions& line, std::string_view line_name,
                                        std::uint64_t replicate_key) {
  LineDistributions result = line;
  for (LineVariable& variable : result.variables) {
    if (variable.tubes == 0) continue;
    const std::optional<FitFamily> family = fit_family_of(variable.distribution);
    if (!family) throw std::logic_error("tubes stated for a law without a fit: " + variable.name);
    // The beta law's upper end is fixed by the unit (1 in frac, 100 in %), not estimated.
    const double fraction_upper = std::holds_alternative<Beta>(variable.distribution)
                                      ? std::get<Beta>(variable.distribution).upper()
                                      : 1.0;
    const std::vector<double> values =
        parametric_resample(variable.distribution, variable.tubes, replicate_key, line_name, variable.name);
    try {
      variable.distribution = fit_distribution(*family, values, fraction_upper).distribution;
    } catch (const InputError& error) {
      throw InputError("data uncertainty, line " + std::string(line_name),
                       "[" + variable.name + "] refit of " + describe(variable.distribution) + " to " +
                           std::to_string(variable.tubes) + " drawn values: " + error.what());
    }
  }
  return result;
}

}  // namespace growthuq
