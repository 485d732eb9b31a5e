// The time-dependent Ortega growth law integrated by CVODE, against closed forms (steady
// growth, a smoothed pressure step up and down across the yield pressure, a linear ramp, an
// oscillating viscosity) and against GSL adaptive quadrature when no closed form exists.
//
// Tolerances: CVODE runs with rtol = 1e-10 and atol = 1e-15 m and controls the local error per
// step to about rtol |L| + atol. The problem is a non-stiff quadrature (the right-hand side
// does not depend on L), so the global error is the sum of local errors over a few hundred
// steps; 100 (rtol |L| + atol) leaves margin for that sum while still failing for a missed
// step, a wrong elastic jump or a wrong integral (each off by 1e-3 relative or more).
#include <doctest/doctest.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/growth/growth_rate.hpp"
#include "growthuq/growth/ortega.hpp"

using namespace growthuq;

namespace {

constexpr double relative_tolerance = 1e-10;
constexpr double absolute_tolerance = 1e-15;

// Wild-type-like tube: d = 6.56 um, h = 145 nm, E = 50 MPa, p0 = 0.1 MPa, kappa = 0.05.
OrtegaTube tube() {
  return {.d = 6.56e-6, .h = 145e-9, .E = 5e7, .growth = {.p0 = 1e5, .kappa = 0.05}};
}

double length_scale(const OrtegaTube& t) { return t.growth.kappa * t.d * t.d / (4.0 * t.h); }

OrtegaOptions options() { return {.relative_tolerance = relative_tolerance, .absolute_tolerance = absolute_tolerance}; }

void check_length(double value, double exact) {
  CHECK(std::abs(value - exact) <= 100.0 * (relative_tolerance * std::abs(exact) + absolute_tolerance));
}

// Integral over [0, s] of the smoothstep weight 3u^2 - 2u^3.
double smoothstep_integral(double s) { return s * s * s - 0.5 * s * s * s * s; }

}  // namespace

TEST_CASE("steady turgor and viscosity: L = v t with v the steady growth law") {
  const OrtegaTube t = tube();
  const double p = 3e5, eta = 1.2e8;
  const std::vector<double> times{0, 1, 10, 100, 1000};
  const auto run = simulate_ortega(t, Waveform::constant(p), Waveform::constant(eta), times, options());

  SampleBlock block(1);
  block.set_column("p", std::vector<double>{p});
  block.set_column("d", std::vector<double>{t.d});
  block.set_column("eta", std::vector<double>{eta});
  block.set_column("h", std::vector<double>{t.h});
  GrowthEvaluator(t.growth).evaluate(block);
  const double steady = block.column("v")[0];

  for (std::size_t k = 0; k < times.size(); ++k) {
    CAPTURE(times[k]);
    // Same law, other order of operations: a few roundings apart.
    CHECK(std::abs(run.velocity[k] - steady) <= 4 * std::numeric_limits<double>::epsilon() * steady);
    check_length(run.length[k], steady * times[k]);
  }
}

