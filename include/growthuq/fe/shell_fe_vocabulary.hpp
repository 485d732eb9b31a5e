// The finite-element shell's words, one enum per concept, shared by its options
// (indentation.hpp, what a campaign or `growthuq indent` sets) and its solver (src/fe, whose
// ForwardProblem takes them as they are: no translation between two mirrored families).
#pragma once

namespace growthuq {

// The wall's constitutive law, both linear in E (src/fe/README.md, equations 3-4).
enum class ShellFeLaw {
  hencky,                  // "log": Kirchhoff stress = Hooke's law of the logarithmic strain
  saint_venant_kirchhoff,  // "stvk": second Piola-Kirchhoff stress = Hooke's law of Green's strain
};
enum class ShellFeGeometry { tube, sphere, file };
enum class ShellFeMesh { coarse, standard, fine, finer };  // "coarse" | "default" | "fine" | "finer"

// The strain energy the study's driver's viscous stabilisation measures its dissipation against
// (src/fe/README.md, "Viscous stabilisation"): the commercial code's documents say "strain
// energy" without saying whether it is the model's or the step's, so both are offered.
enum class ShellFeStabilisationEnergy {
  model,  // "model": the model's strain energy (membrane + bending), the inflation's included
  step,   // "step": what the indentation adds to the stored energy (strain energy and -p V)
};

// The driver's automatic viscous stabilisation of the indentation's load steps, as an ablation
// of the study's choice (not a model option a lab should use). Off (fraction 0) by default.
struct ShellFeStabilisation {
  double fraction = 0.0;  // dissipated-energy fraction of the first increment's rule; 0: off
  double ratio = 0.0;     // adaptive cap: dissipated <= ratio x strain energy; 0: no cap
  ShellFeStabilisationEnergy energy = ShellFeStabilisationEnergy::model;
  bool active() const { return fraction > 0.0; }
};

}  // namespace growthuq
