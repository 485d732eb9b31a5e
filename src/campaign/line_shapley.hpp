// The Shapley effects of one campaign line (src/sensitivity/README.md, Eqs. (S3)-(S5)), when the
// campaign's [sensitivity] method is shapley: new model runs of the line's own models (its
// fidelity's closed form or correction; a shell_fe line is refused, a finite-element solve per
// run being out of proportion), inputs drawn from the line's laws joined by a Gaussian copula
// of the line's rank correlation target (the normal-score correlation Iman-Conover imposes,
// rank_correlation_target.hpp). Reported as shares Sh_i / Var(output), which sum to 1.
// Outputs of samples whose status is not ok count as missing (as in the line's analyses).
#pragma once

#include <string>
#include <vector>

#include "campaign/sensitivity_settings.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/campaign/run_time_estimate.hpp"
#include "growthuq/evaluation/line_result.hpp"
#include "growthuq/sensitivity/shapley.hpp"

namespace growthuq {

struct LineShapley {
  std::string line;
  std::vector<std::string> inputs;   // column names, rows of effects
  std::vector<std::string> outputs;  // column names, columns of effects
  bool computed = false;
  ShapleyEffects effects;
  std::string note;  // why not computed
};

// `result` gives the line's name, columns and rank correlation target.
LineShapley line_shapley(const PreparedCampaign& campaign, const LineResult& result, const SensitivitySettings& settings);

// The model runs the Shapley effects take per line (Eq. (S3) cost, src/sensitivity/README.md):
// N_v + (2^d - 2) N_o N_i with exact permutations (d <= 6 inputs), N_v + m (d - 1) N_o N_i beyond.
std::size_t shapley_model_runs(std::size_t inputs, const ShapleySettings& cost);

// The shares as a table (inputs as rows, outputs as columns, "share [low, high]"), the model runs
// and the copula assumption; or the note. Ends with a newline.
std::string format_line_shapley(const LineShapley& shapley);

}  // namespace growthuq
