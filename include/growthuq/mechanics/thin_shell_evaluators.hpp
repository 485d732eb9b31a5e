// The thin-shell model as evaluators a campaign chains (evaluation/evaluator.hpp). Turgor and
// modulus are separate so that a turgor-only campaign never needs wall thickness:
//   ThinShellTurgor   reads k, d, d0      writes lambda, alpha, phi, p
//   ThinShellModulus  reads p, d, d0, h   writes E, hoop_stress, wall_stiffness
//   ThinShellForward  reads p, E, h, d0   writes d, k          (used by `growthuq correlate`)
//   WallStress        reads p, E, d, d0, h   writes lambda, hoop_stress, wall_stiffness
// WallStress gives a model that writes p and E together (fidelity/fidelity.hpp) the closed form's
// derived outputs: the hoop stress p d / (2 h) is the far field's exact equilibrium, whatever
// gave p.
// Each loops over contiguous columns calling the closed forms of thin_shell.hpp. Turgor and
// modulus take the stretch from the block's hoop_strain column when it has one (formed where the
// diameters entered, in their measured unit: add_hoop_strain), and from d and d0 in SI otherwise,
// which loses digits of lambda - 1 near lambda = 1 (TubeDiameters); lambda is then 1 + strain.
#pragma once

#include <span>
#include <string_view>

#include "growthuq/evaluation/evaluator.hpp"
#include "growthuq/mechanics/probe_radius_column.hpp"
#include "growthuq/mechanics/thin_shell.hpp"

namespace growthuq {

inline constexpr std::string_view hoop_strain_column = "hoop_strain";

// Adds the hoop_strain column, (d - d0)/d0 per sample from the diameters as measured (values
// `d`, `d0` in units of factors d_to_si, d0_to_si; measured_diameters). The caller sets the SI
// columns d and d0 itself (d * d_to_si, d0 * d0_to_si).
void add_hoop_strain(SampleBlock& block, std::span<const double> d, double d_to_si, std::span<const double> d0,
                     double d0_to_si);

class ThinShellTurgor final : public Evaluator {
 public:
  // InputError (from validate, with `location`) when the parameters are invalid.
  ThinShellTurgor(const Instrument& parameters, std::string_view location);
  std::string_view name() const override { return "thin_shell_turgor"; }
  std::vector<std::string> reads() const override { return reads_with_probe_radius({"k", "d", "d0"}, parameters_); }
  std::vector<std::string> writes() const override { return {"lambda", "alpha", "phi", "p"}; }
  void evaluate(SampleBlock& block) const override;

 private:
  Instrument parameters_;
};

class ThinShellModulus final : public Evaluator {
 public:
  std::string_view name() const override { return "thin_shell_modulus"; }
  std::vector<std::string> reads() const override { return {"p", "d", "d0", "h"}; }
  std::vector<std::string> writes() const override { return {"E", "hoop_stress", "wall_stiffness"}; }
  void evaluate(SampleBlock& block) const override;
};

class WallStress final : public Evaluator {
 public:
  std::string_view name() const override { return "wall_stress"; }
  std::vector<std::string> reads() const override { return {"p", "E", "d", "d0", "h"}; }
  std::vector<std::string> writes() const override { return {"lambda", "hoop_stress", "wall_stiffness"}; }
  void evaluate(SampleBlock& block) const override;
};

class ThinShellForward final : public Evaluator {
 public:
  ThinShellForward(const Instrument& parameters, std::string_view location);
  std::string_view name() const override { return "thin_shell_forward"; }
  std::vector<std::string> reads() const override { return reads_with_probe_radius({"p", "E", "h", "d0"}, parameters_); }
  std::vector<std::string> writes() const override { return {"d", "k"}; }
  void evaluate(SampleBlock& block) const override;

 private:
  Instrument parameters_;
};

}  // namespace growthuq
