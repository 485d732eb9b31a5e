// process_force_curve: Eqs. (C1)-(C9), src/forcecurves/README.md, in the order a curve goes
// through them; a curve that fails a step stops there with its status and reason.
#include "growthuq/forcecurves/curve_processing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "contact_point.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/mechanics/instrument.hpp"
#include "line_fit.hpp"

namespace growthuq {
namespace {

// Fewer baseline samples than this give no usable noise estimate.
constexpr std::size_t minimum_baseline_samples = 10;
// This many approach samples at the recorded maximum: the reading is clipped (saturated).
constexpr std::size_t saturation_repeats = 3;

std::string uN(double force_N) { return format_double(std::round(to_uN(force_N) * 1e4) / 1e4) + " uN"; }
std::string um(double position_m) { return format_double(std::round(to_um(position_m) * 1e4) / 1e4) + " um"; }

CurveResult& fail(CurveResult& result, CurveStatus status, std::string reason) {
  result.status = status;
  result.reason = std::move(reason);
  return result;
}

// The tube's k from a measured slope (C7), or NaN when the slope is not below k_sys.
double series_corrected(double measured, double sensor_stiffness) {
  if (!(measured < sensor_stiffness)) return std::numeric_limits<double>::quiet_NaN();
  return tube_stiffness(measured, Instrument{std::numeric_limits<double>::quiet_NaN(), 0.2, sensor_stiffness});
}

// |k of a refit - k| (C9), 0 when the refit has too few samples or no series-corrected value
// (the sensitivity is then not measurable, and the curve's own fit stands).
double refit_change(const double* z, const double* y, std::size_t first, std::size_t last, double low, double high,
                    std::size_t minimum, double sensor_stiffness, double stiffness) {
  const detail::LineFit fit = detail::fit_line_where(z, y, first, last, low, high);
  if (fit.n < minimum) return 0.0;
  const double k = series_corrected(fit.slope, sensor_stiffness);
  return std::isfinite(k) ? std::abs(k - stiffness) : 0.0;
}

}  // namespace

std::string_view to_string(CurveStatus status) {
  switch (status) {
    case CurveStatus::ok: return "ok";
    case CurveStatus::no_baseline: return "no_baseline";
    case CurveStatus::no_contact: return "no_contact";
    case CurveStatus::saturated: return "saturated";
    case CurveStatus::window_not_reached: return "window_not_reached";
    case CurveStatus::snap_in: return "snap_in";
    case CurveStatus::slip: return "slip";
    case CurveStatus::non_monotonic: return "non_monotonic";
    case CurveStatus::poor_linearity: return "poor_linearity";
    case CurveStatus::sensor_limited: return "sensor_limited";
  }
  return "unknown";
}

std::string CurveProcessingOptions::invalid_reason() const {
  if (!(baseline_fraction > 0.0 && baseline_fraction < 0.9)) {
    return "--baseline-fraction = " + format_double(baseline_fraction) + ": expected a share in (0, 0.9)";
  }
  if (!(threshold_sigma > 0.0) || !std::isfinite(threshold_sigma)) {
    return "--threshold-sigma = " + format_double(threshold_sigma) + ": expected a number > 0";
  }
  if (smoothing_window != 0 && (smoothing_window < 5 || smoothing_window % 2 == 0)) {
    return "--smooth = " + std::to_string(smoothing_window) + ": expected 0 (off) or an odd window >= 5";
  }
  const bool finite = std::isfinite(window.low_N) && std::isfinite(window.high_N);
  if (window.convention == WindowConvention::absolute && !(finite && window.low_N >= 0.0 && window.high_N > window.low_N)) {
    return "--window-uN = " + format_double(to_uN(window.low_N)) + "," + format_double(to_uN(window.high_N)) +
           ": expected F_low,F_high with 0 <= F_low < F_high (uN above the baseline)";
  }
  if (window.convention == WindowConvention::relative && !(finite && window.high_N >= 0.0 && window.low_N > window.high_N)) {
    return "--window-uN = " + format_double(to_uN(window.low_N)) + "," + format_double(to_uN(window.high_N)) +
           ": expected a,b with a > b >= 0 (the window F_max - a to F_max - b, uN)";
  }
  if (minimum_window_samples < 3) return "--min-window-samples: expected at least 3";
  if (!(minimum_r_squared >= 0.0 && minimum_r_squared < 1.0)) {
    return "--min-r2 = " + format_double(minimum_r_squared) + ": expected a number in [0, 1)";
  }
  if (!(jump_sigma > 0.0) || !std::isfinite(jump_sigma)) return "--jump-sigma: expected a number > 0";
  if (!(edge_step_N >= 0.0) || !std::isfinite(edge_step_N)) return "--edge-step-uN: expected a number >= 0";
  return {};
}

CurveResult process_force_curve(const ForceCurve& curve, const CurveProcessingOptions& options) {
  CurveResult result;
  result.curve = curve.name;
  result.tube = curve.tube;
  result.repetition = curve.repetition;
  const std::size_t n = curve.approach_end;
  const double* z = curve.position.data();
  const double* raw = curve.force.data();

  // (C1) baseline from the leading, out-of-contact share of the approach.
  const auto baseline_end = static_cast<std::size_t>(options.baseline_fraction * static_cast<double>(n));
  if (baseline_end < minimum_baseline_samples) {
    return fail(result, CurveStatus::no_baseline,
                "baseline region of " + std::to_string(baseline_end) + " samples: expected at least " +
                    std::to_string(minimum_baseline_samples) + " (a longer approach or a larger --baseline-fraction)");
  }
  const double inf = std::numeric_limits<double>::infinity();
  const detail::LineFit baseline = detail::fit_line_where(z, raw, 0, baseline_end - 1, -inf, inf);
  double se_tilt = 0.0;
  if (options.baseline_tilt) {
    result.baseline_offset_N = baseline.intercept;
    result.baseline_tilt_N_per_m = baseline.slope;
    result.noise_N = std::sqrt(baseline.sse / static_cast<double>(baseline.n - 2));
    se_tilt = baseline.slope_se();
  } else {
    double sum = 0.0;
    for (std::size_t i = 0; i < baseline_end; ++i) sum += raw[i];
    result.baseline_offset_N = sum / static_cast<double>(baseline_end);
    double squares = 0.0;
    for (std::size_t i = 0; i < baseline_end; ++i) squares += (raw[i] - result.baseline_offset_N) * (raw[i] - result.baseline_offset_N);
    result.noise_N = std::sqrt(squares / static_cast<double>(baseline_end - 1));
  }

  // (C2) saturation: a clipped reading repeats the sensor's maximum.
  const double raw_max = *std::max_element(raw, raw + n);
  if (std::count(raw, raw + n, raw_max) >= static_cast<long>(saturation_repeats)) {
    return fail(result, CurveStatus::saturated,
                std::to_string(std::count(raw, raw + n, raw_max)) + " samples at the recorded maximum " + uN(raw_max) +
                    ": the sensor's reading is clipped");
  }

  std::vector<double> corrected(n);
  for (std::size_t i = 0; i < n; ++i) {
    corrected[i] = raw[i] - (result.baseline_offset_N + result.baseline_tilt_N_per_m * z[i]);
  }
  // (C5) optional smoothing of the corrected force; contact and fit use the smoothed force.
  std::vector<double> smoothed;
  if (options.smoothing_window > 0) {
    smoothed.resize(n);
    savitzky_golay_quadratic(corrected.data(), smoothed.data(), n, options.smoothing_window);
  }
  const double* y = smoothed.empty() ? corrected.data() : smoothed.data();

  const std::size_t peak = static_cast<std::size_t>(std::max_element(y + baseline_end, y + n) - y);
  result.force_max_N = y[peak];
  // A noiseless record has sd 0: the threshold then sits just above rounding.
  const double rounding = 64.0 * std::numeric_limits<double>::epsilon() * std::abs(raw_max);
  const double threshold = std::max(options.threshold_sigma * result.noise_N, rounding);
  if (!(result.force_max_N > threshold)) {
    return fail(result, CurveStatus::no_contact,
                "maximum force " + uN(result.force_max_N) + " above the baseline: not above the contact threshold " +
                    uN(threshold) + " (" + format_double(options.threshold_sigma) + " noise sd)");
  }

  // (C3), (C4) contact point by both methods; the chosen one bounds the window, the other gives
  // the contact sensitivity.
  const std::size_t by_deviation = detail::deviation_contact(y, peak, threshold, rounding);
  const std::size_t by_piecewise = detail::piecewise_contact(z, y, peak);
  const bool deviation = options.contact == ContactMethod::deviation;
  const std::size_t contact = deviation ? by_deviation : by_piecewise;
  const std::size_t other = deviation ? by_piecewise : by_deviation;
  result.contact_index = contact;
  result.contact_position_m = z[contact];
  result.contact_other_m = z[other];
  if (contact < baseline_end) {
    return fail(result, CurveStatus::no_baseline,
                "contact at z = " + um(z[contact]) + " (sample " + std::to_string(contact) +
                    ") lies inside the baseline region (the first " + std::to_string(baseline_end) +
                    " samples): a smaller --baseline-fraction");
  }

  // (C2) jumps: an attraction before contact (snap-in), a drop in contact (slip).
  const double jump = options.jump_sigma * result.noise_N;
  for (std::size_t i = baseline_end; i < contact; ++i) {
    if (y[i] < -std::max(jump, threshold)) {
      return fail(result, CurveStatus::snap_in,
                  "force " + uN(y[i]) + " below the baseline at z = " + um(z[i]) + ", before contact: an attractive jump");
    }
  }
  const double step_jump = std::max(jump * std::sqrt(2.0), threshold);
  for (std::size_t i = contact; i < peak; ++i) {
    if (y[i + 1] - y[i] < -step_jump) {
      return fail(result, CurveStatus::slip,
                  "force drops by " + uN(y[i] - y[i + 1]) + " between z = " + um(z[i]) + " and " + um(z[i + 1]) +
                      " in contact (more than " + format_double(options.jump_sigma) + " noise sd)");
    }
  }

  // (C6) the window, in forces above the baseline.
  const FitWindow& window = options.window;
  const bool relative = window.convention == WindowConvention::relative;
  result.window_low_N = relative ? result.force_max_N - window.low_N : window.low_N;
  result.window_high_N = relative ? result.force_max_N - window.high_N : window.high_N;
  if (relative && !(result.window_low_N > threshold)) {
    return fail(result, CurveStatus::window_not_reached,
                "maximum force " + uN(result.force_max_N) + ": the window's lower edge F_max - " + uN(window.low_N) +
                    " is not above the contact threshold " + uN(threshold));
  }
  if (!relative && result.force_max_N < result.window_high_N) {
    return fail(result, CurveStatus::window_not_reached,
                "maximum force " + uN(result.force_max_N) + " is below the window's upper edge " + uN(result.window_high_N));
  }
  double running_max = -inf;
  for (std::size_t i = contact; i <= peak; ++i) {
    if (running_max == -inf && y[i] < result.window_low_N) continue;
    running_max = std::max(running_max, y[i]);
    if (running_max - y[i] > std::max(jump, threshold)) {
      return fail(result, CurveStatus::non_monotonic,
                  "force falls " + uN(running_max - y[i]) + " below its running maximum at z = " + um(z[i]) +
                      " in the window");
    }
  }

  const detail::LineFit fit =
      detail::fit_line_where(z, y, contact, peak, result.window_low_N, result.window_high_N);
  result.window_samples = fit.n;
  if (fit.n < options.minimum_window_samples) {
    return fail(result, CurveStatus::window_not_reached,
                std::to_string(fit.n) + " samples in the window [" + uN(result.window_low_N) + ", " +
                    uN(result.window_high_N) + "]: expected at least " + std::to_string(options.minimum_window_samples));
  }
  result.measured_stiffness = fit.slope;
  result.fit_intercept_N = fit.intercept;
  result.r_squared = fit.r_squared();
  if (!(fit.slope > 0.0)) {
    return fail(result, CurveStatus::non_monotonic, "the window's slope " + format_double(fit.slope) + " N/m is not positive");
  }
  if (result.r_squared < options.minimum_r_squared) {
    return fail(result, CurveStatus::poor_linearity,
                "R^2 " + format_double(std::round(result.r_squared * 1e4) / 1e4) + " of the window fit: expected at least " +
                    format_double(options.minimum_r_squared));
  }

  // (C7) the sensor in series.
  const double k_sys = curve.sensor_stiffness_N_per_m;
  result.stiffness = series_corrected(fit.slope, k_sys);
  if (!std::isfinite(result.stiffness)) {
    result.stiffness = 0.0;
    return fail(result, CurveStatus::sensor_limited,
                "measured slope " + format_double(fit.slope) + " N/m is not below the sensor stiffness " +
                    format_double(k_sys) + " N/m");
  }

  // (C8) standard errors through dk/dk_m = (k_sys / (k_sys - k_m))^2 = (k / k_m)^2.
  const double gain = (result.stiffness / fit.slope) * (result.stiffness / fit.slope);
  result.se_fit = gain * fit.slope_se();
  result.se_baseline = gain * se_tilt;
  result.uncertainty_statistical = std::hypot(result.se_fit, result.se_baseline);

  // (C9) sensitivities: the other method's contact, each window edge moved by +- edge_step.
  const std::size_t minimum = options.minimum_window_samples;
  result.sensitivity_contact = refit_change(z, y, std::max(other, baseline_end), peak, result.window_low_N,
                                            result.window_high_N, minimum, k_sys, result.stiffness);
  const double step = options.edge_step_N;
  for (const double shift : {-step, step}) {
    result.sensitivity_window = std::max(
        {result.sensitivity_window,
         refit_change(z, y, contact, peak, result.window_low_N + shift, result.window_high_N, minimum, k_sys, result.stiffness),
         refit_change(z, y, contact, peak, result.window_low_N, result.window_high_N + shift, minimum, k_sys, result.stiffness)});
  }
  result.uncertainty = std::sqrt(result.se_fit * result.se_fit + result.se_baseline * result.se_baseline +
                                 result.sensitivity_contact * result.sensitivity_contact +
                                 result.sensitivity_window * result.sensitivity_window);
  return result;
}

}  // namespace growthuq
