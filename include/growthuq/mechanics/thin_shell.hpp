// The fast thin-shell model of a pressurized pollen tube (Eqs. (M1)-(M10),
// src/mechanics/README.md): hoop equilibrium with logarithmic strain (Vogler et al. 2013) plus the
// apparent stiffness under a probe (Arnoldi et al. 2000). Closed-form inverse (k, d, d0 [, h] -> p
// [, E]) and the forward model (p, E, h, d0 -> d, k). Per-sample functions, SI units, a status
// instead of NaN.
#pragma once

#include "growthuq/evaluation/sample_status.hpp"
#include "growthuq/mechanics/instrument.hpp"

namespace growthuq {

// A tube's turgid and plasmolysed diameters [m] with its stretch lambda = d/d0 and hoop strain
// lambda - 1 = (d - d0)/d0 formed from the diameters as measured, before their conversion to SI:
// converting each diameter rounds it by up to half an ulp, which at lambda - 1 = 1e-12 moves
// d - d0, and with it ln(lambda), p and E, by about 1e-4 of itself. In one unit d - d0 is exact
// (Sterbenz, 1/2 <= lambda <= 2), so the strain is exact to one rounding at any stretch.
struct TubeDiameters {
  double d;       // [m]
  double d0;      // [m]
  double lambda;  // d / d0
  double strain;  // (d - d0) / d0 = lambda - 1, with all its digits
};

// From diameters d and d0 in units whose factors to SI are d_to_si and d0_to_si (unit_factor::um,
// Unit::to_si): the stretch and strain are formed in their own unit when both share one, from the
// SI values otherwise (a diameter converted between units is rounded, like one converted to SI).
TubeDiameters measured_diameters(double d, double d_to_si, double d0, double d0_to_si) noexcept;

// From diameters already in SI, for callers that have nothing else: the strain has only the
// digits the conversion left (see TubeDiameters).
inline TubeDiameters diameters_in_si(double d, double d0) noexcept { return measured_diameters(d, 1.0, d0, 1.0); }

// Relation 2 inverted for turgor: needs k, d, d0 but not h.
struct TurgorResult {
  double lambda;  // d / d0
  double q;       // (1 - nu^2) ln(lambda), < 1 for a membrane solution
  double alpha;   // decay length d sqrt(3q / (16 (1 - q))) [m]
  double x;       // rho / alpha
  double phi;     // arnoldi_phi(x)
  double p;       // 4 k / (3 pi d phi) [Pa], k the tube stiffness after the sensor correction
  SampleStatus status;  // not ok: every field above that could not be computed is NaN
};

// Measured stiffness k_m [N/m], turgid and plasmolysed diameters [m]. Statuses:
// invalid_input (a non-finite or non-positive input), stiffness_at_sensor_limit
// (k_m >= k_sys), lambda_not_above_one (d <= d0), beyond_membrane_limit (q >= 1),
// unstable_branch (ln(lambda) > 1, i.e. e < lambda < exp(1/(1 - nu^2)): past the pressure
// maximum of relation 1, where the forward model returns the other, smaller diameter; lambda = e
// itself is ok), out_of_range (p not a finite positive double), checked in this order, so for
// nu = 0 (q = ln(lambda)) every lambda > e is beyond_membrane_limit. ln(lambda) is computed as
// log1p(strain), exact to rounding even at lambda = 1 + 1e-12 when the strain was formed from
// the diameters as measured (TubeDiameters).
TurgorResult invert_turgor(double k_measured, const TubeDiameters& diameters, const Instrument& parameters) noexcept;
// The same from d and d0 in SI (diameters_in_si).
TurgorResult invert_turgor(double k_measured, double d, double d0,
                           const Instrument& parameters) noexcept;

// Relation 1 solved for the modulus, given turgor: E = p d / (2 h ln lambda).
struct ModulusResult {
  double E;               // [Pa]
  double hoop_stress;     // p d / (2 h) [Pa]
  double wall_stiffness;  // E h [N/m]
  SampleStatus status;    // invalid_input, lambda_not_above_one, unstable_branch (ln(lambda) > 1,
                          // as invert_turgor), out_of_range (E overflows)
};

ModulusResult invert_modulus(double p, const TubeDiameters& diameters, double h) noexcept;
// The same from d and d0 in SI (diameters_in_si).
ModulusResult invert_modulus(double p, double d, double d0, double h) noexcept;

// The forward model: the turgid diameter solves ln(d/d0) = c d, c = p / (2 h E), i.e.
// d = -W0(-c d0)/c (Lambert W, principal branch), then k from relation 2, as the instrument
// measures it (in series with k_sys).
struct ForwardResult {
  double d;           // [m]
  double lambda;      // d / d0, in (1, e]
  double alpha;       // [m]
  double phi;
  double k_measured;  // [N/m]
  SampleStatus status;  // invalid_input, burst (c d0 > 1/e), beyond_membrane_limit, out_of_range
};

ForwardResult thin_shell_forward(double p, double E, double h, double d0,
                                 const Instrument& parameters) noexcept;

}  // namespace growthuq
