// The relaxation-curve fits of a raw-data line (most of the time a raw line takes to fit)
// shared out over the processes of a Pool, so that under mpirun the curves are fitted once per
// campaign and not once per process. Every process ends with every fit; a fit is a pure
// function of its curve, so the fits, and the campaign, do not depend on the number of
// processes.
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "growthuq/campaign/progress.hpp"
#include "growthuq/pool/pool.hpp"
#include "growthuq/rawdata/raw_line_fit.hpp"
#include "growthuq/relaxation/analysis.hpp"

namespace growthuq {

// A CurveFitter (raw_line_fit.hpp) over `pool`: one curve per chunk, handed out as processes
// become free; rank 0 collects the fits and sends them to every process. Every process must
// call it with the same curves and options. Progress ("fitting relaxation curves of line
// <line>: curve 12/31") goes to `log` as `progress` says (ProgressMode::none off rank 0). The
// fitter refers to `pool` and `log`, which must outlive it.
CurveFitter shared_curve_fitter(Pool& pool, std::string line, ProgressMode progress, std::ostream& log);

// A curve fit as numbers and back, exactly (texts as character codes, counts as doubles): what
// travels between the processes.
std::vector<double> curve_fit_numbers(const CurveFit& fit);
// std::invalid_argument when `numbers` is not one whole curve_fit_numbers() record.
CurveFit curve_fit_from_numbers(std::span<const double> numbers);

}  // namespace growthuq
