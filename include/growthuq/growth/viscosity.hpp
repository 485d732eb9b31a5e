// Wall viscosity from the per-line relaxation distributions, for campaigns without raw
// force-relaxation curves (Eq. (G1), src/growth/README.md): eta = tau (1 - e_inf) E.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "growthuq/evaluation/evaluator.hpp"

namespace growthuq {

// eta = tau (1 - e_inf) E [Pa s] for one sample (SI: tau in s, e_inf = E_inf/E_r(0) as a
// fraction, E in Pa). The slow Maxwell branch relaxes the share 1 - e_inf of the modulus with
// time constant tau, so its viscosity is tau times that share of E (generalized Maxwell model,
// Eq. (R7): eta = tau E0 with E0 = (1 - e_inf) E). No validation: see the evaluator.
inline double relaxation_viscosity(double tau, double einf, double modulus) noexcept {
  return tau * (1.0 - einf) * modulus;
}

// Reads tau, einf, E; writes eta. Status invalid_input when tau or E is not positive and
// finite or einf is outside [0, 1); out_of_range when eta is not a normal positive double.
class ViscosityEvaluator final : public Evaluator {
 public:
  std::string_view name() const override { return "viscosity"; }
  std::vector<std::string> reads() const override { return {"tau", "einf", "E"}; }
  std::vector<std::string> writes() const override { return {"eta"}; }
  void evaluate(SampleBlock& block) const override;
};

}  // namespace growthuq
