// The residual kriging of fidelity corrected (growthuq/correction/residual_kriging.hpp) on
// functions whose answer is known: it reproduces its data, predicts a smooth function between
// them to the accuracy the data's spacing allows, and its likeliest length scales tell a
// coordinate the function depends on from one it ignores.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "correction/kriging_fit.hpp"

using namespace growthuq;

namespace {

// A smooth function of two coordinates in [-1, 1] that ignores the second when `flat`.
double smooth(double x, double y, bool flat) { return 0.03 * std::sin(2.0 * x) + (flat ? 0.0 : 0.02 * std::cos(1.5 * y)); }

// Points of a 2D Halton sequence (bases 2 and 3) scaled onto [-1, 1]^2.
std::vector<double> halton_points(int n) {
  const auto radical_inverse = [](int i, int base) {
    double f = 1.0, r = 0.0;
    for (; i > 0; i /= base) {
      f /= base;
      r += f * (i % base);
    }
    return r;
  };
  std::vector<double> points;
  for (int i = 1; i <= n; ++i) {
    points.push_back(2.0 * radical_inverse(i, 2) - 1.0);
    points.push_back(2.0 * radical_inverse(i, 3) - 1.0);
  }
  return points;
}

}  // namespace

TEST_CASE("the kriging reproduces its data and predicts a smooth function between them") {
  const std::vector<double> points = halton_points(80);
  std::vector<double> values;
  for (std::size_t i = 0; i < points.size(); i += 2) values.push_back(smooth(points[i], points[i + 1], false));
  const KrigingHyperparameters hyperparameters = likeliest_hyperparameters(points, 2, values);
  const ResidualKriging kriging = fit_kriging(points, 2, values, hyperparameters);
  REQUIRE(kriging.size() == values.size());
  // At its own points: within the noise it assumed (a floor of 1e-4 on exact data).
  for (std::size_t c = 0; c < values.size(); ++c) {
    CHECK(std::abs(kriging.value({&points[2 * c], 2}) - values[c]) < 3 * hyperparameters.noise_sd + 1e-6);
  }
  // Between them (a 21 x 21 grid inside the box): the function to 1e-4 of its 0.05 range.
  double largest = 0.0;
  for (int i = 0; i <= 20; ++i) {
    for (int j = 0; j <= 20; ++j) {
      const double z[2] = {-0.9 + 0.09 * i, -0.9 + 0.09 * j};
      largest = std::max(largest, std::abs(kriging.value(z) - smooth(z[0], z[1], false)));
    }
  }
  CHECK(largest < 1e-4);
}

TEST_CASE("the likeliest length scales separate a coordinate the function ignores") {
  const std::vector<double> points = halton_points(60);
  std::vector<double> values;
  for (std::size_t i = 0; i < points.size(); i += 2) values.push_back(smooth(points[i], points[i + 1], true));
  const KrigingHyperparameters h = likeliest_hyperparameters(points, 2, values);
  REQUIRE(h.length_scales.size() == 2);
  // sin(2x) varies over about half the box; the ignored y has no scale at all.
  CHECK(h.length_scales[0] > 0.2);
  CHECK(h.length_scales[0] < 2.0);
  CHECK(h.length_scales[1] > 5 * h.length_scales[0]);
}

TEST_CASE("no centres, no correction") {
  const ResidualKriging empty;
  const double z[2] = {0.3, -0.2};
  CHECK(empty.value(z) == 0.0);
}
