// Where a campaign line's distributions come from: its line file (distributions = FILE), or its
// raw data (raw = FILE), fitted here with the campaign's instrument (probe radius and Poisson
// ratio map the relaxation curves to E_r(t)). The fits are kept for the report and results.h5.
#pragma once

#include <memory>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/mechanics/thin_shell.hpp"
#include "growthuq/rawdata/raw_line_fit.hpp"

namespace growthuq {

// The line's distributions; `raw_fit` is set to the fits when the line has raw data and reset
// otherwise. InputError naming the file for any problem (line_file.hpp, raw_line_fit.hpp).
// `fit_curves` (optional) fits the relaxation curves (RawFitSettings::fit_curves).
LineDistributions load_line_distributions(const CampaignLine& line, const Instrument& instrument,
                                          std::shared_ptr<const RawLineFit>& raw_fit, const CurveFitter& fit_curves = {});

}  // namespace growthuq
