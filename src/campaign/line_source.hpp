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

// A line whose k comes from raw force curves ([force_curves]) against the campaign that uses it:
// the curves' k is already the tube's (each curve corrected for its sheet's k_sys), so a finite
// [instrument] sensor_stiffness_N_per_m would correct it twice; and at fidelity shell_fe or
// corrected the model's k is a slope over [shell_fe] force_window_uN from contact, so the data's
// window must be that absolute window (a k over another window is another quantity for a
// nonlinear curve). InputError at `location` naming both otherwise.
void require_force_curves_match(const RawLineFit& fit, const Campaign& campaign, Fidelity fidelity,
                                const std::string& location);

}  // namespace growthuq
