// The 1-D root in E on one dimensionless force curve: exact for a straight curve, a round trip
// on a stiffening one, and statuses when the curve cannot serve the window.
#include <doctest/doctest.h>

#include <vector>

#include "fe/modulus_from_curve.hpp"

using growthuq::fe::curve_stiffness;
using growthuq::fe::match_modulus;
using growthuq::fe::ModulusMatchStatus;

namespace {

// G = c1 x + c2 x^2 on x = delta/d0 in [0, x_max].
void stiffening_curve(double c1, double c2, double x_max, int points, std::vector<double>& depth,
                      std::vector<double>& force) {
  for (int i = 0; i <= points; ++i) {
    const double x = x_max * i / points;
    depth.push_back(x);
    force.push_back(c1 * x + c2 * x * x);
  }
}

constexpr double d0 = 5.35e-6, low = 0.4e-6, high = 4e-6;

}  // namespace

TEST_CASE("modulus from a curve: a straight curve gives E = k / (d0 G')") {
  std::vector<double> depth, force;
  stiffening_curve(0.02, 0.0, 0.5, 50, depth, force);
  // k = E d0 G' for every window: k = 2 N/m -> E = 2 / (5.35e-6 * 0.02) = 18.69 MPa.
  const auto match = match_modulus(depth, force, 2.0, d0, low, high, 5e6);
  REQUIRE(match.status == ModulusMatchStatus::ok);
  CHECK(match.young == doctest::Approx(2.0 / (d0 * 0.02)).epsilon(1e-9));
  CHECK(match.fitted_stiffness == doctest::Approx(2.0).epsilon(1e-9));
}

TEST_CASE("modulus from a curve: round trip on a stiffening curve, from estimates on both sides") {
  std::vector<double> depth, force;
  stiffening_curve(0.01, 0.3, 0.6, 300, depth, force);
  for (double young : {3e6, 30e6, 300e6}) {
    const double k = curve_stiffness(depth, force, young, d0, low, high);
    REQUIRE(k > 0);
    for (double estimate : {young / 7.0, young * 9.0}) {
      const auto match = match_modulus(depth, force, k, d0, low, high, estimate);
      REQUIRE(match.status == ModulusMatchStatus::ok);
      // Brent stops at a relative bracket of 1e-10 in E; k(E) is smooth there: 1e-9.
      CHECK(match.young == doctest::Approx(young).epsilon(1e-9));
    }
  }
}

TEST_CASE("modulus from a curve: a curve too short for the window, and bad input") {
  std::vector<double> depth, force;
  stiffening_curve(0.01, 0.3, 0.6, 300, depth, force);
  // Largest G = 0.006 + 0.108 = 0.114: the window top 4 uN needs E >= 4e-6 / (d0^2 0.114) =
  // 1.23 MPa. A k that only a softer wall gives (k(E_min) is the smallest k served):
  const double least = 4e-6 / (d0 * d0 * 0.114);
  const double k_least = curve_stiffness(depth, force, least * 1.001, d0, low, high);
  const auto short_match = match_modulus(depth, force, 0.5 * k_least, d0, low, high, 10e6);
  CHECK(short_match.status == ModulusMatchStatus::curve_too_short);
  CHECK(short_match.least_young == doctest::Approx(least).epsilon(1e-9));
  CHECK(match_modulus(depth, force, -1.0, d0, low, high, 10e6).status == ModulusMatchStatus::invalid_input);
  CHECK(match_modulus(depth, force, 1.0, d0, high, low, 10e6).status == ModulusMatchStatus::invalid_input);
}
