// The finite-element shell's words, one enum per concept, shared by its options
// (indentation.hpp, what a campaign or `growthuq indent` sets) and its solver (src/fe, whose
// ForwardProblem takes them as they are: no translation between two mirrored families).
#pragma once

namespace growthuq {

enum class ShellFeGeometry { tube, sphere, file };
enum class ShellFeMesh { coarse, standard, fine, finer };  // "coarse" | "default" | "fine" | "finer"

}  // namespace growthuq
