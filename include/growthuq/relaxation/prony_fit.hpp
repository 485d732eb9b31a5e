// Generalized Maxwell (Prony) series fitted to a relaxation curve by variable projection
// (Golub and Pereyra 1973): the relaxation times are the only nonlinear unknowns, the
// amplitudes follow from non-negative least squares for every trial set of times.
#pragma once

#include <limits>
#include <span>
#include <string>
#include <vector>

namespace growthuq {

struct PronyFitOptions {
  int terms = 2;                  // 1, 2 or 3 exponentials
  double tau_min = 0.0;           // lower bound of every tau (s): the sampling interval
  double tau_max = 0.0;           // upper bound (s): the record length, or a multiple of it
  double record_length = 0.0;     // > 0: a slowest tau at or beyond this (s) is `extrapolated`
  bool profile_slowest = false;   // 95 % profile-likelihood interval of the slowest tau, which
                                  // then replaces max_relative_se as its test of being determined
  double min_separation = 1.2;    // tau_{i+1} / tau_i below this: ill-conditioned, fit_failed
  double bound_margin = 0.02;     // a tau within 2 % of a bound counts as "at the bound"
  double max_relative_se = 0.25;  // a tau whose standard error exceeds 25 % is undetermined
};

// Why a fit is not usable: the first problem found, in this order of checks.
struct PronyFit {
  bool ok = false;
  std::string reason;              // empty when ok
  std::string note;                // ok or not: what the fit could not bound (an open interval)
  double einf = 0.0;               // constant term (E_inf / E_r(0) for a normalized curve)
  std::vector<double> tau;         // ordered, fastest first (s)
  std::vector<double> amplitude;   // of each exp(-t / tau_i), same order
  std::vector<double> tau_relative_se;  // linearized standard error of each tau / tau
  bool extrapolated = false;       // ok, and the slowest tau is at or beyond options.record_length
  double tau_slow_low = std::numeric_limits<double>::quiet_NaN();   // profile_slowest: the 95 %
  double tau_slow_high = std::numeric_limits<double>::quiet_NaN();  // interval of the slowest tau (s)
  double rms = 0.0;                // root mean square residual
  double aic = 0.0;                // n ln(RSS / n) + 2 (2 terms + 1), to compare 1, 2, 3 terms
  std::size_t points = 0;
  double ramp_time = 0.0;          // fit_ramp_hold only: the fitted end of the ramp (s)
};

// Fits y(t) = einf + sum_i a_i exp(-t / tau_i), einf, a_i >= 0, tau_min <= tau_1 < ... <=
// tau_max. The ordered, bounded times are reparametrized without constraints (see the .cpp)
// and the projected residual is minimized by GSL's Nelder-Mead simplex from several starts.
// profile_slowest: the interval is {tau : n ln(RSS_profile(tau) / RSS_min) <= 3.84}, RSS_profile
// minimized over the other taus (amplitudes by NNLS) at each fixed slowest tau (Eq. (R6b),
// src/relaxation/README.md). An interval that reaches the faster taus makes the fit not ok;
// one that reaches tau_max is open above (tau_slow_high = tau_max, and `note` says so).
// InputError for inconsistent options or data (sizes, fewer than 2 terms + 2 points, bounds).
PronyFit fit_prony(std::span<const double> t, std::span<const double> y,
                   const PronyFitOptions& options);

// The ramp-aware fit: the same search, but the basis is the simulated ramp-and-hold response
// of each Maxwell mode (maxwell_mode_responses), so force = k_inf u(t) + sum_i k_i F_i(t) is
// fitted over the ramp (u from 0 at t = 0 to `indentation`) and the hold. The ramp's end is
// a further unknown in [ramp_time_min, ramp_time_max]: sampled data only bracket it. On return
// einf is k_inf and amplitude[i] is k_i (N/m) when `force` is in N (rms in its units).
// Times are from contact: increasing, >= 0 (InputError otherwise). A ramp that ends by the
// first sample t_1 > 0 (no sample inside it: fast ramps) fits equally well for every end in
// [ramp_time_min, t_1]; the taus and k_inf do not depend on which, each k_i by a factor of at
// most (tau_i / t_1)(exp(t_1 / tau_i) - 1) ~ 1 + t_1 / (2 tau_i). Such a fit reports the
// middle of [ramp_time_min, min(ramp_time_max, t_1)] as ramp_time and the k_i for it; the
// bounds [0, 0] are the step response fitted to the samples after contact (fit_prony's model).
PronyFit fit_ramp_hold(std::span<const double> t, std::span<const double> force, double ramp_time_min,
                       double ramp_time_max, double indentation, const PronyFitOptions& options);

}  // namespace growthuq
