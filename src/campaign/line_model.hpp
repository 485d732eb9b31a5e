// A campaign line's models as a function of its inputs, for the sensitivity estimators that need
// new model runs (Shapley effects, Sobol' indices): rows of inputs in the line file's units
// through PreparedCampaign::evaluate_chunk, as the run evaluates a chunk; outputs in SI, NaN
// where the sample's status is not ok (as the line's analyses leave those out).
#pragma once

#include <vector>

#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/sensitivity/shapley.hpp"

namespace growthuq {

// The prepared line named `name`; std::logic_error when there is none (a caller's bug).
const PreparedLine& prepared_line(const PreparedCampaign& campaign, const std::string& name);

// The model (valid while `campaign` is) and the marginal quantile functions of the line's design
// variables, in their order.
BatchModel line_model(const PreparedCampaign& campaign, const PreparedLine& line);
std::vector<Quantile> line_marginals(const PreparedLine& line);

}  // namespace growthuq
