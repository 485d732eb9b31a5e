// Batch loops of the thin-shell evaluators: one pass over contiguous columns per block, no
// virtual call per sample. Samples flagged on entry are skipped and keep NaN outputs.
#include "growthuq/mechanics/thin_shell_evaluators.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace growthuq {

namespace {

// Sample i's diameters: with the strain formed at the edge when the block carries it.
TubeDiameters diameters_of(std::span<const double> d, std::span<const double> d0, std::span<const double> strain,
                           std::size_t i) {
  if (strain.empty()) return diameters_in_si(d[i], d0[i]);
  return {d[i], d0[i], 1.0 + strain[i], strain[i]};
}

std::span<const double> strain_column(const SampleBlock& block) {
  return block.has(hoop_strain_column) ? block.column(hoop_strain_column) : std::span<const double>();
}

}  // namespace

void add_hoop_strain(SampleBlock& block, std::span<const double> d, double d_to_si, std::span<const double> d0,
                     double d0_to_si) {
  const std::span<double> strain = block.add_column(hoop_strain_column);
  for (std::size_t i = 0; i < strain.size(); ++i) strain[i] = measured_diameters(d[i], d_to_si, d0[i], d0_to_si).strain;
}

ThinShellTurgor::ThinShellTurgor(const Instrument& parameters, std::string_view location)
    : parameters_(parameters) {
  validate(parameters_, location);
}

void ThinShellTurgor::evaluate(SampleBlock& block) const {
  const std::span<const double> k = std::as_const(block).column("k");
  const std::span<const double> d = std::as_const(block).column("d");
  const std::span<const double> d0 = std::as_const(block).column("d0");
  const std::span<const double> strain = strain_column(block);
  const SampleInstruments instruments(block, parameters_);
  const std::span<double> lambda = block.add_column("lambda");
  const std::span<double> alpha = block.add_column("alpha");
  const std::span<double> phi = block.add_column("phi");
  const std::span<double> p = block.add_column("p");
  const std::span<SampleStatus> status = block.status();
  for (std::size_t i = 0; i < block.size(); ++i) {
    if (status[i] != SampleStatus::ok) continue;
    const TurgorResult result = invert_turgor(k[i], diameters_of(d, d0, strain, i), instruments[i]);
    if (result.status != SampleStatus::ok) {
      status[i] = result.status;
      continue;
    }
    lambda[i] = result.lambda;
    alpha[i] = result.alpha;
    phi[i] = result.phi;
    p[i] = result.p;
  }
}

void ThinShellModulus::evaluate(SampleBlock& block) const {
  const std::span<const double> p = std::as_const(block).column("p");
  const std::span<const double> d = std::as_const(block).column("d");
  const std::span<const double> d0 = std::as_const(block).column("d0");
  const std::span<const double> h = std::as_const(block).column("h");
  const std::span<const double> strain = strain_column(block);
  const std::span<double> E = block.add_column("E");
  const std::span<double> hoop_stress = block.add_column("hoop_stress");
  const std::span<double> wall_stiffness = block.add_column("wall_stiffness");
  const std::span<SampleStatus> status = block.status();
  for (std::size_t i = 0; i < block.size(); ++i) {
    if (status[i] != SampleStatus::ok) continue;
    const ModulusResult result = invert_modulus(p[i], diameters_of(d, d0, strain, i), h[i]);
    if (result.status != SampleStatus::ok) {
      status[i] = result.status;
      continue;
    }
    E[i] = result.E;
    hoop_stress[i] = result.hoop_stress;
    wall_stiffness[i] = result.wall_stiffness;
  }
}

void WallStress::evaluate(SampleBlock& block) const {
  const std::span<const double> p = std::as_const(block).column("p");
  const std::span<const double> E = std::as_const(block).column("E");
  const std::span<const double> d = std::as_const(block).column("d");
  const std::span<const double> d0 = std::as_const(block).column("d0");
  const std::span<const double> h = std::as_const(block).column("h");
  const std::span<const double> strain = strain_column(block);
  const std::span<double> lambda = block.add_column("lambda");
  const std::span<double> hoop_stress = block.add_column("hoop_stress");
  const std::span<double> wall_stiffness = block.add_column("wall_stiffness");
  const std::span<SampleStatus> status = block.status();
  for (std::size_t i = 0; i < block.size(); ++i) {
    if (status[i] != SampleStatus::ok) continue;
    const TubeDiameters diameters = diameters_of(d, d0, strain, i);
    lambda[i] = diameters.lambda;
    hoop_stress[i] = p[i] * diameters.d / (2.0 * h[i]);  // the modulus is the caller's E, not hoop / ln lambda
    wall_stiffness[i] = E[i] * h[i];
    if (!std::isfinite(lambda[i]) || !std::isfinite(hoop_stress[i]) || !std::isfinite(wall_stiffness[i])) {
      lambda[i] = hoop_stress[i] = wall_stiffness[i] = std::numeric_limits<double>::quiet_NaN();
      status[i] = SampleStatus::out_of_range;
    }
  }
}

ThinShellForward::ThinShellForward(const Instrument& parameters, std::string_view location)
    : parameters_(parameters) {
  validate(parameters_, location);
}

void ThinShellForward::evaluate(SampleBlock& block) const {
  const std::span<const double> p = std::as_const(block).column("p");
  const std::span<const double> E = std::as_const(block).column("E");
  const std::span<const double> h = std::as_const(block).column("h");
  const std::span<const double> d0 = std::as_const(block).column("d0");
  const SampleInstruments instruments(block, parameters_);
  const std::span<double> d = block.add_column("d");
  const std::span<double> k = block.add_column("k");
  const std::span<SampleStatus> status = block.status();
  for (std::size_t i = 0; i < block.size(); ++i) {
    if (status[i] != SampleStatus::ok) continue;
    const ForwardResult result = thin_shell_forward(p[i], E[i], h[i], d0[i], instruments[i]);
    if (result.status != SampleStatus::ok) {
      status[i] = result.status;
      continue;
    }
    d[i] = result.d;
    k[i] = result.k_measured;
  }
}

}  // namespace growthuq
