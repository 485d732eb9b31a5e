#include "campaign/campaign_models.hpp"

#include "growthuq/fidelity/fidelity.hpp"
#include "growthuq/growth/growth_rate.hpp"
#include "growthuq/growth/viscosity.hpp"

namespace growthuq {

std::vector<std::unique_ptr<const Evaluator>> campaign_models(const Campaign& campaign, Fidelity fidelity) {
  // A fidelity is the choice of the evaluators that provide p and E (fidelity/fidelity.hpp).
  std::vector<std::unique_ptr<const Evaluator>> models =
      turgor_modulus_models(fidelity, campaign.instrument, campaign.shell_fe, campaign.path);
  models.push_back(std::make_unique<ViscosityEvaluator>());
  models.push_back(std::make_unique<GrowthEvaluator>(GrowthParameters{campaign.yield_pressure, 1.0}));
  return models;
}

}  // namespace growthuq
