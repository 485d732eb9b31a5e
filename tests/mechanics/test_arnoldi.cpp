// phi(x) = x K1(x)/K0(x) against 50-digit values, its derivative identity, monotonicity, and
// the round trip through its inverse.
#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

#include "growthuq/mechanics/arnoldi.hpp"

using namespace growthuq;

namespace {

struct Reference {
  double x;
  double phi;
};

double relative_error(double value, double reference) {
  return std::fabs(value - reference) / std::fabs(reference);
}

}  // namespace

TEST_CASE("phi matches 50-digit reference values to 1e-14") {
  // The table of src/mechanics/README.md (M13), then values from
  //   /usr/bin/python3 -c "import mpmath as mp; mp.mp.dps=50; x=mp.mpf('X');
  //                        print(mp.nstr(x*mp.besselk(1,x)/mp.besselk(0,x), 20))"
  // at points around the series switch (1e-5), the scaled-Bessel range and the large-x
  // expansion switch (1e8). 1e-14 is ~45 ulp: GSL's K0/K1 are accurate to a few ulp each.
  const std::vector<Reference> references{
      {1e-300, 1.4474053577798814e-3},  {1e-8, 5.3947290151765658e-2},
      {1e-3, 0.14237479286895749},      {0.1, 0.40599771496323273},
      {0.5, 0.89593625421611012},       {1.0, 1.4296253982604017},
      {2.0, 2.4560738596378160},        {10.0, 10.488587228891769},
      {700.0, 700.49982168310578},      {1e4, 10000.499987501249},
      {1e-100, 0.0043407593154084618642}, {1e-20, 0.021660196264897195203},
      {1e-12, 0.036039993770761194679},  {3e-6, 0.077925135507524113758},
      {9.999999e-6, 0.085992973551305208816}, {1e-5, 0.085992974290784392168},
      {1.0000001e-5, 0.085992975030263514291}, {2e-5, 0.091443538269224364499},
      {1e-4, 0.10722397546938863616},    {0.01, 0.21175325540662029887},
      {0.3, 0.66799583929138827597},     {3.0, 3.4677896392834905989},
      {30.0, 30.495965450800298457},     {100.0, 100.49876230864832338},
      {750.0, 750.49983355509387215},    {1e3, 1000.4998751248050927},
      {1e5, 100000.4999987500125},       {1e6, 1000000.4999998750001},
      {1e7, 10000000.4999999875},        {1e8, 100000000.49999999875},
      {1e10, 10000000000.5},
  };
  for (const Reference& reference : references) {
    CAPTURE(reference.x);
    CHECK(relative_error(arnoldi_phi(reference.x), reference.phi) < 1e-14);
  }
}

TEST_CASE("phi at the ends of the double range and outside its domain") {
  CHECK(arnoldi_phi(0.0) == 0.0);
  CHECK(std::isnan(arnoldi_phi(-1.0)));
  CHECK(std::isnan(arnoldi_phi(std::numeric_limits<double>::quiet_NaN())));
  CHECK(arnoldi_phi(std::numeric_limits<double>::infinity()) == std::numeric_limits<double>::infinity());
  // Subnormal x: the series still holds, phi = 1/(ln(2/x) - gamma) to double precision.
  const double tiny = std::numeric_limits<double>::denorm_min();
  CHECK(relative_error(arnoldi_phi(tiny), 1.0 / (std::log(2.0) - std::log(tiny) - 0.57721566490153286)) < 1e-15);
  CHECK(std::isfinite(arnoldi_phi(DBL_MAX)));
  CHECK(arnoldi_phi(DBL_MAX) == DBL_MAX);
}

