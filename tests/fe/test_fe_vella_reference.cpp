// The pressurised-sphere reference stiffness (Vella et al. 2012) against a second derivation,
// the shallow-shell Green's function integrated numerically, against 40-digit values, and its
// limits: Reissner at tau = 0, continuity at tau = 1, k ~ pi p R / ln(2 tau) at large tau.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "vella_stiffness.hpp"

using growthuq::testing::PressurisedSphere;
using growthuq::testing::vella_factor;
using growthuq::testing::vella_stiffness;

namespace {

// A point force F on the shallow shell B lap^2 w - sigma lap w + (Y/R^2) w = F delta (sigma =
// p R / 2, the membrane prestress) gives, by a Hankel transform, w(0) = (F / 4 pi) int_0^inf du
// / (B u^2 + sigma u + Y/R^2) (Vella et al. 2012, section 3). With u = sqrt(Y/(B R^2)) t the
// factor is f(tau) = 1 / J(tau), J = int_0^inf dt / (t^2 + 2 tau t + 1); t -> 1/t maps [1, inf)
// onto [0, 1] with the same integrand, and t = e^x makes the peak near t ~ 1/(2 tau) smooth,
// so composite Simpson on x in [-60, 0] converges fast (the integrand is below e^-60 beyond).
double factor_by_quadrature(double tau) {
  const int intervals = 20000;
  const double low = -60.0;
  const double step = -low / intervals;
  auto integrand = [tau](double x) {
    const double t = std::exp(x);
    return t / (t * t + 2.0 * tau * t + 1.0);
  };
  double sum = integrand(low) + integrand(0.0);
  for (int i = 1; i < intervals; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * integrand(low + i * step);
  const double half_integral = sum * step / 3.0;
  return 1.0 / (2.0 * half_integral);
}

}  // namespace

TEST_CASE("Vella's factor matches the numerically integrated shallow-shell Green's function") {
  // Both are the same integral, one in closed form; Simpson's error at 20000 intervals is
  // below 1e-12 for these tau.
  const std::vector<double> taus{0.0, 1e-3, 0.1, 0.5, 0.9, 0.999, 1.0, 1.001, 1.5, 3.0, 10.0, 30.0, 100.0, 1000.0};
  for (double tau : taus) {
    CAPTURE(tau);
    CHECK(std::fabs(vella_factor(tau) / factor_by_quadrature(tau) - 1.0) < 1e-11);
  }
}

TEST_CASE("Vella's factor matches 40-digit values") {
  // mpmath (dps 40) of the two closed forms: sqrt(1-t^2)/acos(t), sqrt(t^2-1)/atanh(sqrt(1-t^-2)).
  struct Case {
    double tau, factor;
  };
  const std::vector<Case> cases{{0.5, 0.82699334313268807427}, {3.0, 1.6045563234489544149},
                                {10.0, 3.3241341799667970612}, {100.0, 18.873061917841530085}};
  for (const Case& c : cases) {
    CAPTURE(c.tau);
    CHECK(std::fabs(vella_factor(c.tau) / c.factor - 1.0) < 1e-14);
  }
}

TEST_CASE("at zero pressure the stiffness is Reissner's 8 sqrt(B Y) / R") {
  PressurisedSphere shell{.radius = 3.0e-6, .thickness = 150e-9, .pressure = 0.0, .young = 50e6, .poisson = 0.3};
  CHECK(shell.tau() == 0.0);
  // f(0) = 1/arccos(0) = 2/pi exactly, so k = (4 pi sqrt(BY)/R)(2/pi): equal to a few ulps.
  CHECK(std::fabs(vella_stiffness(shell) / shell.reissner_stiffness() - 1.0) < 4e-16);
  // And it approaches Reissner continuously: f(tau) = 2/pi + (4/pi^2) tau + O(tau^2) (series of
  // sqrt(1 - t^2)/arccos(t) at 0), so at tau = 1e-6 the ratio is 1 + (2/pi) 1e-6.
  shell.pressure = 1e-6 * 4.0 * std::sqrt(shell.bending_modulus() * shell.stretching_modulus()) /
                   (shell.radius * shell.radius);
  CHECK(shell.tau() == doctest::Approx(1e-6).epsilon(1e-12));
  CHECK(vella_stiffness(shell) / shell.reissner_stiffness() - 1.0 ==
        doctest::Approx(2.0 / std::numbers::pi * 1e-6).epsilon(1e-5));
}

TEST_CASE("the two branches meet at tau = 1 with the common value 1 and slope 1/3") {
  CHECK(vella_factor(1.0) == 1.0);
  // On either side, within and beyond the series' range: f(1 + x) = 1 + x/3 - x^2/45 + O(x^3)
  // (mpmath), the O(x^3) term below 1e-2 |x|^3 for |x| <= 1e-2.
  for (double x : {-1e-2, -1e-4, -2e-6, -5e-7, 5e-7, 2e-6, 1e-4, 1e-2}) {
    CAPTURE(x);
    const double series = 1.0 + x / 3.0 - x * x / 45.0;
    CHECK(std::fabs(vella_factor(1.0 + x) - series) < 1e-2 * std::fabs(x * x * x) + 1e-15);
  }
}

TEST_CASE("at large tau the stiffness tends to pi p R / ln(2 tau)") {
  // sqrt(tau^2 - 1) = tau (1 - 1/(2 tau^2) + ...) and artanh(sqrt(1 - tau^-2)) = ln(2 tau) -
  // 1/(4 tau^2) + ..., so the relative gap to pi p R / ln(2 tau) is below 1/tau^2 (Vella et al.
  // 2012's large-pressure limit, where bending matters only through the logarithm).
  for (double tau : {10.0, 100.0, 1000.0}) {
    CAPTURE(tau);
    PressurisedSphere shell{.radius = 3.0e-6, .thickness = 150e-9, .pressure = 0.0, .young = 50e6, .poisson = 0.0};
    shell.pressure = tau * 4.0 * std::sqrt(shell.bending_modulus() * shell.stretching_modulus()) /
                     (shell.radius * shell.radius);
    const double asymptote = std::numbers::pi * shell.pressure * shell.radius / std::log(2.0 * tau);
    const double gap = std::fabs(vella_stiffness(shell) / asymptote - 1.0);
    CHECK(gap < 1.0 / (tau * tau));
    CHECK(gap > 0.1 / (tau * tau));  // the correction is really of that order, not smaller
  }
}
