// The thin-shell model as evaluators a campaign chains (evaluation/evaluator.hpp). Turgor and
// modulus are separate so that a turgor-only campaign never needs wall thickness:
//   ThinShellTurgor   reads k, d, d0      writes lambda, alpha, phi, p
//   ThinShellModulus  reads p, d, d0, h   writes E, hoop_stress, wall_stiffness
//   ThinShellForward  reads p, E, h, d0   writes d, k          (used by `growthuq correlate`)
// Each loops over contiguous columns calling the closed forms of thin_shell.hpp.
#pragma once

#include "growthuq/evaluation/evaluator.hpp"
#include "growthuq/mechanics/thin_shell.hpp"

namespace growthuq {

class ThinShellTurgor final : public Evaluator {
 public:
  // InputError (from validate, with `location`) when the parameters are invalid.
  ThinShellTurgor(const Instrument& parameters, std::string_view location);
  std::string_view name() const override { return "thin_shell_turgor"; }
  std::vector<std::string> reads() const override { return {"k", "d", "d0"}; }
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

class ThinShellForward final : public Evaluator {
 public:
  ThinShellForward(const Instrument& parameters, std::string_view location);
  std::string_view name() const override { return "thin_shell_forward"; }
  std::vector<std::string> reads() const override { return {"p", "E", "h", "d0"}; }
  std::vector<std::string> writes() const override { return {"d", "k"}; }
  void evaluate(SampleBlock& block) const override;

 private:
  Instrument parameters_;
};

}  // namespace growthuq
