// From one measured force-relaxation curve to the wall's relaxation parameters: locate the
// hold, map k(t) = F(t) / delta to E_r(t), fit the Prony series (step or ramp-aware) and
// derive E0 = (1 - e_inf) E_r(0) and the viscosity eta = tau_slow E0, the campaigns' eta = tau
// (1 - e_inf) E at E = E_r(0) (Eqs. (R1)-(R7), src/relaxation/README.md).
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "growthuq/relaxation/curves.hpp"
#include "growthuq/relaxation/simulator.hpp"

namespace growthuq {

// The longest relaxation time a fit may report, in hold lengths. Over a hold of length T a slower
// exponential differs from a straight line by less than (T / tau)^2 / 8 of its amplitude (0.1 %
// at 10 T, below a 0.2 % force noise), so the curve holds nothing that tells a tau beyond 10 T
// from a longer one; the wild type's tau_slow reaches 3.4 x the published 5 s hold at its 99th
// percentile (17 s), well inside.
inline constexpr double longest_tau_in_records = 10.0;

struct RelaxationOptions {
  int terms = 2;                    // exponentials in the Prony series: 1, 2 or 3
  double poisson_ratio = 0.2;       // nu of the wall: the instrument's (mechanics/instrument.hpp)
  bool ramp_aware = false;          // fit the ramp and the hold with the simulator
  double drop_ramp_multiple = 0.0;  // step fit only: ignore hold samples with t < this x ramp time
};

struct CurveFit {
  std::string curve;
  bool ok = false;
  bool extrapolated = false;      // ok, with tau_slow at or beyond the hold length (status
                                  // `extrapolated`): reported and used, its interval says how well
  std::string reason;             // why not ok; for an ok fit, what it extrapolates or leaves open
  std::vector<double> tau;        // s, fastest first
  std::vector<double> amplitude;  // of each exp(-t / tau_i) in E_r(t) / E_r(0), same order
  double einf = 0.0;              // E_inf / E_r(0)
  double modulus0 = 0.0;          // E_r(0) (Pa): first sample of the hold (step fit) or the
                                  // instantaneous modulus of the fitted springs (ramp-aware)
  double relaxing_modulus = 0.0;  // E0 = E_r(0) - E_inf = (1 - e_inf) E_r(0) (Pa): what relaxes
  double viscosity = 0.0;         // eta = tau_slow E0 (Pa s), relaxation/viscosity.hpp's formula
  double tau_slow_relative_se = 0.0;  // linearized standard error of tau_slow / tau_slow (for
                                      // the ramp-aware fit: of the springs' slow time)
  double tau_slow_low = std::numeric_limits<double>::quiet_NaN();   // step fit: 95 % profile-
  double tau_slow_high = std::numeric_limits<double>::quiet_NaN();  // likelihood interval of tau_slow (s)
  double rms = 0.0;               // residual of the data: of E_r / E_r(0) (step), F / F_peak (ramp-aware)
  double aic = 0.0;
  double ramp_time = 0.0;         // s: first sample to force maximum (step), fitted (ramp-aware)
  std::size_t points = 0;         // samples fitted
  MaxwellModel springs;           // ramp-aware only: the contact fitted to the force (k_inf, k_i
                                  // in N/m, tau_i in s), its ramp ending at ramp_time
};

// "ok", "extrapolated" (ok, tau_slow at or beyond the hold) or "fit_failed": the status column
// of `growthuq relax` and of a campaign's relaxation fits.
std::string_view fit_status(const CurveFit& fit);

// Hold = samples from the force maximum on (t = 0 there, E_r(0) its modulus); ramp time =
// time of the maximum minus time of the first sample. Step fit: Prony series on E_r / E_r(0)
// over t >= drop_ramp_multiple x ramp time; taus bounded by [median sampling interval, hold
// length x longest_tau_in_records]; tau_slow gets its profile interval, which decides whether the
// data determine it (not its linearized standard error). Ramp-aware fit: simulator basis on F over ramp and hold. Never throws for
// bad data: a failed or ill-conditioned fit comes back with ok = false and a reason.
// Ramp-aware: the springs fitted to the force are turned into a step response k(t), mapped to
// E_r(t) / E_r(0) and fitted like a step (see the .cpp), so both fits report the same quantity.
CurveFit analyze_relaxation_curve(const RelaxationCurve& curve, const RelaxationOptions& options);

// The fitted model as a force at every sample of `curve` (N), for plotting a fit over its
// data. Step fit: from the force maximum on, F = delta k(E_r(0) [e_inf + sum_i a_i
// exp(-(t - t_peak) / tau_i)]) with k(E_r) the forward Arnoldi relation at the curve's p, d,
// h, rho (relaxation_stiffness); NaN before the maximum, which the step fit does not model.
// Ramp-aware fit: the fitted springs' ramp-and-hold force at every sample. All NaN for a fit
// without parameters (e.g. a hold too short to fit).
std::vector<double> fitted_force(const RelaxationCurve& curve, const CurveFit& fit, double poisson_ratio);

}  // namespace growthuq
