// Steady tip growth rate of a pollen tube from turgor, diameter, wall viscosity and
// thickness: Lockhart's yield-flow law on a hemispherical tip (Eq. (G4), src/growth/README.md),
//   v = kappa (p - p0) d^2 / (4 eta h).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "growthuq/evaluation/evaluator.hpp"

namespace growthuq {

// Campaign parameters of the growth law, SI. p0 is the yield turgor (same for every line;
// 0 allowed); kappa the dimensionless geometric factor calibrated once per campaign on a
// reference line (see kappa.hpp).
struct GrowthParameters {
  double p0 = 0.0;     // Pa
  double kappa = 1.0;  // dimensionless, > 0
};

// InputError "<location>: p0 = '<value> MPa': expected ..." (or kappa) unless p0 is finite and
// >= 0 and kappa finite and > 0. `location` is where the values came from (file:line, option).
void validate(const GrowthParameters& parameters, std::string_view location);

// Reads p, d, eta, h; writes v [m/s]. Per sample:
//   - invalid_input, v = NaN: p negative or not finite, or d, eta, h not positive and finite;
//   - no_growth, v = 0: p <= p0. The wall does not yield, so the physical rate is zero and the
//     column holds exactly 0 (a summary can include these tubes as non-growing or skip them by
//     status; either way they are counted, never mistaken for missing values);
//   - out_of_range, v = NaN: v overflows or underflows a normal double (eta tiny or huge
//     beyond the envelope, or an extreme kappa);
//   - ok: v = kappa (p - p0) d^2 / (4 eta h) > 0.
class GrowthEvaluator final : public Evaluator {
 public:
  // Validates `parameters` (InputError with location "growth parameters").
  explicit GrowthEvaluator(GrowthParameters parameters);

  const GrowthParameters& parameters() const noexcept { return parameters_; }

  std::string_view name() const override { return "growth"; }
  std::vector<std::string> reads() const override { return {"p", "d", "eta", "h"}; }
  std::vector<std::string> writes() const override { return {"v"}; }
  void evaluate(SampleBlock& block) const override;

 private:
  GrowthParameters parameters_;
};

}  // namespace growthuq
