// A program using the installed library: the thin-shell turgor inverse and a lognormal law,
// each checked against a value computed here independently. Exit 0 when both agree.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "growthuq/distributions/lognormal.hpp"
#include "growthuq/mechanics/thin_shell.hpp"

int main() {
  int failures = 0;

  // Turgor of a tube of stiffness k = 2 N/m, d = 10 um, d0 = 9.3 um under a 0.5 um probe,
  // nu = 0.2, ideal sensor. Reference: the closed form the header states,
  //   lambda = d/d0, q = (1 - nu^2) ln lambda, alpha = d sqrt(3q / (16 (1 - q))),
  //   phi = x K1(x) / K0(x) with x = rho / alpha, p = 4 k / (3 pi d phi),
  // with the Bessel functions of the C++ standard library (the engine uses GSL's). The two
  // Bessel implementations agree to about 1e-14 relative here; 1e-10 leaves room for either and
  // still catches any wrong term (a unit or factor error is of order 1).
  const double k = 2.0, d = 10e-6, d0 = 9.3e-6, rho = 0.5e-6, nu = 0.2;
  growthuq::Instrument instrument;
  instrument.probe_radius_m = rho;
  instrument.poisson_ratio = nu;
  const growthuq::TurgorResult turgor = growthuq::invert_turgor(k, d, d0, instrument);

  const double q = (1 - nu * nu) * std::log(d / d0);
  const double alpha = d * std::sqrt(3 * q / (16 * (1 - q)));
  const double x = rho / alpha;
  const double phi = x * std::cyl_bessel_k(1.0, x) / std::cyl_bessel_k(0.0, x);
  const double p_reference = 4 * k / (3 * std::numbers::pi * d * phi);
  const double p_error = std::abs(turgor.p - p_reference) / p_reference;
  std::printf("turgor: %.17g Pa, reference %.17g Pa, relative difference %.2g\n", turgor.p, p_reference, p_error);
  if (turgor.status != growthuq::SampleStatus::ok || !(p_error < 1e-10)) ++failures;

  // A lognormal given by median 4 and IQR 3: its quartiles must be 3 apart and its median 4;
  // quantiles are accurate to a few ulp, so 1e-12 relative is ample.
  const auto law = growthuq::Lognormal::from_median_iqr(4.0, 3.0);
  const double iqr = growthuq::quantile(law, 0.75) - growthuq::quantile(law, 0.25);
  const double median = growthuq::quantile(law, 0.5);
  std::printf("lognormal: median %.17g, IQR %.17g\n", median, iqr);
  if (!(std::abs(median - 4.0) < 4e-12 && std::abs(iqr - 3.0) < 3e-12)) ++failures;

  return failures == 0 ? 0 : 1;
}
