// Sobol' first-order and total indices of one campaign line (Eq. (S6), src/sensitivity/README.md)
// when [sensitivity] method = sobol, made only for a line whose inputs are independent (no
// rank_correlation): the pick-freeze estimators presume independence, and for a correlated line
// the run refuses them with one line saying why. New runs of the line's models (not shell_fe).
#pragma once

#include <string>
#include <vector>

#include "campaign/sensitivity_settings.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/evaluation/line_result.hpp"
#include "growthuq/sensitivity/sobol.hpp"

namespace growthuq {

struct LineSobol {
  std::string line;
  std::vector<std::string> inputs, outputs;  // column names: rows and columns of the indices
  bool computed = false;
  SobolIndices indices;
  std::string note;  // why not computed
};

LineSobol line_sobol(const PreparedCampaign& campaign, const LineResult& result, const SensitivitySettings& settings);

// The first-order and total indices as two tables (inputs as rows), or the note. Ends with a newline.
std::string format_line_sobol(const LineSobol& sobol);

}  // namespace growthuq
