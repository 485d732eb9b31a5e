// growthuq curves: the apparent stiffness k of every raw force-indentation curve and of every
// tube (its repeated curves), with their uncertainty, as CSV tables and a report (Eqs. (C1)-(C10),
// src/forcecurves/README.md).
#include <cmath>
#include <iostream>
#include <map>
#include <optional>

#include "growthuq/campaign/progress.hpp"
#include "commands.hpp"
#include "growthuq/campaign/progress_mode.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/forcecurves/curve_processing.hpp"
#include "growthuq/forcecurves/force_curve.hpp"
#include "growthuq/forcecurves/tube_stiffness.hpp"
#include "growthuq/forcecurves/window_text.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/io/output_file.hpp"
#include "options.hpp"
#include "result_output.hpp"

namespace growthuq::cli {
namespace {

constexpr std::string_view command = "growthuq curves";
constexpr std::string_view usage = "CURVES --out CURVES_K.csv [--tubes TUBES_K.csv] [options]";

struct CurvesOptions {
  std::string curves;
  std::string sheet;
  std::string out;
  std::string tubes;
  CurveProcessingOptions processing;
  Overwrite overwrite = Overwrite::refuse;
  bool quiet = false;
};

CurvesOptions parse(const Arguments& arguments, bool& run) {
  CurvesOptions options;
  CurveProcessingOptions& processing = options.processing;
  std::string contact = "deviation", window = "relative", window_uN, baseline = "tilt";
  double edge_step_uN = 0.1;
  int minimum_samples = static_cast<int>(processing.minimum_window_samples);
  po::options_description described("options");
  described.add_options()
      ("curves", po::value(&options.curves)->required(),
       "force curves: a CSV file (a curve column for several curves) or a folder of CSV files, one curve each "
       "(format: distributions/README.md, Force curves)")
      ("sheet", po::value(&options.sheet), "curve sheet: CSV curve,tube,repetition,rho_um,k_sys_N_per_m[,gain_uN_per_V] "
                                           "(default for a folder: its sheet.csv)")
      ("out", po::value(&options.out)->required(), "per-curve table (CSV); - writes it to standard output (the report "
                                                   "then goes to standard error)")
      ("tubes", po::value(&options.tubes), "per-tube table (CSV): k as the mean of the tube's ok curves, their spread "
                                           "and the uncertainty; - for standard output")
      ("contact", po::value(&contact)->default_value(contact), "contact point: deviation (from the baseline) or "
                                                                 "piecewise (a hinge fitted by least squares)")
      ("window", po::value(&window)->default_value(window), "fit window: relative ([F_max - a, F_max - b]) or absolute "
                                                            "([F_low, F_high] above the baseline, from contact)")
      ("window-uN", po::value(&window_uN), "the window's two forces in uN: a,b for relative (default 4,0.5, the group's "
                                           "script), F_low,F_high for absolute (default 0.4,4, the study's "
                                           "finite-element fit)")
      ("baseline", po::value(&baseline)->default_value(baseline), "tilt (offset and slope fitted to the baseline "
                                                                  "region) or offset (its mean only)")
      ("baseline-fraction", po::value(&processing.baseline_fraction)->default_value(processing.baseline_fraction),
       "leading share of the approach taken as the baseline region (out of contact)")
      ("threshold-sigma", po::value(&processing.threshold_sigma)->default_value(processing.threshold_sigma),
       "contact threshold, in noise standard deviations of the baseline")
      ("smooth", po::value(&processing.smoothing_window)->default_value(0),
       "Savitzky-Golay window (quadratic, odd >= 5) applied after the baseline; 0: none")
      ("min-r2", po::value(&processing.minimum_r_squared)->default_value(processing.minimum_r_squared, "0.95"),
       "least R^2 of the window fit (below: poor_linearity)")
      ("min-window-samples", po::value(&minimum_samples)->default_value(minimum_samples),
       "least samples in the window (below: window_not_reached)")
      ("jump-sigma", po::value(&processing.jump_sigma)->default_value(processing.jump_sigma),
       "a force drop larger than this many noise sd is a slip, snap-in or non-monotonic curve")
      ("edge-step-uN", po::value(&edge_step_uN)->default_value(edge_step_uN, "0.1"),
       "the window edges' shift for k's window sensitivity (uN)")
      ("force", "overwrite existing outputs")
      ("quiet", po::bool_switch(&options.quiet), "no progress on standard error");
  po::positional_options_description positional;
  positional.add("curves", 1);
  po::variables_map values;
  run = parse_arguments(arguments, "curves", usage,
                        "The apparent stiffness k of every raw force-indentation curve: baseline offset and tilt "
                        "from the leading part of the approach, the contact point, optional smoothing, a straight "
                        "line fitted to force against stage position over the force window, and the sensor in "
                        "series, k = k_m k_sys / (k_sys - k_m). Each curve gets a status (ok, no_baseline, "
                        "no_contact, saturated, window_not_reached, snap_in, slip, non_monotonic, "
                        "poor_linearity, sensor_limited) with its reason, and k's uncertainty: the fit's and the "
                        "baseline tilt's standard errors and the sensitivities to the contact point and the window "
                        "edges.\n\nPer tube: the mean k of its ok curves, their spread and the mean's "
                        "uncertainty. Equations and sources: src/forcecurves/README.md.",
                        described, positional, values);
  if (!run) return options;
  if (contact != "deviation" && contact != "piecewise") throw_bad_value(command, "--contact", contact, "deviation or piecewise");
  processing.contact = contact == "deviation" ? ContactMethod::deviation : ContactMethod::piecewise;
  if (window != "relative" && window != "absolute") throw_bad_value(command, "--window", window, "relative or absolute");
  processing.window = window_of(window == "relative" ? WindowConvention::relative : WindowConvention::absolute,
                                window_uN.empty() ? (window == "relative" ? "4,0.5" : "0.4,4") : window_uN, command,
                                "--window-uN");
  if (baseline != "tilt" && baseline != "offset") throw_bad_value(command, "--baseline", baseline, "tilt or offset");
  processing.baseline_tilt = baseline == "tilt";
  if (minimum_samples < 3) throw_bad_value(command, "--min-window-samples", std::to_string(minimum_samples), "at least 3");
  processing.minimum_window_samples = static_cast<std::size_t>(minimum_samples);
  processing.edge_step_N = from_uN(edge_step_uN);
  if (const std::string reason = processing.invalid_reason(); !reason.empty()) throw InputError(std::string(command), reason);
  if (values.count("force")) options.overwrite = Overwrite::allow;
  if (is_standard_output(options.out) && is_standard_output(options.tubes)) {
    throw InputError(std::string(command), "--out and --tubes are both -: standard output takes one result");
  }
  return options;
}

std::string number(double value) { return std::isfinite(value) ? format_double(value) : std::string(); }

std::string curves_csv(const std::vector<CurveResult>& results) {
  CsvWriter writer({"curve", "tube", "repetition", "status", "reason", "k_N_per_m", "u_k_N_per_m", "u_stat_N_per_m",
                    "se_fit_N_per_m", "se_baseline_N_per_m", "sens_contact_N_per_m", "sens_window_N_per_m",
                    "k_measured_N_per_m", "r2", "contact_um", "contact_other_um", "F_max_uN", "window_low_uN",
                    "window_high_uN", "window_samples", "baseline_offset_uN", "baseline_tilt_N_per_m", "noise_uN"});
  for (const CurveResult& r : results) {
    const bool ok = r.status == CurveStatus::ok;
    const auto if_ok = [&](double value) { return ok ? number(value) : std::string(); };
    const bool contact = r.contact_index > 0 || r.contact_position_m != 0.0;
    const auto if_contact = [&](double value) { return contact ? number(value) : std::string(); };
    const bool fitted = r.window_samples > 0;
    writer.add_row({r.curve, r.tube, std::to_string(r.repetition), std::string(to_string(r.status)), r.reason,
                    if_ok(r.stiffness), if_ok(r.uncertainty), if_ok(r.uncertainty_statistical), if_ok(r.se_fit),
                    if_ok(r.se_baseline), if_ok(r.sensitivity_contact), if_ok(r.sensitivity_window),
                    fitted ? number(r.measured_stiffness) : "", fitted ? number(r.r_squared) : "",
                    if_contact(to_um(r.contact_position_m)), if_contact(to_um(r.contact_other_m)),
                    number(to_uN(r.force_max_N)), contact ? number(to_uN(r.window_low_N)) : "",
                    contact ? number(to_uN(r.window_high_N)) : "", std::to_string(r.window_samples),
                    number(to_uN(r.baseline_offset_N)), number(r.baseline_tilt_N_per_m), number(to_uN(r.noise_N))});
  }
  return writer.text();
}

std::string tubes_csv(const std::vector<TubeStiffness>& tubes) {
  CsvWriter writer({"tube", "curves", "ok", "statuses", "k_N_per_m", "spread_N_per_m", "u_spread_N_per_m",
                    "u_measurement_N_per_m", "u_k_N_per_m"});
  for (const TubeStiffness& t : tubes) {
    const auto if_ok = [&](double value) { return t.ok > 0 ? number(value) : std::string(); };
    writer.add_row({t.tube, std::to_string(t.curves), std::to_string(t.ok), t.statuses, if_ok(t.stiffness),
                    if_ok(t.spread), if_ok(t.uncertainty_spread), if_ok(t.uncertainty_measurement), if_ok(t.uncertainty)});
  }
  return writer.text();
}

std::string rounded(double value, int digits) {
  const double scale = std::pow(10.0, digits);
  return format_double(std::round(value * scale) / scale);
}

void report(const CurvesOptions& options, const std::vector<CurveResult>& results, const std::vector<TubeStiffness>& tubes,
            std::ostream& out) {
  const FitWindow& window = options.processing.window;
  const bool relative = window.convention == WindowConvention::relative;
  out << "growthuq curves: " << results.size() << " curve(s) of " << tubes.size() << " tube(s) from " << options.curves
      << "; window " << (relative ? "[F_max - " : "[") << rounded(to_uN(window.low_N), 9)
      << (relative ? " uN, F_max - " : " uN, ") << rounded(to_uN(window.high_N), 9) << " uN], contact "
      << (options.processing.contact == ContactMethod::deviation ? "deviation" : "piecewise") << "\n";
  std::map<std::string, std::size_t> counts;
  for (const CurveResult& r : results) ++counts[std::string(to_string(r.status))];
  out << "  curves:";
  for (const auto& [status, count] : counts) out << " " << status << " " << count;
  out << "\n";
  constexpr std::size_t shown = 50;
  for (std::size_t t = 0; t < tubes.size() && t < shown; ++t) {
    const TubeStiffness& tube = tubes[t];
    out << "  " << tube.tube << ": ";
    if (tube.ok > 0) {
      out << "k " << rounded(tube.stiffness, 3) << " +- " << rounded(tube.uncertainty, 3) << " N/m (spread "
          << rounded(tube.spread, 3) << ")";
    } else {
      out << "no ok curve";
    }
    out << "; " << tube.statuses << "\n";
  }
  if (tubes.size() > shown) out << "  ... " << tubes.size() - shown << " more tube(s) in the per-tube table\n";
  out << wrote(options.out) << (options.tubes.empty() ? "" : ", " + wrote(options.tubes)) << "\n";
}

}  // namespace

int run_curves(const Arguments& arguments) {
  bool run = true;
  const CurvesOptions options = parse(arguments, run);
  if (!run) return 0;
  check_result_target(options.out, options.overwrite);
  if (!options.tubes.empty()) check_result_target(options.tubes, options.overwrite);

  const std::vector<ForceCurve> curves = read_force_curves(options.curves, options.sheet);
  StepProgress progress(choose_progress_mode(options.quiet), std::cerr, "curves", "curve", curves.size());
  std::vector<CurveResult> results;
  results.reserve(curves.size());
  for (const ForceCurve& curve : curves) {
    results.push_back(process_force_curve(curve, options.processing));
    progress.advance();
  }
  progress.clear();
  const std::vector<TubeStiffness> tubes = tube_stiffness(results);

  std::vector<FileContent> outputs{{options.out, curves_csv(results)}};
  if (!options.tubes.empty()) outputs.push_back({options.tubes, tubes_csv(tubes)});
  write_results_together(outputs, options.overwrite);
  const bool to_stdout = is_standard_output(options.out) || is_standard_output(options.tubes);
  report(options, results, tubes, to_stdout ? std::cerr : std::cout);
  return 0;
}

}  // namespace growthuq::cli
