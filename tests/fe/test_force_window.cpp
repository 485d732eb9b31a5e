// The force-window fit against hand-computed lines and the exact least-squares slope of a
// parabola, and its independence of the load steps.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "fe/force_window.hpp"

using growthuq::fe::fit_force_window;
using growthuq::fe::WindowFitStatus;

TEST_CASE("force window: hand-computed line of a kinked curve") {
  // Window [1, 4] on (0,0) (1,1) (2,3) (3,4) (4,6): from x = 1 to 3, F = 3 + 2t (t < 0) and
  // 3 + t (t >= 0), t = x - 2, read at 2m + 1 = 101 equally spaced t_j = j/m. By hand:
  // sum t F = 2 S + S (S = sum_{j>0} t_j^2), sum t^2 = 2 S, so the slope is 3/2 for any m;
  // the mean F is 3 - (m + 1) / (2 (2m + 1)), so the intercept is -51/202 at m = 50.
  const std::vector<double> depth{0, 1, 2, 3, 4}, force{0, 1, 3, 4, 6};
  const auto fit = fit_force_window(depth, force, 1.0, 4.0);
  REQUIRE(fit.status == WindowFitStatus::ok);
  CHECK(fit.points == 101);
  CHECK(fit.slope == doctest::Approx(1.5).epsilon(1e-14));
  CHECK(fit.intercept == doctest::Approx(-51.0 / 202.0).epsilon(1e-13));
  CHECK(fit.low_depth == 1.0);
  CHECK(fit.top_depth == 3.0);
}

TEST_CASE("force window: a straight curve with uneven steps, the edges interpolated") {
  // F = 1 + 3 x at uneven depths: the line itself whatever the steps; the window [2.5, 7]
  // starts at x = 0.5 and ends at x = 2 (both between points).
  const std::vector<double> depth{0, 0.1, 0.45, 0.7, 1.3, 1.35, 2.6, 3.0};
  std::vector<double> force;
  for (double x : depth) force.push_back(1 + 3 * x);
  const auto fit = fit_force_window(depth, force, 2.5, 7.0);
  REQUIRE(fit.status == WindowFitStatus::ok);
  CHECK(fit.slope == doctest::Approx(3.0).epsilon(1e-14));
  CHECK(fit.intercept == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(fit.low_depth == doctest::Approx(0.5).epsilon(1e-15));
  CHECK(fit.top_depth == doctest::Approx(2.0).epsilon(1e-15));
}

TEST_CASE("force window: a parabola's exact least-squares slope, and no jump with the step") {
  // F = a x^2 read at equally spaced x from x0 to x1: for points symmetric about their mean
  // m, cov(x, x^2) = 2 m var(x), so the least-squares slope is exactly a (x0 + x1) for any
  // number of points. With a = 2, x0 = 0.5, x1 = 1.5: window [0.5, 4.5], slope 4.
  const double a = 2.0, x0 = 0.5, x1 = 1.5;
  for (double h : {0.25, 0.1, 0.0137, 0.00731, 0.00293}) {
    std::vector<double> depth, force;
    for (int i = 0; i * h < 2.0; ++i) {
      depth.push_back(i * h);
      force.push_back(a * i * h * i * h);
    }
    const auto fit = fit_force_window(depth, force, a * x0 * x0, a * x1 * x1);
    REQUIRE(fit.status == WindowFitStatus::ok);
    // The curve between its points is the chord, at most e = a h^2 / 4 above the parabola;
    // a least-squares slope moves by at most e sum|t| / sum t^2 -> 3 e / L for an error of
    // size e on a window of length L = x1 - x0 (and the passages move by e / F' too, within
    // the same order): the slope is within 3 a h^2 / 4 (x1 - x0) of 4. Raw solver points
    // instead would be off by O(h) (1.5e-3 relative at h = 0.00731, 70 times this bound).
    CHECK(std::abs(fit.slope - a * (x0 + x1)) <= 3 * a * h * h / (4 * (x1 - x0)));
    CHECK(std::abs(fit.low_depth - x0) <= h * h / (8 * x0));
    CHECK(std::abs(fit.top_depth - x1) <= h * h / (8 * x1));
  }
}

TEST_CASE("force window: statuses for a short curve and an unusable one") {
  const std::vector<double> depth{0, 1, 2}, force{0, 1, 2};
  const auto short_curve = fit_force_window(depth, force, 0.5, 2.5);
  CHECK(short_curve.status == WindowFitStatus::window_not_reached);
  CHECK(short_curve.max_force == 2.0);
  CHECK(fit_force_window(depth, force, 0.5, 2.0).status == WindowFitStatus::ok);  // the top is reached exactly
  CHECK(fit_force_window(depth, force, 2.0, 1.0).status == WindowFitStatus::invalid_curve);
  CHECK(fit_force_window(std::vector<double>{0}, std::vector<double>{0}, 0.0, 1.0).status == WindowFitStatus::invalid_curve);
  CHECK(fit_force_window(depth, std::vector<double>{0, 1}, 0.0, 1.0).status == WindowFitStatus::invalid_curve);
  CHECK(fit_force_window(depth, std::vector<double>{0, NAN, 2}, 0.0, 1.0).status == WindowFitStatus::invalid_curve);
  CHECK(fit_force_window(depth, std::vector<double>{3, 4, 5}, 0.0, 1.0).status == WindowFitStatus::invalid_curve);
  // A window from 0 starts at the first point.
  const auto from_zero = fit_force_window(depth, force, 0.0, 2.0);
  REQUIRE(from_zero.status == WindowFitStatus::ok);
  CHECK(from_zero.low_depth == 0.0);
  CHECK(from_zero.slope == doctest::Approx(1.0).epsilon(1e-15));
}
