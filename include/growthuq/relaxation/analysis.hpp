// From one measured force-relaxation curve to the wall's relaxation parameters: locate the
// hold, map k(t) = F(t) / delta to E_r(t), fit the Prony series (step or ramp-aware) and
// derive E0 and the viscosity eta = tau_slow E0 (Eqs. (R1)-(R7), src/relaxation/README.md).
#pragma once

#include <string>
#include <vector>

#include "growthuq/relaxation/curves.hpp"
#include "growthuq/relaxation/simulator.hpp"

namespace growthuq {

struct RelaxationOptions {
  int terms = 2;                    // exponentials in the Prony series: 1, 2 or 3
  double poisson_ratio = 0.2;       // nu of the wall: the instrument's (mechanics/instrument.hpp)
  bool ramp_aware = false;          // fit the ramp and the hold with the simulator
  double drop_ramp_multiple = 0.0;  // step fit only: ignore hold samples with t < this x ramp time
};

struct CurveFit {
  std::string curve;
  bool ok = false;
  std::string reason;             // why not ok
  std::vector<double> tau;        // s, fastest first
  std::vector<double> amplitude;  // of each exp(-t / tau_i) in E_r(t) / E_r(0), same order
  double einf = 0.0;              // E_inf / E_r(0)
  double modulus0 = 0.0;          // E_r(0) (Pa): first sample of the hold (step fit) or the
                                  // instantaneous modulus of the fitted springs (ramp-aware)
  double slow_modulus = 0.0;      // E0 = amplitude of the slow term (Pa)
  double viscosity = 0.0;         // eta = tau_slow E0 (Pa s)
  double tau_slow_relative_se = 0.0;  // linearized standard error of tau_slow / tau_slow (for
                                      // the ramp-aware fit: of the springs' slow time)
  double rms = 0.0;               // residual of the data: of E_r / E_r(0) (step), F / F_peak (ramp-aware)
  double aic = 0.0;
  double ramp_time = 0.0;         // s: first sample to force maximum (step), fitted (ramp-aware)
  std::size_t points = 0;         // samples fitted
  MaxwellModel springs;           // ramp-aware only: the contact fitted to the force (k_inf, k_i
                                  // in N/m, tau_i in s), its ramp ending at ramp_time
};

// Hold = samples from the force maximum on (t = 0 there, E_r(0) its modulus); ramp time =
// time of the maximum minus time of the first sample. Step fit: Prony series on E_r / E_r(0)
// over t >= drop_ramp_multiple x ramp time; taus bounded by [median sampling interval, hold
// length]. Ramp-aware fit: simulator basis on F over ramp and hold. Never throws for
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