TEST_CASE("phi is strictly increasing on a dense log grid from 1e-300 to 1e300") {
  // 60 points per decade: the grid step (4 %) is far above the rounding, so strict increase
  // is required everywhere.
  double previous_phi = 0.0;
  int strict_failures = 0;
  for (int i = -300 * 60; i <= 300 * 60; ++i) {
    const double x = std::pow(10.0, i / 60.0);
    const double phi = arnoldi_phi(x);
    REQUIRE(std::isfinite(phi));
    if (!(phi > previous_phi)) ++strict_failures;
    // K1 > K0 and K1/K0 < 1 + 1/(2x) (Segura 2011): 0 < phi - x < 1/2. phi - x is exact
    // (Sterbenz); phi itself carries a rounding of up to ~2 ulp of x, and from x = 2^53 on
    // x + 1/2 rounds to x.
    if (x < 0x1p52) CHECK(phi > x);
    CHECK(phi >= x);
    CHECK(phi - x < 0.5 + 4.0 * DBL_EPSILON * x);
    previous_phi = phi;
  }
  CHECK(strict_failures == 0);
}

TEST_CASE("phi'(x) = (phi^2 - x^2)/x agrees with a central finite difference") {
  // Central difference in x with step s = x * 1e-5: truncation ~ phi''' s^2 / 6 and rounding
  // ~ eps phi / s; both below 1e-8 relative of phi' for the points used here (phi' >= 1e-3
  // relative to phi/x down to x = 1e-250 where phi' ~ phi^2/x).
  for (double x : {1e-250, 1e-30, 1e-6, 2e-5, 1e-3, 0.1, 0.7, 1.0, 3.0, 25.0, 800.0, 1e5, 1e7, 1e9}) {
    CAPTURE(x);
    const double step = x * 1e-5;
    const double finite_difference = (arnoldi_phi(x + step) - arnoldi_phi(x - step)) / (2.0 * step);
    CHECK(relative_error(arnoldi_phi_derivative(x), finite_difference) < 1e-7);
  }
}

TEST_CASE("phi inverse round trips over the whole range") {
  for (int i = -300 * 20; i <= 300 * 20; ++i) {
    const double x = std::pow(10.0, i / 20.0);
    const double phi = arnoldi_phi(x);
    const double back = arnoldi_phi_inverse(phi);
    CAPTURE(x);
    // phi(back) must reproduce phi to a few ulp (the forward direction is well conditioned).
    CHECK(relative_error(arnoldi_phi(back), phi) < 8 * DBL_EPSILON);
    // x itself: relative condition number (phi / (x phi')) is ~ 1/phi for small x (up to ~700),
    // so x is recovered to ~1e-13 there and to a few ulp elsewhere.
    CHECK(relative_error(back, x) < 1e-12);
  }
}

TEST_CASE("phi inverse at the ends of its domain") {
  CHECK(arnoldi_phi_inverse(0.0) == 0.0);
  CHECK(std::isnan(arnoldi_phi_inverse(-0.1)));
  CHECK(std::isnan(arnoldi_phi_inverse(std::numeric_limits<double>::quiet_NaN())));
  CHECK(arnoldi_phi_inverse(std::numeric_limits<double>::infinity()) == std::numeric_limits<double>::infinity());
  // Below phi(denorm_min) = 1.3430823e-3 (mpmath) the root underflows to 0 (documented);
  // between it and phi(DBL_MIN) = 1.411408e-3 the root is subnormal.
  CHECK(arnoldi_phi_inverse(1.3e-3) == 0.0);
  const double subnormal = arnoldi_phi_inverse(1.38e-3);
  CHECK(subnormal > 0.0);
  CHECK(subnormal < DBL_MIN);
  CHECK(arnoldi_phi_inverse(1e-3) == 0.0);
  // Roots from 50 digits: mp.findroot(lambda x: x*mp.besselk(1,x)/mp.besselk(0,x) - P, 0.5)
  //   P = 1: 0.5950467264497842928850182, P = 0.5: 0.165721516183442573960156.
  // Tolerance 1e-14: the condition number phi/(x phi') is below 3 at these points.
  CHECK(relative_error(arnoldi_phi_inverse(1.0), 0.5950467264497842928850182) < 1e-14);
  CHECK(relative_error(arnoldi_phi_inverse(0.5), 0.165721516183442573960156) < 1e-14);
  CHECK(relative_error(arnoldi_phi_inverse(1.4296253982604017), 1.0) < 1e-14);
  CHECK(relative_error(arnoldi_phi_inverse(10000.499987501249), 1e4) < 1e-14);
}
