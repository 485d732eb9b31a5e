#include "growthuq/fidelity/fidelity.hpp"

#include <stdexcept>

#include "growthuq/core/error.hpp"
#include "growthuq/fe/shell_fe_evaluator.hpp"
#include "growthuq/mechanics/thin_shell_evaluators.hpp"

namespace growthuq {

std::string_view to_string(Fidelity fidelity) {
  switch (fidelity) {
    case Fidelity::closed_form: return "closed_form";
    case Fidelity::corrected: return "corrected";
    case Fidelity::shell_fe: return "shell_fe";
  }
  return "?";
}

Fidelity parse_fidelity(std::string_view text, std::string_view location, std::string_view key) {
  if (text == "closed_form" || text == "thin_shell") return Fidelity::closed_form;
  if (text == "corrected") return Fidelity::corrected;
  if (text == "shell_fe") return Fidelity::shell_fe;
  throw_bad_value(location, key, text,
                  "closed_form (the thin shell's closed forms; old name thin_shell), corrected (the closed form "
                  "corrected to the finite-element model) or shell_fe (the finite-element model)");
}

std::vector<std::unique_ptr<const Evaluator>> turgor_modulus_models(Fidelity fidelity, const Instrument& instrument,
                                                                    const ShellFeOptions& options,
                                                                    std::string_view location, OptionNames names,
                                                                    ExtraOutputs extra) {
  std::vector<std::unique_ptr<const Evaluator>> models;
  switch (fidelity) {
    case Fidelity::closed_form:
      models.push_back(std::make_unique<ThinShellTurgor>(instrument, location));
      models.push_back(std::make_unique<ThinShellModulus>());
      return models;
    case Fidelity::corrected:
      models.push_back(std::make_unique<CorrectedTurgorModulus>(instrument, options, location, names));
      models.push_back(std::make_unique<WallStress>());
      return models;
    case Fidelity::shell_fe:
      models.push_back(std::make_unique<ShellFeTurgorModulus>(
          instrument, options, location,
          extra == ExtraOutputs::unstressed_thickness ? ShellFeTurgorModulus::Outputs::with_unstressed_thickness
                                                      : ShellFeTurgorModulus::Outputs::turgor_modulus));
      models.push_back(std::make_unique<WallStress>());
      return models;
  }
  throw std::logic_error("turgor_modulus_models: unknown fidelity");
}

}  // namespace growthuq
