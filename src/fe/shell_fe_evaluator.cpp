#include "growthuq/fe/shell_fe_evaluator.hpp"

#include <utility>

namespace growthuq {

SampleStatus sample_status(ShellFeStatus status) {
  switch (status) {
    case ShellFeStatus::ok: return SampleStatus::ok;
    case ShellFeStatus::invalid_input: return SampleStatus::invalid_input;
    case ShellFeStatus::not_converged: return SampleStatus::not_converged;
    case ShellFeStatus::burst: return SampleStatus::burst;
    case ShellFeStatus::contact_lost: return SampleStatus::contact_lost;
    case ShellFeStatus::probe_beyond_mesh: return SampleStatus::probe_beyond_mesh;
    case ShellFeStatus::window_not_reached: return SampleStatus::window_not_reached;
    case ShellFeStatus::stiffness_at_sensor_limit: return SampleStatus::stiffness_at_sensor_limit;
    case ShellFeStatus::no_inflation_state: return SampleStatus::no_inflation_state;
    case ShellFeStatus::no_modulus_root: return SampleStatus::no_modulus_root;
  }
  return SampleStatus::not_converged;
}

ShellFeTurgorModulus::ShellFeTurgorModulus(const Instrument& instrument, const ShellFeOptions& options,
                                           std::string_view location)
    : instrument_(instrument), options_(options) {
  validate(instrument_, location);
  options_.validate(location);
}

void ShellFeTurgorModulus::evaluate(SampleBlock& block) const {
  const std::span<const double> k = std::as_const(block).column("k");
  const std::span<const double> d = std::as_const(block).column("d");
  const std::span<const double> d0 = std::as_const(block).column("d0");
  const std::span<const double> h = std::as_const(block).column("h");
  const std::span<double> p = block.add_column("p");
  const std::span<double> E = block.add_column("E");
  const std::span<SampleStatus> status = block.status();
  for (std::size_t i = 0; i < block.size(); ++i) {
    if (status[i] != SampleStatus::ok) continue;
    const ShellFeInverse inverse = invert_indentation({k[i], h[i], d[i], d0[i]}, instrument_, options_);
    if (inverse.status != ShellFeStatus::ok) {
      status[i] = sample_status(inverse.status);
      continue;
    }
    p[i] = inverse.pressure;
    E[i] = inverse.young;
  }
}

}  // namespace growthuq