TEST_CASE("pressure step up: elastic jump kappa d^2 dp / (4 h E) plus the new steady rate") {
  const OrtegaTube t = tube();
  const double p1 = 3e5, p2 = 5e5, eta = 1.2e8, start = 10.0, rise = 1e-3;
  const double p0 = t.growth.p0;
  // The outputs skip over the 1 ms rise (5 s -> 20 s): the breakpoints must stop CVODE there.
  const std::vector<double> times{0, 5, start, start + 0.5 * rise, start + rise, 20, 60};
  const auto run = simulate_ortega(t, Waveform::smooth_step(p1, p2, start, rise),
                                   Waveform::constant(eta), times, options());

  // Exact: L = s [ integral of (p - p0) / eta + (p(t) - p1) / E ], s = kappa d^2 / (4 h).
  const double s = length_scale(t);
  auto exact = [&](double time) {
    double viscous = (p1 - p0) * std::min(time, start);
    if (time > start) {
      const double u = std::min((time - start) / rise, 1.0);
      viscous += rise * ((p1 - p0) * u + (p2 - p1) * smoothstep_integral(u));
    }
    if (time > start + rise) viscous += (p2 - p0) * (time - start - rise);
    const double u = std::clamp((time - start) / rise, 0.0, 1.0);
    const double p = p1 + (p2 - p1) * u * u * (3 - 2 * u);
    return s * (viscous / eta + (p - p1) / t.E);
  };
  for (std::size_t k = 0; k < times.size(); ++k) {
    CAPTURE(times[k]);
    check_length(run.length[k], exact(times[k]));
  }
  // The jump over the rise: elastic kappa d^2 dp / (4 h E) (1.48e-7 m here) plus the flow
  // during the 1 ms rise at the mean overpressure.
  const double jump = s * (p2 - p1) / t.E + s * ((p1 + p2) / 2 - p0) * rise / eta;
  const double jump_tolerance = 100.0 * (relative_tolerance * (run.length[4] + run.length[2]) + 2 * absolute_tolerance);
  CHECK(std::abs(run.length[4] - run.length[2] - jump) <= jump_tolerance);
  // Sparse outputs that straddle the 1 ms rise: only the breakpoints make CVODE see it.
  const std::vector<double> sparse{0, 20, 60};
  const auto coarse = simulate_ortega(t, Waveform::smooth_step(p1, p2, start, rise), Waveform::constant(eta),
                                      sparse, options());
  check_length(coarse.length[1], exact(20));
  check_length(coarse.length[2], exact(60));
  // The new steady rate, from the integrated lengths (not from the formula).
  const double rate = (run.length[6] - run.length[5]) / 40.0;
  CHECK(std::abs(rate - s * (p2 - p0) / eta) <= 1e-8 * rate);
  CHECK(run.velocity[6] == doctest::Approx(s * (p2 - p0) / eta).epsilon(1e-15));
}

TEST_CASE("pressure step down below p0: elastic shortening, then no growth") {
  const OrtegaTube t = tube();
  const double p0 = t.growth.p0;
  const double p1 = 3e5, p2 = 5e4, eta = 1.2e8, start = 10.0, rise = 0.01;
  const std::vector<double> times{0, start, 20, 60};
  const auto run = simulate_ortega(t, Waveform::smooth_step(p1, p2, start, rise),
                                   Waveform::constant(eta), times, options());

  // p crosses p0 where the smoothstep weight w(u*) = (p1 - p0) / (p1 - p2) = 0.8; solve
  // 3u^2 - 2u^3 = 0.8 on [0, 1] by bisection (w is increasing there).
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid * mid * (3 - 2 * mid) < 0.8 ? lo : hi) = mid;
  }
  const double u_cross = 0.5 * (lo + hi);
  const double s = length_scale(t);
  const double before = s * (p1 - p0) * start / eta;
  const double during = s * rise * ((p1 - p0) * u_cross - (p1 - p2) * smoothstep_integral(u_cross)) / eta;
  const double after = before + during + s * (p2 - p1) / t.E;  // elastic drop of 2.5e-7 m

  check_length(run.length[1], before);
  check_length(run.length[2], after);
  check_length(run.length[3], after);
  CHECK(run.velocity[3] == 0.0);
}

TEST_CASE("a step below p0 is purely elastic, even between sparse outputs") {
  // dL/dt is zero except during the 1 ms rise, so an integrator that stepped over the rise
  // would see a zero right-hand side and miss the jump entirely; the breakpoints prevent it.
  const OrtegaTube t = tube();
  const double p1 = 5e4, p2 = 8e4, start = 10.0, rise = 1e-3;
  const std::vector<double> times{0, 20, 60};
  const auto run = simulate_ortega(t, Waveform::smooth_step(p1, p2, start, rise), Waveform::constant(1.2e8),
                                   times, options());
  const double jump = length_scale(t) * (p2 - p1) / t.E;  // 2.2e-7 m
  check_length(run.length[0], 0.0);
  check_length(run.length[1], jump);
  check_length(run.length[2], jump);
  CHECK(run.velocity[2] == 0.0);
}

