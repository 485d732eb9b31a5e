// Fidelity: which model turns an indentation measurement (k, d, d0, h) into turgor p and modulus
// E. One vocabulary and one factory, shared by a campaign's `fidelity =`, `growthuq eval
// --fidelity`, `growthuq tradeoff` and the Python package, so that a name accepted in one place
// is accepted in all. README, "Fidelity", compares their speed and accuracy.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "growthuq/correction/corrected_closed_form.hpp"
#include "growthuq/evaluation/evaluator.hpp"
#include "growthuq/fe/indentation.hpp"
#include "growthuq/mechanics/instrument.hpp"

namespace growthuq {

enum class Fidelity {
  closed_form,  // the thin shell's closed forms (hoop and Arnoldi relations); old name thin_shell
  corrected,    // the closed form times a correction fitted to the finite-element inverse
  shell_fe,     // the finite-element shell's inverse, one simulation per sample
};
std::string_view to_string(Fidelity);  // "closed_form", "corrected", "shell_fe"
// "closed_form" (or its old name "thin_shell"), "corrected", "shell_fe"; InputError naming
// `location` and `key` otherwise.
Fidelity parse_fidelity(std::string_view text, std::string_view location, std::string_view key);

// What a caller asks of the finite-element fidelity beyond p and E.
enum class ExtraOutputs { none, unstressed_thickness };

// The evaluators that give p and E at `fidelity`, in the planner's order of preference
// (evaluator.hpp, plan_evaluation):
//   closed_form  ThinShellTurgor (k, d, d0 -> lambda, alpha, phi, p), ThinShellModulus
//                (p, d, d0, h -> E, hoop_stress, wall_stiffness): turgor alone needs no h;
//   corrected    CorrectedTurgorModulus (k, d, d0, h -> p, E), then WallStress;
//   shell_fe     ShellFeTurgorModulus (k, d, d0, h -> p, E [, h0]), then WallStress;
// WallStress (p, E, d, d0, h -> lambda, hoop_stress, wall_stiffness) gives the higher fidelities
// the closed form's derived outputs from their own p and E. InputError naming `location` when
// the instrument or the finite-element options are invalid, or (corrected) not those the
// correction was fitted for, the option named as `names` says.
std::vector<std::unique_ptr<const Evaluator>> turgor_modulus_models(Fidelity fidelity, const Instrument& instrument,
                                                                    const ShellFeOptions& options,
                                                                    std::string_view location,
                                                                    OptionNames names = OptionNames::campaign_keys,
                                                                    ExtraOutputs extra = ExtraOutputs::none);

}  // namespace growthuq
