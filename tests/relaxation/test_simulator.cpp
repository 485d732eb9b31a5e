// The experiment simulator against the closed-form ramp-and-hold response of the linear
// generalized Maxwell model, and the reproducible noise generator against its definition.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "growthuq/core/error.hpp"
#include "relaxation/noise.hpp"
#include "growthuq/relaxation/simulator.hpp"

using namespace growthuq;

namespace {

// F(t) during a ramp u = r t from rest: k_inf r t + sum k_i r tau_i (1 - exp(-t / tau_i)).
double ramp_force(const MaxwellModel& m, double rate, double t) {
  double force = m.k_inf * rate * t;
  for (std::size_t i = 0; i < m.k.size(); ++i) force += m.k[i] * rate * m.tau[i] * -std::expm1(-t / m.tau[i]);
  return force;
}

// Closed form over ramp and hold: after t_r each mode decays from its ramp-end value.
double exact_force(const MaxwellModel& m, double rate, double t_r, double t) {
  if (t <= t_r) return ramp_force(m, rate, t);
  double force = m.k_inf * rate * t_r;
  for (std::size_t i = 0; i < m.k.size(); ++i) {
    force += m.k[i] * rate * m.tau[i] * -std::expm1(-t_r / m.tau[i]) * std::exp(-(t - t_r) / m.tau[i]);
  }
  return force;
}

// Set-point time by bisection on the (increasing) closed-form ramp force.
double exact_ramp_end(const MaxwellModel& m, double rate, double set_point) {
  double low = 0.0, high = 1.0;
  while (ramp_force(m, rate, high) < set_point) high *= 2.0;
  for (int i = 0; i < 200; ++i) {
    const double middle = 0.5 * (low + high);
    (ramp_force(m, rate, middle) < set_point ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

const MaxwellModel wall{1.5, {2.0, 1.0}, {0.2, 3.0}};

}  // namespace

TEST_CASE("simulator: CVODE ramp and hold match the closed-form linear response") {
  // A slow ramp (0.5 um/s, ramp ~0.8 s) so that both modes relax during it.
  for (double rate : {0.5e-6, 10e-6, 200e-6}) {
    RampHoldProtocol protocol;
    protocol.rate = rate;
    const SimulatedCurve curve = simulate_ramp_hold(wall, protocol);
    const double t_r = exact_ramp_end(wall, rate, protocol.set_point);
    CAPTURE(rate);
    // CVODE runs at rtol 1e-10; the root and the samples are held to 1e-8 (global error of a
    // BDF solution grows to a few tens of rtol over a run).
    CHECK(curve.ramp_end == doctest::Approx(t_r).epsilon(1e-8));
    CHECK(curve.indentation == doctest::Approx(rate * t_r).epsilon(1e-8));
    double worst = 0.0;
    for (std::size_t j = 0; j < curve.t.size(); ++j) {
      CHECK(curve.t[j] == doctest::Approx(0.01 * static_cast<double>(j)).epsilon(1e-12));
      worst = std::max(worst, std::abs(curve.force[j] - exact_force(wall, rate, t_r, curve.t[j])) / protocol.set_point);
    }
    CHECK(worst < 1e-8);
    // The record ends with the last sample not later than ramp end + hold.
    CHECK(curve.t.back() <= t_r + protocol.hold + 1e-9);
    CHECK(curve.t.back() > t_r + protocol.hold - protocol.sample_interval);
  }
}

TEST_CASE("simulator: unit-stiffness mode responses match the closed form (ramp-aware fit basis)") {
  const std::vector<double> tau{0.05, 0.7, 4.0};
  std::vector<double> t;
  for (int j = 0; j <= 600; ++j) t.push_back(0.01 * j);
  const double t_r = 0.337, delta = 1.7e-6, rate = delta / t_r;
  const Eigen::MatrixXd basis = maxwell_mode_responses(tau, t_r, delta, t);
  double worst = 0.0;
  for (std::size_t j = 0; j < t.size(); ++j) {
    CHECK(basis(static_cast<Eigen::Index>(j), 0) == doctest::Approx(rate * std::min(t[j], t_r)).epsilon(1e-14));
    for (std::size_t i = 0; i < tau.size(); ++i) {
      const double ramp_end = rate * tau[i] * -std::expm1(-std::min(t[j], t_r) / tau[i]);
      const double exact = t[j] <= t_r ? ramp_end : ramp_end * std::exp(-(t[j] - t_r) / tau[i]);
      worst = std::max(worst, std::abs(basis(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i + 1)) - exact) / delta);
    }
  }
  CHECK(worst < 1e-8);
}

TEST_CASE("simulator: noise is reproducible, of the stated size, and drift is linear") {
  RampHoldProtocol protocol;
  const SimulatedCurve clean = simulate_ramp_hold(wall, protocol);
  const SimulatedCurve noisy = simulate_ramp_hold(wall, protocol, {0.01, 0.0, 42});
  const SimulatedCurve again = simulate_ramp_hold(wall, protocol, {0.01, 0.0, 42});
  const SimulatedCurve other = simulate_ramp_hold(wall, protocol, {0.01, 0.0, 43});
  REQUIRE(noisy.force.size() == clean.force.size());
  CHECK(noisy.force == again.force);
  CHECK(noisy.force != other.force);
  double sum = 0.0, squares = 0.0;
  const auto n = static_cast<double>(clean.force.size());
  for (std::size_t j = 0; j < clean.force.size(); ++j) {
    const double e = (noisy.force[j] - clean.force[j]) / protocol.set_point;
    sum += e;
    squares += e * e;
  }
  // ~520 samples: the sample sd is within 10 % of 0.01 (about 3.6 of its standard errors),
  // the mean within 5 standard errors of 0.
  CHECK(std::sqrt(squares / n) == doctest::Approx(0.01).epsilon(0.10));
  CHECK(std::abs(sum / n) < 5.0 * 0.01 / std::sqrt(n));

  const SimulatedCurve drifting = simulate_ramp_hold(wall, protocol, {0.0, -2e-8, 1});
  for (std::size_t j = 0; j < clean.force.size(); ++j) {
    CHECK(drifting.force[j] - clean.force[j] == doctest::Approx(-2e-8 * clean.t[j]).epsilon(1e-9).scale(1e-20));
  }
}

TEST_CASE("noise: mt19937_64 as the standard fixes it, bits to double and Box-Muller as stated") {
  std::mt19937_64 reference(5489u);
  reference.discard(9999);
  CHECK(reference() == 9981545732273789042ull);  // [rand.predef]: the 10000th output

  std::mt19937_64 bits(7);
  GaussianNoise noise(7);
  const std::uint64_t a = bits(), b = bits();
  const double u1 = static_cast<double>((a >> 11) + 1) * 0x1p-53;
  const double u2 = static_cast<double>((b >> 11) + 1) * 0x1p-53;
  const double radius = std::sqrt(-2.0 * std::log(u1));
  CHECK(noise.normal() == radius * std::cos(2.0 * std::numbers::pi * u2));
  CHECK(noise.normal() == radius * std::sin(2.0 * std::numbers::pi * u2));

  // Moments and P(|Z| < 1) = erf(1/sqrt 2) = 0.6826894921370859 over 2e5 deviates, within
  // 5 standard errors.
  GaussianNoise gaussian(2024);
  const int n = 200000;
  double sum = 0.0, squares = 0.0, inside = 0.0;
  for (int i = 0; i < n; ++i) {
    const double z = gaussian.normal();
    sum += z;
    squares += z * z;
    inside += std::abs(z) < 1.0 ? 1.0 : 0.0;
  }
  CHECK(std::abs(sum / n) < 5.0 / std::sqrt(n));
  CHECK(std::abs(squares / n - 1.0) < 5.0 * std::sqrt(2.0 / n));
  const double p = 0.6826894921370859;
  CHECK(std::abs(inside / n - p) < 5.0 * std::sqrt(p * (1 - p) / n));
}

TEST_CASE("simulator: rejects models and protocols it cannot run") {
  RampHoldProtocol protocol;
  CHECK_THROWS_AS(simulate_ramp_hold({1.0, {1.0}, {-0.2}}, protocol), InputError);
  CHECK_THROWS_AS(simulate_ramp_hold({1.0, {}, {}}, protocol), InputError);
  // k_inf = 0: the force saturates at rate k tau = 1e-5 * 0.1 N = 1 uN < 5 uN set point.
  CHECK_THROWS_AS(simulate_ramp_hold({0.0, {1.0}, {0.1}}, protocol), InputError);
  protocol.sample_interval = 0.0;
  CHECK_THROWS_AS(simulate_ramp_hold(wall, protocol), InputError);
}

TEST_CASE("simulator: mode responses for ramps ending on, or ulps from, a sample and for vanishing ramps") {
  // Fitted ramp ends land anywhere, including within rounding of a sample time, where CVODE
  // refuses to start the hold ("tout too close to t0"), and next to 0 when the ramp is
  // shorter than a sample. The closed form (Duhamel's integral of the linear ODE) holds for
  // every ramp time; with phi(x) = -expm1(-x) / x, the ramp-end force is delta phi(t_r / tau)
  // and it tends to delta, the step, as t_r -> 0.
  const std::vector<double> tau{0.05, 0.2, 3.0};
  std::vector<double> t;
  for (int j = 0; j <= 300; ++j) t.push_back(0.02 * j);
  auto phi = [](double x) { return x > 0.0 ? -std::expm1(-x) / x : 1.0; };
  auto exact = [&](double tau_i, double t_r, double time) {
    if (time <= t_r) return time > 0.0 ? (time / t_r) * phi(time / tau_i) : 0.0;  // delta = 1
    return phi(t_r / tau_i) * std::exp(-(time - t_r) / tau_i);
  };
  std::vector<double> ramp_times{0.0, 5e-324, 1e-300, 1e-100, 1e-12, 0.003, 7.0};
  for (std::size_t j : {1, 2, 3, 150, 300}) {
    double below = t[j], above = t[j];
    ramp_times.push_back(t[j]);
    for (int ulps = 1; ulps <= 8; ++ulps) {
      below = std::nextafter(below, 0.0);
      above = std::nextafter(above, 10.0);
      ramp_times.push_back(below);
      ramp_times.push_back(above);
    }
  }
  for (double t_r : ramp_times) {
    CAPTURE(t_r);
    const Eigen::MatrixXd basis = maxwell_mode_responses(tau, t_r, 1.0, t);
    double worst = 0.0;
    for (std::size_t j = 0; j < t.size(); ++j) {
      const double u = t[j] >= t_r ? (t[j] > 0.0 ? 1.0 : 0.0) : t[j] / t_r;
      CHECK(basis(static_cast<Eigen::Index>(j), 0) == u);
      for (std::size_t i = 0; i < tau.size(); ++i) {
        worst = std::max(worst, std::abs(basis(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i + 1)) - exact(tau[i], t_r, t[j])));
      }
    }
    CHECK(worst < 1e-8);  // as for the ramp above: rtol 1e-10, global error a few tens of it
  }
}
