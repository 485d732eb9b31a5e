// A simulated stress-relaxation experiment (Eq. (R8), src/relaxation/README.md): the probe indents
// at a constant rate until the force reaches the set point, then holds its position. The tube under
// the probe is a generalized Maxwell spring, integrated as an ODE with SUNDIALS CVODE.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <span>
#include <vector>

namespace growthuq {

// Stiffness relaxation function k(t) = k_inf + sum_i k_i exp(-t / tau_i) of the probe-tube
// contact: force F = k_inf u + sum_i F_i with dF_i/dt = k_i du/dt - F_i / tau_i (each F_i is a
// spring k_i in series with a dashpot k_i tau_i). SI units: N/m and s.
struct MaxwellModel {
  double k_inf = 0.0;
  std::vector<double> k;
  std::vector<double> tau;
};

struct RampHoldProtocol {
  double rate = 10e-6;            // indentation speed during the ramp (m/s)
  double set_point = 5e-6;        // force that ends the ramp (N)
  double hold = 5.0;              // time the probe is held after the set point (s)
  double sample_interval = 0.01;  // the record holds t = 0, dt, 2 dt, ... <= ramp end + hold (s)
};

// Added to the exact force at every sample: Gaussian noise of standard deviation
// relative_sd * set_point, and a linear drift (N/s) from t = 0. Seeded, hence reproducible.
struct MeasurementNoise {
  double relative_sd = 0.0;
  double drift = 0.0;
  std::uint64_t seed = 1;
};

struct SimulatedCurve {
  std::vector<double> t;             // s, from the start of the ramp (contact)
  std::vector<double> force;         // N, with noise and drift when asked for
  std::vector<double> displacement;  // m, probe indentation u(t)
  double ramp_end = 0.0;             // time the set point was reached (s), by CVODE root finding
  double indentation = 0.0;          // displacement held during the hold (m)
};

// Integrates the ramp (CVODE, BDF, exact diagonal Jacobian, root finding on F = set point)
// and the hold. InputError for a model or protocol that is not positive and finite, and when
// the set point cannot be reached (k_inf = 0 and sum k_i tau_i rate <= set point).
SimulatedCurve simulate_ramp_hold(const MaxwellModel& model, const RampHoldProtocol& protocol,
                                  const MeasurementNoise& noise = {});

// The ramp-aware fit's basis: column 0 is u(t) (the k_inf term), column i + 1 the force of
// mode i with unit stiffness, k_i = 1 N/m, for a displacement ramped linearly from 0 at t = 0
// to `indentation` at `ramp_time` and held after. Integrated with CVODE like
// simulate_ramp_hold, the ramp in t / ramp_time so that any ramp_time >= 0 is well posed:
// ramp_time = 0 is the limit of short ramps, a step just after t = 0 (row 0 at t = 0 is
// contact, all zero). Times must be increasing and >= 0.
Eigen::MatrixXd maxwell_mode_responses(std::span<const double> tau, double ramp_time,
                                       double indentation, std::span<const double> t);

}  // namespace growthuq