TEST_CASE("linear turgor ramp: piecewise quadratic length") {
  const OrtegaTube t = tube();
  const double p0 = t.growth.p0;
  const double p1 = 2e5, p2 = 6e5, start = 5.0, duration = 20.0, eta = 8e7;
  const std::vector<double> times{0, 3, 5, 12.5, 25, 40};
  const auto run = simulate_ortega(t, Waveform::ramp(p1, p2, start, duration),
                                   Waveform::constant(eta), times, options());
  const double s = length_scale(t);
  const double slope = (p2 - p1) / duration;
  auto exact = [&](double time) {
    const double before = std::min(time, start);
    const double inside = std::clamp(time - start, 0.0, duration);
    const double after = std::max(time - start - duration, 0.0);
    const double viscous = (p1 - p0) * before + (p1 - p0) * inside + 0.5 * slope * inside * inside +
                           (p2 - p0) * after;
    return s * (viscous / eta + slope * inside / t.E);
  };
  for (std::size_t k = 0; k < times.size(); ++k) {
    CAPTURE(times[k]);
    check_length(run.length[k], exact(times[k]));
  }
  CHECK(run.velocity[3] == doctest::Approx(s * ((3e5 + 1e5) / eta + slope / t.E)));
}

TEST_CASE("oscillating viscosity eta0 (1 + a sin(w t)): exact integral of 1/eta") {
  const OrtegaTube t = tube();
  const double p = 3e5, eta0 = 1.2e8, a = 0.5, period = 30.0;
  const std::vector<double> times{0, 7, 15, 22.5, 30, 47, 100, 200};
  const auto run = simulate_ortega(t, Waveform::constant(p), Waveform::sine(eta0, a * eta0, period),
                                   times, options());
  // integral_0^theta dx / (1 + a sin x) = G(theta) - G(0),
  //   G(theta) = (2/r) [atan((tan(phi/2) + a) / r) + pi k],  r = sqrt(1 - a^2),
  // phi = theta - 2 pi k in [-pi, pi) (the + pi k keeps G continuous). Checked against
  // mpmath.quad to 2e-16 at these times (python3, mpmath, 30 digits).
  const double r = std::sqrt(1 - a * a), omega = 2 * std::numbers::pi / period;
  auto G = [&](double theta) {
    const double k = std::floor((theta + std::numbers::pi) / (2 * std::numbers::pi));
    const double phi = theta - 2 * std::numbers::pi * k;
    return 2 / r * (std::atan((std::tan(phi / 2) + a) / r) + std::numbers::pi * k);
  };
  const double s = length_scale(t);
  for (std::size_t k = 0; k < times.size(); ++k) {
    CAPTURE(times[k]);
    const double integral = (G(omega * times[k]) - G(0.0)) / omega;
    check_length(run.length[k], s * (p - t.growth.p0) / eta0 * integral);
  }
  // Over whole periods the mean fluidity is 1 / (eta0 sqrt(1 - a^2)): 15 % faster growth than
  // at constant eta0 here.
  check_length(run.length[4], s * (p - t.growth.p0) / eta0 * period / r);
}

