#include "growthuq/growth/growth_rate.hpp"

#include "finite_checks.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"

namespace growthuq {

using growth_detail::moderate;
using growth_detail::non_negative_finite;
using growth_detail::positive_finite;
using growth_detail::positive_normal;
using growth_detail::scaled_ratio;

void validate(const GrowthParameters& parameters, std::string_view location) {
  if (!non_negative_finite(parameters.p0)) {
    throw_bad_value(location, "p0", format_double(parameters.p0 / unit_factor::MPa) + " MPa",
                    "a finite yield pressure >= 0 MPa");
  }
  if (!positive_finite(parameters.kappa)) {
    throw_bad_value(location, "kappa", format_double(parameters.kappa),
                    "a finite dimensionless factor > 0");
  }
}

GrowthEvaluator::GrowthEvaluator(GrowthParameters parameters) : parameters_(parameters) {
  validate(parameters_, "growth parameters");
}

void GrowthEvaluator::evaluate(SampleBlock& block) const {
  const auto p = block.column("p");
  const auto d = block.column("d");
  const auto eta = block.column("eta");
  const auto h = block.column("h");
  const auto v = block.add_column("v");
  const auto status = block.status();
  const double p0 = parameters_.p0;
  const double quarter_kappa = 0.25 * parameters_.kappa;
  const bool moderate_kappa = moderate(quarter_kappa);
  for (std::size_t i = 0; i < block.size(); ++i) {
    if (status[i] != SampleStatus::ok) continue;
    const bool valid = non_negative_finite(p[i]) && positive_finite(d[i]) &&
                       positive_finite(eta[i]) && positive_finite(h[i]);
    if (!valid) {
      status[i] = SampleStatus::invalid_input;
      continue;
    }
    const double overpressure = p[i] - p0;
    if (!(overpressure > 0.0)) {
      v[i] = 0.0;  // the wall does not yield: a true zero, counted through the status
      status[i] = SampleStatus::no_growth;
      continue;
    }
    // Grouped as (overpressure / viscosity = yield strain rate) x (slenderness d/h) x d. With
    // moderate inputs nothing over- or underflows; otherwise the rescaled slow path decides
    // whether v itself is beyond the double range.
    const bool direct = moderate_kappa && moderate(overpressure) && moderate(eta[i]) &&
                        moderate(d[i]) && moderate(h[i]);
    const double value = direct ? quarter_kappa * (overpressure / eta[i]) * (d[i] / h[i]) * d[i]
                                : scaled_ratio({quarter_kappa, overpressure, d[i], d[i]}, {eta[i], h[i]});
    if (positive_normal(value)) {
      v[i] = value;
    } else {
      status[i] = SampleStatus::out_of_range;
    }
  }
}

}  // namespace growthuq
