#include "growthuq/relaxation/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/relaxation/modulus.hpp"
#include "growthuq/relaxation/prony_fit.hpp"
#include "growthuq/relaxation/viscosity.hpp"

namespace growthuq {
namespace {

double median_interval(std::span<const double> t) {
  std::vector<double> intervals;
  for (std::size_t i = 1; i < t.size(); ++i) intervals.push_back(t[i] - t[i - 1]);
  std::nth_element(intervals.begin(), intervals.begin() + static_cast<std::ptrdiff_t>(intervals.size() / 2), intervals.end());
  return intervals[intervals.size() / 2];
}

void fail(CurveFit& result, std::string reason) {
  result.ok = false;
  result.extrapolated = false;
  result.reason = std::move(reason);
}

// The taus' search range: from the median sampling interval to longest_tau_in_records hold
// lengths; a tau_slow at or beyond the hold is extrapolated.
PronyFitOptions search_options(const RelaxationCurve& curve, const RelaxationOptions& options, std::size_t peak) {
  PronyFitOptions fit_options;
  fit_options.terms = options.terms;
  fit_options.tau_min = median_interval(curve.t);
  fit_options.record_length = curve.t.back() - curve.t[peak];
  fit_options.tau_max = longest_tau_in_records * fit_options.record_length;
  return fit_options;
}

// E0 and eta by the one definition every path uses (Eq. (R7); relaxation/viscosity.hpp, Eq. (G1)):
// the modulus that relaxes, E_r(0) - E_inf = (1 - e_inf) E_r(0), times the slow time.
void derive_viscosity(CurveFit& result) {
  result.relaxing_modulus = (1.0 - result.einf) * result.modulus0;
  result.viscosity = relaxation_viscosity(result.tau.back(), result.einf, result.modulus0);
}

// Step fit: E_r(t) / E_r(0) over the hold as if the indentation had been a step at the force
// maximum; hold samples earlier than drop_ramp_multiple x ramp time are left out of the fit.
void fit_step(const RelaxationCurve& curve, const RelaxationOptions& options, std::size_t peak,
              const ShellGeometry& shell, CurveFit& result) {
  std::vector<double> t, y;
  result.modulus0 = relaxation_modulus(curve.force[peak] / curve.indentation, shell);
  const double start = options.drop_ramp_multiple * result.ramp_time;
  for (std::size_t i = peak; i < curve.t.size(); ++i) {
    const double since_peak = curve.t[i] - curve.t[peak];
    if (since_peak < start) continue;
    t.push_back(since_peak);
    y.push_back(relaxation_modulus(curve.force[i] / curve.indentation, shell) / result.modulus0);
  }
  if (!std::isfinite(result.modulus0) || !std::all_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); })) {
    return fail(result, "the apparent modulus E_r(t) is not finite for this p, d, h, rho");
  }
  const std::size_t needed = std::max<std::size_t>(10, 2 * static_cast<std::size_t>(options.terms) + 2);
  if (t.size() < needed) {
    return fail(result, std::to_string(t.size()) + " hold samples after t >= " + format_double(start) +
                            " s (" + format_double(options.drop_ramp_multiple) + " x ramp time " +
                            format_double(result.ramp_time) + " s): expected at least " + std::to_string(needed));
  }
  PronyFitOptions fit_options = search_options(curve, options, peak);
  fit_options.profile_slowest = true;
  const PronyFit fit = fit_prony(t, y, fit_options);
  result.points = fit.points;
  result.tau = fit.tau;
  result.amplitude = fit.amplitude;
  result.einf = fit.einf;
  derive_viscosity(result);
  result.rms = fit.rms;
  result.aic = fit.aic;
  result.tau_slow_relative_se = fit.tau_relative_se.back();
  result.tau_slow_low = fit.tau_slow_low;
  result.tau_slow_high = fit.tau_slow_high;
  result.extrapolated = fit.extrapolated;
  if (!fit.ok) return fail(result, fit.reason);
  // e_inf >= 0 is a constraint of the fit; at 0 it is active, and a slow phase longer than the
  // record has taken what the record cannot tell from the equilibrium modulus.
  if (!(fit.einf > 0.0)) {
    return fail(result, "E_inf/E_r(0) = 0, at its bound: the record does not separate the equilibrium modulus from the "
                        "slow phase (tau_slow = " + format_double(std::round(fit.tau.back() * 1e3) / 1e3) + " s)");
  }
  if (fit.extrapolated) {
    result.reason = "tau_slow = " + format_double(std::round(fit.tau.back() * 1e3) / 1e3) + " s is beyond the hold of " +
                    format_double(std::round(fit_options.record_length * 1e3) / 1e3) + " s: extrapolated";
  }
  if (!fit.note.empty()) result.reason += (result.reason.empty() ? "" : "; ") + fit.note;
}

