// Apparent relaxation modulus of the wall from the probe's stiffness (Eq. (R2),
// src/relaxation/README.md): Arnoldi et al. (2000) relation k = (3 pi / 4) p d phi(rho / alpha)
// inverted at fixed p, d.
#pragma once

#include "growthuq/mechanics/instrument.hpp"

namespace growthuq {

struct ShellGeometry {
  double turgor = 0.0;      // p (Pa)
  double diameter = 0.0;    // d (m)
  double thickness = 0.0;   // h (m)
  Instrument instrument;    // rho and nu (the relaxation maps force through an ideal sensor: k_sys unused)
};

// E_r for a stiffness k >= 0 (N/m): phi = 4 k / (3 pi p d), x = phi^-1(phi), alpha = rho / x,
// then 2 E_r h / (1 - nu^2) = p d + 3 p d^3 / (16 alpha^2) (alpha^2 definition of Arnoldi et
// al. 2000 solved for E). k = 0 gives the membrane limit (1 - nu^2) p d / (2 h).
double relaxation_modulus(double k, const ShellGeometry& shell);

// The forward relation, inverse of relaxation_modulus: the probe stiffness k (N/m) of a wall of
// modulus E_r (Pa) at fixed p, d, h, rho: alpha^2 = 3 p d^3 / (16 (2 E_r h / (1 - nu^2) - p d)),
// k = (3 pi / 4) p d phi(rho / alpha) (Arnoldi et al. 2000). At or below the membrane limit
// (1 - nu^2) p d / (2 h) alpha is unbounded and k = 0.
double relaxation_stiffness(double modulus, const ShellGeometry& shell);

}  // namespace growthuq
