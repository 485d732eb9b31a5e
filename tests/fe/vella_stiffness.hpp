// Linear point-load stiffness of a pressurised thin spherical shell (shallow-shell theory), the
// reference the finite-element sphere is checked against: Vella, Ajdari, Vaziri and Boudaoud
// 2012 (J R Soc Interface 9:448), with Reissner's unpressurised limit (Reissner 1946).
#pragma once

#include <cmath>
#include <numbers>

namespace growthuq::testing {

// Shell of mid-surface radius R and thickness h under internal pressure p (all of the
// pressurised state), Young's modulus E, Poisson's ratio nu; any consistent units.
struct PressurisedSphere {
  double radius = 0.0;
  double thickness = 0.0;
  double pressure = 0.0;
  double young = 0.0;
  double poisson = 0.0;

  // Bending modulus B = E h^3 / (12 (1 - nu^2)) and stretching modulus Y = E h.
  double bending_modulus() const { return young * thickness * thickness * thickness / (12.0 * (1.0 - poisson * poisson)); }
  double stretching_modulus() const { return young * thickness; }
  // tau = p R^2 / (4 sqrt(B Y)) (Vella et al. 2012, eq. 2.5): pressure over its bending scale.
  double tau() const { return pressure * radius * radius / (4.0 * std::sqrt(bending_modulus() * stretching_modulus())); }
  // Reissner's stiffness 8 sqrt(B Y) / R, the limit p -> 0.
  double reissner_stiffness() const { return 8.0 * std::sqrt(bending_modulus() * stretching_modulus()) / radius; }
};

// The dimensionless factor f(tau) of k = (4 pi sqrt(B Y) / R) f(tau) (Vella et al. 2012,
// eq. 3.3): sqrt(1 - tau^2) / arccos(tau) below tau = 1, sqrt(tau^2 - 1) / artanh(sqrt(1 -
// tau^-2)) above, 1 at tau = 1. Written without cancellation: 1 - tau^2 = (1 - tau)(1 + tau),
// arccos(tau) = 2 arcsin(sqrt((1 - tau)/2)), and with s = sqrt(1 - tau^-2), artanh(s) =
// ln(tau (1 + s)) = log1p(tau - 1 + sqrt(tau^2 - 1)) (since 1 - s^2 = tau^-2). At tau = 1 both
// forms are 0/0: within 1e-6 of it their common series 1 + x/3 - x^2/45 (x = tau - 1, next term
// ~5e-3 x^3) is used.
inline double vella_factor(double tau) {
  const double x = tau - 1.0;
  if (std::fabs(x) < 1e-6) return 1.0 + x / 3.0 - x * x / 45.0;
  if (tau < 1.0) return std::sqrt(-x * (1.0 + tau)) / (2.0 * std::asin(std::sqrt(-x / 2.0)));
  const double root = std::sqrt(x * (1.0 + tau));  // sqrt(tau^2 - 1) = tau s
  return root / std::log1p(x + root);
}

// k = F / w of a point force on the shell, linear in the indentation w.
inline double vella_stiffness(const PressurisedSphere& shell) {
  const double bending_scale =
      4.0 * std::numbers::pi * std::sqrt(shell.bending_modulus() * shell.stretching_modulus()) / shell.radius;
  return bending_scale * vella_factor(shell.tau());
}

}  // namespace growthuq::testing
