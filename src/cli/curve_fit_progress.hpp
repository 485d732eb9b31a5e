// The relaxation curves of a command fitted one after the other with their progress on stderr
// (the fits take seconds: about 1.4 s of CPU for 31 curves), as a campaign shows them
// (campaign/shared_raw_fits.cpp); nothing with ProgressMode::none.
#pragma once

#include <vector>

#include "growthuq/campaign/progress_mode.hpp"
#include "growthuq/relaxation/analysis.hpp"

namespace growthuq::cli {

std::vector<CurveFit> fit_curves_showing_progress(const std::vector<RelaxationCurve>& curves,
                                                  const RelaxationOptions& options, ProgressMode mode);

}  // namespace growthuq::cli
