#include "campaign/campaign_models.hpp"

#include "growthuq/growth/growth_rate.hpp"
#include "growthuq/growth/viscosity.hpp"
#include "growthuq/mechanics/thin_shell_evaluators.hpp"

namespace growthuq {

namespace {

// The evaluators that provide turgor p and modulus E: what the campaign's fidelity chooses.
void add_pressure_and_modulus(const Campaign& campaign, std::vector<std::unique_ptr<const Evaluator>>& models) {
  switch (campaign.fidelity) {
    case Fidelity::thin_shell:
      models.push_back(std::make_unique<ThinShellTurgor>(campaign.instrument, campaign.path));
      models.push_back(std::make_unique<ThinShellModulus>());
      return;
  }
}

}  // namespace

std::vector<std::unique_ptr<const Evaluator>> campaign_models(const Campaign& campaign) {
  std::vector<std::unique_ptr<const Evaluator>> models;
  add_pressure_and_modulus(campaign, models);
  models.push_back(std::make_unique<ViscosityEvaluator>());
  models.push_back(std::make_unique<GrowthEvaluator>(GrowthParameters{campaign.yield_pressure, 1.0}));
  return models;
}

}  // namespace growthuq
