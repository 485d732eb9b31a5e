// The lognormal quantile's exp (src/distributions/vector_exp.hpp, Cephes' algorithm written to
// vectorize) against the C library's exp: within 2 ulps over the whole double range and on the
// arguments a lognormal quantile produces, exact at the ends, and the batch form equal to the
// scalar one bit for bit.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "distributions/vector_exp.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "support/ulps.hpp"

using namespace growthuq;
using namespace growthuq::testing;

TEST_CASE("Cephes exp is within 2 ulps of std::exp; batch equals scalar") {
  RandomStream stream(derive_key(5, "exp"));
  std::vector<double> x;
  for (int i = 0; i < 400000; ++i) {
    x.push_back(-745.0 + 1454.7 * stream.uniform());      // the whole range with normal results
    x.push_back(3.0 * (stream.uniform() - 0.5) * 30.0);  // mu + sigma z of lognormal quantiles
  }
  std::vector<double> y(x.size());
  detail::exp_affine(x.data(), y.data(), x.size(), 0.0, 1.0);
  double worst = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    REQUIRE(y[i] == detail::cephes_exp(x[i]));
    worst = std::max(worst, ulps_apart(y[i], std::exp(x[i])));
  }
  MESSAGE("worst distance from std::exp: " << worst << " ulps over " << x.size() << " arguments");
  CHECK(worst <= 2.0);
}

TEST_CASE("Cephes exp at the ends of the double range") {
  CHECK(detail::cephes_exp(0.0) == 1.0);
  CHECK(detail::cephes_exp(-HUGE_VAL) == 0.0);
  CHECK(detail::cephes_exp(HUGE_VAL) == HUGE_VAL);
  CHECK(detail::cephes_exp(709.79) == HUGE_VAL);  // ln(DBL_MAX) = 709.7827...
  CHECK(detail::cephes_exp(709.78) == std::exp(709.78));
  CHECK(detail::cephes_exp(-745.2) == 0.0);  // below half the smallest subnormal
  // Subnormal results are rounded once (two power-of-two factors, the first exact).
  for (const double x : {-745.1, -744.44, -740.0, -720.5, -708.4}) {
    CAPTURE(x);
    CHECK(ulps_apart(detail::cephes_exp(x), std::exp(x)) <= 1.0);
  }
  CHECK(std::isnan(detail::cephes_exp(std::numeric_limits<double>::quiet_NaN())));
}
