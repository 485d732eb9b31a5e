#include "growthuq/growth/viscosity.hpp"

#include "finite_checks.hpp"

namespace growthuq {

using growth_detail::moderate;
using growth_detail::positive_finite;
using growth_detail::positive_normal;
using growth_detail::scaled_ratio;

void ViscosityEvaluator::evaluate(SampleBlock& block) const {
  const auto tau = block.column("tau");
  const auto einf = block.column("einf");
  const auto modulus = block.column("E");
  const auto eta = block.add_column("eta");
  const auto status = block.status();
  for (std::size_t i = 0; i < block.size(); ++i) {
    if (status[i] != SampleStatus::ok) continue;
    // einf = 1 would mean no relaxation at all (eta = 0); einf < 0 a modulus that grows.
    const bool valid = positive_finite(tau[i]) && einf[i] >= 0.0 && einf[i] < 1.0 &&
                       positive_finite(modulus[i]);
    if (!valid) {
      status[i] = SampleStatus::invalid_input;
      continue;
    }
    // Direct product when no intermediate can over- or underflow; otherwise (e.g. a subnormal
    // tau) the rescaled slow path, so out_of_range means eta itself is beyond double range.
    const double value = moderate(tau[i]) && moderate(modulus[i])
                             ? relaxation_viscosity(tau[i], einf[i], modulus[i])
                             : scaled_ratio({tau[i], 1.0 - einf[i], modulus[i]}, {});
    if (positive_normal(value)) {
      eta[i] = value;
    } else {
      status[i] = SampleStatus::out_of_range;
    }
  }
}

}  // namespace growthuq
