// The time-dependent growth law (Ortega 1985, augmented Lockhart equation) for a tip of
// fixed diameter and wall, driven by prescribed turgor and viscosity histories and
// integrated with SUNDIALS CVODE: tip length L(t) and growth rate v(t).
//
// Wall strain rate (Ortega 1985, eq. 5, written for the hoop direction of a thin shell with
// hoop stress sigma = p d / (2 h) and yield stress sigma_y = p0 d / (2 h)):
//   eps_dot = (sigma - sigma_y)_+ / eta + (d / (2 h E)) dp/dt.
// The tip, a hemispherical shell of radius d/2, advances at its radius times its strain rate
// (times the geometric factor kappa that the campaign calibrates, see kappa.hpp):
//   dL/dt = v = kappa (d/2) eps_dot = kappa (d^2 / (4 h)) [ (p - p0)_+ / eta + (1/E) dp/dt ].
// At constant turgor this is the steady law of growth_rate.hpp, v = kappa (p - p0) d^2/(4 eta h);
// a fast turgor change dp adds the elastic jump kappa d^2 dp / (4 h E) to L. The elastic term
// acts whether or not the wall yields (elastic strain is reversible), so a turgor drop
// shortens L elastically even below p0.
#pragma once

#include <span>
#include <vector>

#include "growthuq/growth/growth_rate.hpp"
#include "growthuq/growth/waveform.hpp"

namespace growthuq {

// The tube, SI.
struct OrtegaTube {
  double d = 0.0;  // diameter, m
  double h = 0.0;  // wall thickness, m
  double E = 0.0;  // elastic modulus of the wall, Pa
  GrowthParameters growth;  // p0 (Pa), kappa
};

// CVODE tolerances. CVODE controls the local error per step to about
// relative_tolerance |L| + absolute_tolerance; the global error of these smooth, non-stiff
// problems stays within a small multiple of that.
struct OrtegaOptions {
  double relative_tolerance = 1e-10;
  double absolute_tolerance = 1e-15;  // m (a femtometre: far below any tip length)
  long max_steps = 500000;            // per output interval
};

// L and v at the requested times (m, m/s); L(times[0]) = 0.
struct OrtegaTrajectory {
  std::vector<double> time;
  std::vector<double> length;
  std::vector<double> velocity;
};

// Integrates dL/dt above with CVODE (Adams, non-stiff) from times[0] to times.back(). The
// integrator stops and restarts at every breakpoint of the histories (ramp and step ends) and,
// through CVODE's root finder, wherever p(t) crosses p0 (the kink of (.)_+), and caps its step
// at a tenth of the shortest history time scale so it cannot step over a fast step or a
// period. InputError (location "ortega") for: d, h, E not positive and finite; invalid growth
// parameters; a viscosity history that is not positive at all times; a turgor history that
// goes negative; fewer than 2 or non-increasing or non-finite times; CVODE failing (e.g.
// the step budget is exhausted: the message names CVODE's flag and the time reached).
OrtegaTrajectory simulate_ortega(const OrtegaTube& tube, const Waveform& turgor,
                                 const Waveform& viscosity, std::span<const double> times,
                                 const OrtegaOptions& options = {});

}  // namespace growthuq