TEST_CASE("oscillating turgor across p0 and oscillating viscosity: CVODE matches GSL quadrature") {
  const OrtegaTube t = tube();
  const Waveform turgor = Waveform::sine(1.2e5, 1e5, 20.0, 0.3);  // 0.02-0.22 MPa, p0 = 0.1
  const Waveform viscosity = Waveform::sine(1e8, 6e7, 7.0);
  const std::vector<double> times{0, 3, 11, 50, 97.5};
  const auto run = simulate_ortega(t, turgor, viscosity, times, options());

  // Second algorithm: L(t) = s [ integral (p - p0)_+ / eta dt + (p(t) - p(0)) / E ], the
  // integral by GSL QAGS to 1e-13 relative.
  struct Data {
    const Waveform* turgor;
    const Waveform* viscosity;
    double p0;
  } data{&turgor, &viscosity, t.growth.p0};
  gsl_function f;
  f.function = [](double time, void* params) {
    const auto& d = *static_cast<const Data*>(params);
    return std::max(d.turgor->value(time) - d.p0, 0.0) / d.viscosity->value(time);
  };
  f.params = &data;
  gsl_set_error_handler_off();  // statuses are checked below
  gsl_integration_workspace* workspace = gsl_integration_workspace_alloc(10000);
  const double s = length_scale(t);
  for (std::size_t k = 1; k < times.size(); ++k) {
    CAPTURE(times[k]);
    // In pieces of at most 1 s, so each piece holds at most one kink of (.)_+.
    double integral = 0, error = 0;
    for (double a = 0.0; a < times[k]; a += 1.0) {
      double piece = 0, piece_error = 0;
      const double b = std::min(a + 1.0, times[k]);
      const int code = gsl_integration_qags(&f, a, b, 0.0, 1e-13, 10000, workspace, &piece, &piece_error);
      CAPTURE(gsl_strerror(code));
      REQUIRE(code == GSL_SUCCESS);
      integral += piece;
      error += piece_error;
    }
    const double exact = s * (integral + (turgor.value(times[k]) - turgor.value(0.0)) / t.E);
    CHECK(std::abs(run.length[k] - exact) <= 100.0 * (relative_tolerance * std::abs(exact) + absolute_tolerance) + s * error);
  }
  gsl_integration_workspace_free(workspace);
}

TEST_CASE("bad Ortega inputs are InputErrors naming the value") {
  const std::vector<double> times{0, 1};
  CHECK_THROWS_WITH_AS(simulate_ortega(tube(), Waveform::constant(3e5), Waveform::sine(1e6, 2e6, 10.0), times),
                       "ortega: minimum of the viscosity history = '-1e+06': expected a viscosity > 0 Pa s at all times",
                       InputError);
  CHECK_THROWS_WITH_AS(simulate_ortega(tube(), Waveform::ramp(3e5, -1e5, 0, 1), Waveform::constant(1e8), times),
                       "ortega: minimum of the turgor history = '-1e+05': expected a turgor >= 0 Pa at all times",
                       InputError);
  const std::vector<double> backwards{0, 2, 1};
  CHECK_THROWS_WITH_AS(simulate_ortega(tube(), Waveform::constant(3e5), Waveform::constant(1e8), backwards),
                       "ortega: times[2] = '1': expected finite times in increasing order", InputError);
  OrtegaTube flat = tube();
  flat.h = 0.0;
  CHECK_THROWS_WITH_AS(simulate_ortega(flat, Waveform::constant(3e5), Waveform::constant(1e8), times),
                       "ortega: h = '0': expected a positive finite thickness in m", InputError);
  CHECK_THROWS_WITH_AS(Waveform::ramp(1, 2, 0, 0), "ramp waveform: duration = '0': expected a positive finite time in s",
                       InputError);
  CHECK_THROWS_AS(Waveform::sine(1, 2, -3), InputError);
  CHECK_THROWS_AS(Waveform::constant(std::nan("")), InputError);
  // A step budget far too small for 10^4 periods: CVODE's failure is reported, not hidden.
  const std::vector<double> long_span{0, 1e4};
  CHECK_THROWS_AS(simulate_ortega(tube(), Waveform::sine(3e5, 1e5, 1.0), Waveform::constant(1e8), long_span,
                                  {.relative_tolerance = 1e-10, .absolute_tolerance = 1e-15, .max_steps = 100}),
                  InputError);
}
