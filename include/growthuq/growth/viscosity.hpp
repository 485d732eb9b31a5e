// Wall viscosity from the per-line relaxation distributions, for campaigns without raw
// force-relaxation curves (Eq. (G1), src/growth/README.md): eta = tau (1 - e_inf) E.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "growthuq/evaluation/evaluator.hpp"
#include "growthuq/relaxation/viscosity.hpp"  // relaxation_viscosity: eta = tau (1 - e_inf) E

namespace growthuq {

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
