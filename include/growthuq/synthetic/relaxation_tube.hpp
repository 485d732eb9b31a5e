// One synthetic stress-relaxation experiment with a known truth: a tube whose wall relaxes as
// E_r(t) / E_r(0) = e_inf + (1 - e_inf) [s exp(-t / tau_fast) + (1 - s) exp(-t / tau_slow)]
// (the two phases of Eq. (R4), src/relaxation/README.md; s is the fast share of the relaxing part),
// indented by the ramp-and-hold protocol of the experiment simulator (relaxation/simulator.hpp).
//
// The probe sees the stiffness k(t) = k(E_r(t)) of the forward Arnoldi relation at the tube's p,
// d, h and rho (relaxation_stiffness). The simulator needs a generalized Maxwell contact with
// positive springs, and k(E_r(t)) is not completely monotone, so no positive series matches it
// exactly: the best one (NNLS over 40 log-spaced times) is off by about 5e-4 k(0), enough to
// bias a fitted tau_slow by up to 4 % (measured; distributions/README.md). So the ramp and hold
// come from the simulator with that series, and the hold is then corrected by delta [k(E_r(t -
// t_r)) - k_series(t - t_r)], t_r the end of the ramp: the hold is the exact step response plus the
// memory of the ramp the simulator computed, and an instantaneous ramp gives F = delta k(E_r(t))
// exactly. Noise: Gaussian, relative to the set point, from GaussianNoise(seed) as in the
// simulator; forces are clipped at 0 (a zeroed sensor does not report negative force).
#pragma once

#include <cstdint>

#include "growthuq/mechanics/instrument.hpp"
#include "growthuq/relaxation/simulator.hpp"

namespace growthuq {

struct RelaxationTube {
  double turgor = 0.0;        // p (Pa)
  double diameter = 0.0;      // d (m)
  double thickness = 0.0;     // h (m)
  Instrument instrument{0.0, 0.2};  // rho (m) and nu of the measurement (an ideal sensor)
  double stiffness0 = 0.0;    // k(0) = k(E_r(0)) (N/m): the instantaneous stiffness
  double tau_slow = 0.0;      // s
  double tau_fast = 0.0;      // s, < tau_slow
  double einf = 0.0;          // E_inf / E_r(0), in [0, 1)
  double fast_share = 0.0;    // s in [0, 1]
};

// k(t) of the tube for a step indentation at t = 0 (N/m).
double tube_step_stiffness(const RelaxationTube& tube, double t);

// The simulated record of `tube` (force with noise, in N). InputError for a tube or protocol
// that is not physical (non-positive geometry, e_inf outside [0, 1), tau_fast >= tau_slow).
SimulatedCurve simulate_relaxation_tube(const RelaxationTube& tube, const RampHoldProtocol& protocol,
                                        double relative_noise, std::uint64_t noise_seed);

}  // namespace growthuq
