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

}  // namespace growthuq