// Ramp-aware fit, in two steps. (1) The simulated ramp (linear from 0 at the first sample to
// delta at a fitted time next to the force maximum) and hold of a generalized Maxwell spring is fitted to F(t):
// this removes the ramp in force space, where the superposition it relies on holds. (2) The
// fitted step response k(t) = k_inf + sum_i k_i exp(-t / tau_i), sampled like the hold, is
// mapped to E_r(t) / E_r(0) and fitted like a measured step. E_r(k) is nonlinear (close to
// E ~ k^2 at physiological x = rho/alpha), so the moduli's taus are not the springs' taus.
void fit_ramp(const RelaxationCurve& curve, const RelaxationOptions& options, std::size_t peak,
              const ShellGeometry& shell, CurveFit& result) {
  std::vector<double> t;
  for (double time : curve.t) t.push_back(time - curve.t.front());
  const PronyFitOptions fit_options = search_options(curve, options, peak);
  // The ramp ends between the samples either side of the force maximum.
  const double before = peak > 0 ? t[peak - 1] : 0.0;
  const double after = peak + 1 < t.size() ? t[peak + 1] : t[peak];
  const PronyFit springs = fit_ramp_hold(t, curve.force, before, after, curve.indentation, fit_options);
  result.ramp_time = springs.ramp_time;
  result.rms = springs.rms / curve.force[peak];
  result.springs = MaxwellModel{springs.einf, springs.amplitude, springs.tau};
  if (!springs.ok) return fail(result, "ramp and hold: " + springs.reason);

  std::vector<double> hold_t, y;
  for (std::size_t i = peak; i < curve.t.size(); ++i) {
    const double since_peak = curve.t[i] - curve.t[peak];
    double k = springs.einf;
    for (std::size_t m = 0; m < springs.tau.size(); ++m) k += springs.amplitude[m] * std::exp(-since_peak / springs.tau[m]);
    hold_t.push_back(since_peak);
    y.push_back(relaxation_modulus(k, shell));
  }
  result.modulus0 = y.front();
  for (double& value : y) value /= result.modulus0;
  if (!std::all_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); })) {
    return fail(result, "the apparent modulus E_r(t) is not finite for this p, d, h, rho");
  }
  const PronyFit moduli = fit_prony(hold_t, y, fit_options);
  result.points = springs.points;
  result.tau = moduli.tau;
  result.amplitude = moduli.amplitude;
  result.einf = moduli.einf;
  derive_viscosity(result);
  result.tau_slow_relative_se = springs.tau_relative_se.back();
  result.aic = springs.aic;
  result.extrapolated = moduli.extrapolated;
  if (!moduli.ok) fail(result, "step response in E_r: " + moduli.reason);
}

}  // namespace

std::string_view fit_status(const CurveFit& fit) {
  if (!fit.ok) return "fit_failed";
  return fit.extrapolated ? "extrapolated" : "ok";
}

CurveFit analyze_relaxation_curve(const RelaxationCurve& curve, const RelaxationOptions& options) {
  CurveFit result;
  result.curve = curve.name;
  result.ok = true;
  const auto peak = static_cast<std::size_t>(std::max_element(curve.force.begin(), curve.force.end()) - curve.force.begin());
  result.ramp_time = curve.t[peak] - curve.t.front();
  const std::size_t hold = curve.t.size() - peak;
  const std::size_t needed = std::max<std::size_t>(10, 2 * static_cast<std::size_t>(options.terms) + 2);
  if (hold < needed) {
    fail(result, "the force maximum is " + std::to_string(hold - 1) +
                     " samples before the end: expected a hold of at least " + std::to_string(needed) + " samples");
    return result;
  }
  const ShellGeometry shell{curve.turgor, curve.diameter, curve.thickness, {curve.probe_radius_m, options.poisson_ratio}};
  try {
    if (options.ramp_aware) {
      fit_ramp(curve, options, peak, shell, result);
    } else {
      fit_step(curve, options, peak, shell, result);
    }
  } catch (const std::exception& error) {  // InputError from the fit's own checks, CVODE failures
    fail(result, error.what());
  }
  return result;
}

std::vector<double> fitted_force(const RelaxationCurve& curve, const CurveFit& fit, double poisson_ratio) {
  std::vector<double> force(curve.t.size(), std::numeric_limits<double>::quiet_NaN());
  if (curve.t.empty()) return force;
  if (!fit.springs.tau.empty()) {
    std::vector<double> since_contact;
    for (const double time : curve.t) since_contact.push_back(time - curve.t.front());
    const Eigen::MatrixXd basis = maxwell_mode_responses(fit.springs.tau, fit.ramp_time, curve.indentation, since_contact);
    Eigen::VectorXd stiffness(basis.cols());
    stiffness(0) = fit.springs.k_inf;
    for (std::size_t i = 0; i < fit.springs.k.size(); ++i) stiffness(static_cast<Eigen::Index>(i + 1)) = fit.springs.k[i];
    const Eigen::VectorXd model = basis * stiffness;
    for (std::size_t i = 0; i < force.size(); ++i) force[i] = model(static_cast<Eigen::Index>(i));
    return force;
  }
  if (fit.tau.empty() || fit.amplitude.size() != fit.tau.size() || !(fit.modulus0 > 0.0)) return force;
  const auto peak = static_cast<std::size_t>(std::max_element(curve.force.begin(), curve.force.end()) - curve.force.begin());
  const ShellGeometry shell{curve.turgor, curve.diameter, curve.thickness, {curve.probe_radius_m, poisson_ratio}};
  for (std::size_t i = peak; i < curve.t.size(); ++i) {
    const double since_peak = curve.t[i] - curve.t[peak];
    double relative = fit.einf;
    for (std::size_t m = 0; m < fit.tau.size(); ++m) relative += fit.amplitude[m] * std::exp(-since_peak / fit.tau[m]);
    force[i] = curve.indentation * relaxation_stiffness(fit.modulus0 * relative, shell);
  }
  return force;
}

}  // namespace growthuq
