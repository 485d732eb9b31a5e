// From one raw force-indentation curve to the tube's apparent stiffness k with its uncertainty:
// baseline offset and tilt, contact point, optional Savitzky-Golay smoothing, a linear fit over a
// force window, the sensor in series, and a status with a reason. Each step's equation and
// source: src/forcecurves/README.md, Eqs. (C1)-(C9).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "growthuq/forcecurves/force_curve.hpp"

namespace growthuq {

enum class ContactMethod { deviation, piecewise };
enum class WindowConvention { absolute, relative };

// The force window of the fit (Eq. (C6)), forces above the baseline in N. absolute: [low, high]
// from contact (the study's finite-element fit: 0.4 uN up to the target force). relative:
// [F_max - low, F_max - high] (the group's script: a = 4 uN, b = 0.5 uN), so low > high there.
struct FitWindow {
  WindowConvention convention = WindowConvention::relative;
  double low_N = 4e-6;
  double high_N = 0.5e-6;
};

struct CurveProcessingOptions {
  double baseline_fraction = 0.25;     // leading share of the approach taken as out of contact (C1)
  bool baseline_tilt = true;           // fit offset and tilt; false: offset only (the group's script)
  ContactMethod contact = ContactMethod::deviation;
  double threshold_sigma = 5.0;        // contact threshold in baseline noise sd (C3)
  int smoothing_window = 0;            // Savitzky-Golay window (odd, >= 5); 0: no smoothing (C5)
  FitWindow window;
  std::size_t minimum_window_samples = 10;
  double minimum_r_squared = 0.95;     // below: poor_linearity
  double jump_sigma = 8.0;             // a drop larger than this many noise sd: slip, snap-in, non-monotonic
  double edge_step_N = 0.1e-6;         // window edges moved by this for the window sensitivity (C9)

  // Empty when valid, else what is wrong ("--baseline-fraction = 0.9: expected ...").
  std::string invalid_reason() const;
};

enum class CurveStatus {
  ok,
  no_baseline,          // the baseline region is too short or the contact lies inside it
  no_contact,           // the force never leaves the baseline noise
  saturated,            // the sensor's reading is clipped at its maximum
  window_not_reached,   // the curve's force does not span the fit window
  snap_in,              // an attractive jump before contact
  slip,                 // a sudden drop of force in contact
  non_monotonic,        // the force falls back in the window
  poor_linearity,       // R^2 of the window fit below the minimum
  sensor_limited,       // measured slope >= k_sys: the series correction has no answer
};
std::string_view to_string(CurveStatus status);

struct CurveResult {
  std::string curve, tube;
  int repetition = 0;
  CurveStatus status = CurveStatus::ok;
  std::string reason;                  // empty for ok
  // Baseline (C1), N and N/m, and the noise sd of its residuals (N).
  double baseline_offset_N = 0.0, baseline_tilt_N_per_m = 0.0, noise_N = 0.0;
  // Contact (C3/C4): sample index and stage position (m), and the other method's position.
  std::size_t contact_index = 0;
  double contact_position_m = 0.0, contact_other_m = 0.0;
  double force_max_N = 0.0;            // above the baseline
  double window_low_N = 0.0, window_high_N = 0.0;  // the window's forces above the baseline
  std::size_t window_samples = 0;
  double measured_stiffness = 0.0;     // k_m, slope of force against stage position (N/m)
  double fit_intercept_N = 0.0;        // the window line's force above the baseline at z = 0:
                                       // F - baseline = fit_intercept_N + k_m z (for figures)
  double r_squared = 0.0;
  // The tube's stiffness (C7) and its uncertainty (C8, C9), all N/m.
  double stiffness = 0.0;
  double se_fit = 0.0;                 // the window fit's standard error, through C7
  double se_baseline = 0.0;            // the baseline tilt's standard error, through C7
  double sensitivity_contact = 0.0;    // |k(other method's contact) - k|
  double sensitivity_window = 0.0;     // max |k(edge +- edge_step) - k|
  double uncertainty_statistical = 0.0;  // sqrt(se_fit^2 + se_baseline^2)
  double uncertainty = 0.0;            // the four in quadrature
};

// Processes the approach of `curve`. Never throws for a bad curve: it gets a status and a reason
// (numbers of a failed curve are those computed before it failed, zero otherwise).
CurveResult process_force_curve(const ForceCurve& curve, const CurveProcessingOptions& options);

// Savitzky-Golay smoothing with a quadratic over `window` samples (odd, >= 5; Eq. (C5)); the
// first and last (window - 1) / 2 samples are kept as they are.
void savitzky_golay_quadratic(const double* in, double* out, std::size_t n, int window);

}  // namespace growthuq
