#include "modulus_from_curve.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "core/gsl_errors.hpp"
#include "force_window.hpp"

namespace growthuq::fe {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

struct Problem {
  std::span<const double> depth, force;
  double stiffness, d0, low, high;
};

// k(E)/k_measured - 1 at E = exp(log_young).
double relative_mismatch(double log_young, void* parameters) {
  const auto& problem = *static_cast<const Problem*>(parameters);
  const double k = curve_stiffness(problem.depth, problem.force, std::exp(log_young), problem.d0, problem.low, problem.high);
  return k / problem.stiffness - 1.0;
}

}  // namespace

double curve_stiffness(std::span<const double> depth, std::span<const double> force, double young, double d0,
                       double window_low, double window_high) {
  const double scale = young * d0 * d0;  // F = E d0^2 G
  const WindowFit fit = fit_force_window(depth, force, window_low / scale, window_high / scale);
  if (fit.status != WindowFitStatus::ok) return nan;
  // dF/d(delta) = E d0^2 dG / (d0 d(delta/d0)) = E d0 dG/d(delta/d0).
  return young * d0 * fit.slope;
}

ModulusMatch match_modulus(std::span<const double> depth, std::span<const double> force, double stiffness, double d0,
                           double window_low, double window_high, double estimate) {
  ModulusMatch match;
  if (depth.size() < 2 || depth.size() != force.size() || !(stiffness > 0 && std::isfinite(stiffness)) ||
      !(d0 > 0 && std::isfinite(d0)) || !(window_high > window_low && window_low >= 0) ||
      !(estimate > 0 && std::isfinite(estimate))) {
    match.status = ModulusMatchStatus::invalid_input;
    return match;
  }
  const double largest = *std::max_element(force.begin(), force.end());
  if (!(largest > 0)) {
    match.status = ModulusMatchStatus::no_root;
    return match;
  }
  // The window's top lies on the curve for E >= least_young (a hair above, so that the top is
  // strictly inside despite rounding).
  match.least_young = window_high / (d0 * d0 * largest) * (1.0 + 1e-12);
  Problem problem{depth, force, stiffness, d0, window_low, window_high};

  // Bracket on ln E: k(E) grows with E (the window slides down the curve but the slope is
  // multiplied by E; for large E it tends to E d0 G'(0)). Expand by factors of 2 from the
  // estimate; below least_young the curve cannot serve the window.
  double lower = std::log(std::max(estimate, match.least_young));
  double f_lower = relative_mismatch(lower, &problem);
  double upper = lower, f_upper = f_lower;
  constexpr int max_expansions = 80;  // 2^80: any E a double curve can serve
  constexpr double step = 0.6931471805599453;
  int expansions = 0;
  if (f_lower < 0) {
    while (f_upper < 0 && expansions++ < max_expansions) {
      lower = upper;
      f_lower = f_upper;
      upper += step;
      f_upper = relative_mismatch(upper, &problem);
    }
    if (!(f_upper >= 0)) {
      match.status = ModulusMatchStatus::no_root;
      return match;
    }
  } else {
    const double floor = std::log(match.least_young);
    while (f_lower > 0 && expansions++ < max_expansions) {
      if (lower <= floor) {
        match.status = ModulusMatchStatus::curve_too_short;  // needs an E below least_young
        return match;
      }
      upper = lower;
      f_upper = f_lower;
      lower = std::max(lower - step, floor);
      f_lower = relative_mismatch(lower, &problem);
    }
    if (!(f_lower <= 0)) {
      match.status = ModulusMatchStatus::no_root;
      return match;
    }
  }
  if (f_lower == 0 || f_upper == 0) {
    match.young = std::exp(f_lower == 0 ? lower : upper);
  } else {
    detail::gsl_errors_return();  // a NaN inside the bracket is a status, not an abort
    gsl_function function{&relative_mismatch, &problem};
    const std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
        gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
    gsl_root_fsolver_set(solver.get(), &function, lower, upper);
    int status = GSL_CONTINUE;
    while (status == GSL_CONTINUE && match.iterations < 200) {
      ++match.iterations;
      if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS) break;
      // Width 1e-10 in ln E = relative 1e-10 in E.
      status = gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()), gsl_root_fsolver_x_upper(solver.get()),
                                      1e-10, 0.0);
    }
    if (status != GSL_SUCCESS) {
      match.status = ModulusMatchStatus::no_root;
      return match;
    }
    match.young = std::exp(gsl_root_fsolver_root(solver.get()));
  }
  match.fitted_stiffness = curve_stiffness(depth, force, match.young, d0, window_low, window_high);
  return match;
}

}  // namespace growthuq::fe
