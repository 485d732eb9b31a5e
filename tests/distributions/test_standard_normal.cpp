// The inlined AS241 (src/distributions/as241.hpp) against GSL's gsl_cdf_ugaussian_Pinv, which
// implements the same algorithm: they must agree to a few ulps everywhere, tails included.
#include <doctest/doctest.h>

#include <gsl/gsl_cdf.h>

#include <cmath>
#include <limits>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/distributions/standard_normal.hpp"
#include "support/ulps.hpp"

using namespace growthuq;
using namespace growthuq::testing;

TEST_CASE("standard normal quantile equals GSL's AS241 to 2 ulps on a dense grid, both tails") {
  // Same coefficients and the same evaluation order as GSL, so agreement is expected to be
  // exact; 2 ulps allows for a compiler contracting a multiply-add differently.
  std::vector<double> u;
  for (double e = -323.0; e < 0.0; e += 0.0005) {
    const double p = std::pow(10.0, e);
    u.insert(u.end(), {p, 1.0 - p, 0.5 + 0.5 * p, 0.5 - 0.5 * p, 0.075 * (1 + p), 0.925 * (1 - p)});
  }
  for (int i = 1; i < 100000; ++i) u.push_back(i / 100000.0);
  u.push_back(std::numeric_limits<double>::denorm_min());
  u.push_back(std::exp(-25.0));  // r = 5 exactly: the boundary of the two tail branches
  std::vector<double> x(u.size());
  standard_normal_quantiles(u, x);
  double worst = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (!(u[i] > 0.0 && u[i] < 1.0)) continue;
    const double reference = gsl_cdf_ugaussian_Pinv(u[i]);
    worst = std::max(worst, ulps_apart(x[i], reference));
    REQUIRE(x[i] == standard_normal_quantile(u[i]));
  }
  CHECK(worst <= 2.0);
  MESSAGE("worst disagreement with GSL: " << worst << " ulps over " << u.size() << " points");
}

TEST_CASE("standard normal quantile: closed-form points, symmetry, ends, bad input") {
  CHECK(standard_normal_quantile(0.5) == 0.0);
  CHECK(standard_normal_quantile(0.0) == -HUGE_VAL);
  CHECK(standard_normal_quantile(1.0) == HUGE_VAL);
  // Phi^-1(0.975) = 1.959963984540054 (mpmath: mp.dps=30; print(sqrt(2)*erfinv(0.95)))
  CHECK(standard_normal_quantile(0.975) == doctest::Approx(1.959963984540054).epsilon(2e-16));
  // Phi^-1(1e-300) (mpmath: mp.dps=30; findroot(lambda z: log(ncdf(z)) + 300*log(10), -37))
  CHECK(standard_normal_quantile(1e-300) == doctest::Approx(-37.0470962993611992).epsilon(4e-16));
  // Symmetry through the upper-tail route: for dyadic p, 1 - p is exact, and the upper tail
  // must keep every digit of it (a 1 - u computed as 1 - (1 - p) would lose them).
  for (const double p : {0x1p-52, 0x1p-30, 0x1p-10, 0.3125}) {
    CHECK(standard_normal_quantile(1.0 - p) == -standard_normal_quantile(p));
  }
  CHECK_THROWS_WITH_AS(standard_normal_quantile(1.5), "standard normal quantile: u = '1.5': expected a probability in [0, 1]", InputError);
  CHECK_THROWS_AS(standard_normal_quantile(std::nan("")), InputError);
}
