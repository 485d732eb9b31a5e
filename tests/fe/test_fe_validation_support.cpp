// The validation helpers on inputs with known answers: the window slope of an exact line and of
// a line with a quadratic term, Richardson's order and limit of an exact power-law sequence.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "fe_validation_support.hpp"

using growthuq::testing::richardson;
using growthuq::testing::window_slope;

TEST_CASE("the window slope fits only the samples inside the force window") {
  std::vector<double> depth, force;
  for (int i = 0; i <= 40; ++i) {
    const double d = 0.01 * i;
    depth.push_back(d);
    // Slope 2 for d in [0.1, 0.3] (forces 0.3 to 0.7), other slopes outside with forces
    // outside [0.3, 0.7] (below 0.05 before, above 10 after): only the line may count.
    force.push_back(d < 0.1 - 1e-9 ? 0.5 * d : d > 0.3 + 1e-9 ? 10.0 + 3.0 * d : 2.0 * d + 0.1);
  }
  CHECK(window_slope(depth, force, 0.3, 0.7) == doctest::Approx(2.0).epsilon(1e-12));
  CHECK(std::isnan(window_slope(depth, force, 100.0, 200.0)));
}

TEST_CASE("Richardson extrapolation recovers the order and limit of q = q_inf + C h^p") {
  const double ratio = std::sqrt(2.0), q_inf = 3.7, c = -0.9, p = 1.6;
  auto q = [&](double h) { return q_inf + c * std::pow(h, p); };
  const double h = 0.2;
  const auto r = richardson(q(h), q(h / ratio), q(h / (ratio * ratio)), ratio);
  CHECK(r.order == doctest::Approx(p).epsilon(1e-10));
  CHECK(r.limit == doctest::Approx(q_inf).epsilon(1e-12));
  // Differences that grow or change sign: no asymptotic range, no order.
  CHECK(std::isnan(richardson(1.0, 1.1, 1.0, ratio).order));
  CHECK(std::isnan(richardson(1.0, 1.1, 1.3, ratio).order));
}
