// The outputs a campaign adds for lines given by raw data (raw = FILE) once its lines are done:
// the fit report on stdout, the fits, the curves and their fitted models in results.h5, and the
// data-uncertainty bootstrap (data_uncertainty.hpp) as data_uncertainty.csv, in results.h5 and
// on stdout, followed by the line comparisons on that bootstrap (line_comparison_outputs.hpp).
// Without a bootstrap: only the line saying comparisons need it (for two lines or more).
//
// results.h5 (in addition to the campaign layout; NaN for undefined numbers):
//   /lines/<line>/fits                 one row per variable: variable, unit, family, parameters
//                                      (text), n (int64), log_likelihood, aic, ks, ad, source
//   /lines/<line>/fit_candidates       one row per variable and family tried: variable, family,
//                                      status ("ok" or "failed"), parameters, n, log_likelihood,
//                                      aic, delta_aic (to the chosen family), ks, ad, reason
//   /lines/<line>/fit_parameters       the laws' parameters as numbers (unrounded), one row per
//                                      variable, family that fitted and parameter: variable, unit,
//                                      family, chosen (int64, 1 for the least-AIC family),
//                                      parameter, value (distribution.hpp parameter_values)
//   /lines/<line>/relaxation/fits      one row per curve, the columns of `growthuq relax` (curve,
//                                      status (ok, extrapolated, fit_failed), reason, terms,
//                                      tau_fast_s, tau_mid_s, tau_slow_s, tau_slow_low_s,
//                                      tau_slow_high_s, einf_frac, E0_MPa, eta_MPa_s, Er0_MPa, tau_slow_se_pct, rms,
//                                      aic, ramp_time_s, points) and the tube sheet (delta_um,
//                                      p_MPa, d_um, h_nm, rho_um); group attributes fit ("step" or
//                                      "ramp_aware"), terms, curves_path
//   /lines/<line>/relaxation/points/   the curves in long format on the dimension `point`:
//                                      curve_index (int32, row of the
//                                      fits table), t_s, F_uN (data), F_fit_uN (the fitted model at
//                                      the point, relaxation/analysis.hpp fitted_force; NaN before
//                                      the force maximum for the step fit)
//   /lines/<line>/force_curves/curves  one row per force curve ([force_curves]): curve, tube, repetition,
//                                      status, reason, baseline_offset_uN, baseline_tilt_N_per_m, and
//                                      for an ok curve (NaN otherwise) contact_z_um, window_low_uN,
//                                      window_high_uN (forces above the baseline), k_m_N_per_m and
//                                      fit_intercept_uN (the window line: F - baseline = intercept +
//                                      k_m z), k_N_per_m, u_N_per_m; attributes curves_path, window
//   /lines/<line>/force_curves/tubes   one row per tube: tube, curves, ok, k_N_per_m, spread_N_per_m,
//                                      u_N_per_m (Eq. (C10), NaN without an ok curve)
//   /lines/<line>/force_curves/points/ the approaches in long format on the dimension `point`:
//                                      curve_index (int32, row of curves), z_um, F_uN (as recorded)
//   /data_uncertainty                  one row per line and output: line, quantity, unit, median,
//                                      median_ci_low, median_ci_high (the Monte Carlo CI of
//                                      summary.csv), data_ci_low, data_ci_high, data_sd,
//                                      replicates, failed_replicates, samples_per_replicate,
//                                      measurement_error ("included": k of force curves was also
//                                      drawn within each tube's uncertainty; "none") (attribute method); also under /lines/<line>/data_uncertainty
//   /lines/<line>/data_uncertainty_replicates/<quantity>   float64, the successful replicates'
//                                      medians (attributes unit and units, dimension replicate),
//                                      for plots and other intervals
//   /line_comparisons, /line_letters   the line comparisons on the bootstrap
//                                      (line_comparison_outputs.hpp), with comparisons.csv and
//                                      letters.csv
// Every table has the attribute column_units (ExtraColumn::unit of each member).
#pragma once

#include <span>
#include <string>

#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/campaign/data_uncertainty.hpp"
#include "growthuq/evaluation/line_result.hpp"
#include "growthuq/io/results_h5.hpp"

namespace growthuq {

inline constexpr const char* data_uncertainty_csv_name = "data_uncertainty.csv";

// Writes what is above (h5 may be null: no results.h5 this run; data_uncertainty.csv goes to
// `directory`, where the run stages its results) and returns the report text for stdout.
// `summaries` are the campaign's rows of summary.csv, `uncertainty` the bootstrap's result
// (estimate_data_uncertainty; no rows when the campaign has none).
std::string write_raw_data_outputs(const PreparedCampaign& campaign, std::span<const QuantitySummary> summaries,
                                   DataUncertaintyResult uncertainty, ResultsH5Writer* h5, const std::string& directory);

// Each summary's data interval (data_ci_low/high) from the bootstrap row of its line and
// quantity; summaries without a row keep NaN.
void add_data_intervals(std::span<QuantitySummary> summaries, std::span<const DataUncertainty> rows);

// The data-uncertainty rows as CSV text (the columns of /data_uncertainty above).
std::string data_uncertainty_csv_text(std::span<const DataUncertainty> rows);

}  // namespace growthuq
