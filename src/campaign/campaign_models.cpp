#include "campaign/campaign_models.hpp"

#include <stdexcept>

#include "growthuq/correction/corrected_closed_form.hpp"
#include "growthuq/fe/shell_fe_evaluator.hpp"
#include "growthuq/growth/growth_rate.hpp"
#include "growthuq/growth/viscosity.hpp"
#include "growthuq/mechanics/thin_shell_evaluators.hpp"

namespace growthuq {

namespace {

// The evaluators that provide turgor p and modulus E: what the campaign's fidelity chooses.
// closed_form has two (a turgor-only campaign then needs no thickness); the other two write p
// and E together, from k, d, d0 and h.
void add_pressure_and_modulus(const Campaign& campaign, Fidelity fidelity, std::vector<std::unique_ptr<const Evaluator>>& models) {
  switch (fidelity) {
    case Fidelity::closed_form:
      models.push_back(std::make_unique<ThinShellTurgor>(campaign.instrument, campaign.path));
      models.push_back(std::make_unique<ThinShellModulus>());
      return;
    case Fidelity::corrected:
      models.push_back(std::make_unique<CorrectedTurgorModulus>(campaign.instrument, campaign.shell_fe, campaign.path));
      return;
    case Fidelity::shell_fe:
      models.push_back(std::make_unique<ShellFeTurgorModulus>(campaign.instrument, campaign.shell_fe, campaign.path));
      return;
  }
  throw std::logic_error("add_pressure_and_modulus: unknown fidelity");
}

}  // namespace

std::vector<std::unique_ptr<const Evaluator>> campaign_models(const Campaign& campaign, Fidelity fidelity) {
  std::vector<std::unique_ptr<const Evaluator>> models;
  add_pressure_and_modulus(campaign, fidelity, models);
  models.push_back(std::make_unique<ViscosityEvaluator>());
  models.push_back(std::make_unique<GrowthEvaluator>(GrowthParameters{campaign.yield_pressure, 1.0}));
  return models;
}

}  // namespace growthuq
