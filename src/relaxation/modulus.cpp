#include "growthuq/relaxation/modulus.hpp"

#include <cmath>
#include <numbers>

#include "growthuq/mechanics/arnoldi.hpp"

namespace growthuq {

double relaxation_modulus(double k, const ShellGeometry& shell) {
  const double p = shell.turgor, d = shell.diameter;
  const double rho = shell.instrument.probe_radius_m, nu = shell.instrument.poisson_ratio;
  const double phi = 4.0 * k / (3.0 * std::numbers::pi * p * d);
  const double x = arnoldi_phi_inverse(phi);
  // 1 / alpha^2 = x^2 / rho^2; x underflowing to 0 is the membrane limit alpha -> infinity.
  const double inverse_alpha_squared = (x / rho) * (x / rho);
  const double membrane = p * d + 3.0 * p * d * d * d * inverse_alpha_squared / 16.0;
  return (1.0 - nu * nu) * membrane / (2.0 * shell.thickness);
}

double relaxation_stiffness(double modulus, const ShellGeometry& shell) {
  const double p = shell.turgor, d = shell.diameter;
  const double rho = shell.instrument.probe_radius_m, nu = shell.instrument.poisson_ratio;
  const double excess = 2.0 * modulus * shell.thickness / (1.0 - nu * nu) - p * d;
  if (!(excess > 0.0)) return 0.0;
  // x = rho / alpha with 1 / alpha^2 = 16 excess / (3 p d^3).
  const double x = rho * std::sqrt(16.0 * excess / (3.0 * p * d * d * d));
  return 0.75 * std::numbers::pi * p * d * arnoldi_phi(x);
}

}  // namespace growthuq
