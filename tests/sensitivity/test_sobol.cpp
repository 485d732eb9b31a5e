// Sobol' indices of independent inputs (Eq. (S6), src/sensitivity/README.md) against the
// Ishigami function's closed-form first and total indices.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <span>

#include "growthuq/sensitivity/sobol.hpp"

using namespace growthuq;

TEST_CASE("Sobol indices (Saltelli first order, Jansen total): Ishigami's closed form") {
  // Y = sin X1 + a sin^2 X2 + b X3^4 sin X1, X_i ~ U(-pi, pi) independent, a = 7, b = 0.1:
  // V1 = (1 + b pi^4 / 5)^2 / 2, V2 = a^2 / 8, V13 = 8 b^2 pi^8 / 225 (Saltelli et al. 2008, 4.9);
  // T1 = (V1 + V13) / V, T2 = V2 / V, T3 = V13 / V.
  constexpr double a = 7, b = 0.1, pi = std::numbers::pi;
  const double pi4 = std::pow(pi, 4), pi8 = std::pow(pi, 8);
  const double v = a * a / 8 + b * pi4 / 5 + b * b * pi8 / 18 + 0.5;
  const double v1 = 0.5 * (1 + b * pi4 / 5) * (1 + b * pi4 / 5), v2 = a * a / 8, v13 = 8 * b * b * pi8 / 225;
  const double first[3] = {v1 / v, v2 / v, 0.0}, total[3] = {(v1 + v13) / v, v2 / v, v13 / v};
  CHECK(total[0] == doctest::Approx(0.5576).epsilon(1e-3));
  CHECK(total[2] == doctest::Approx(0.2437).epsilon(1e-3));
  const BatchModel ishigami = [](const Eigen::MatrixXd& x) {
    Eigen::MatrixXd y(x.rows(), 1);
    for (Eigen::Index j = 0; j < x.rows(); ++j) {
      y(j, 0) = std::sin(x(j, 0)) + a * std::pow(std::sin(x(j, 1)), 2) + b * std::pow(x(j, 2), 4) * std::sin(x(j, 0));
    }
    return y;
  };
  const Quantile uniform = [](std::span<const double> u, std::span<double> x) {
    for (std::size_t j = 0; j < u.size(); ++j) x[j] = -pi + 2 * pi * u[j];
  };
  const SobolIndices s = sobol_indices(ishigami, {uniform, uniform, uniform}, {.samples = 100000, .sections = 10, .key = 9});
  CHECK(s.model_runs == 500000);
  for (Eigen::Index i = 0; i < 3; ++i) {
    CAPTURE(i);
    MESSAGE("S_" << i + 1 << " " << s.first(i, 0) << " [" << s.first_low(i, 0) << ", " << s.first_high(i, 0) << "], exact "
                 << first[i] << "; T_" << i + 1 << " " << s.total(i, 0) << " [" << s.total_low(i, 0) << ", "
                 << s.total_high(i, 0) << "], exact " << total[i]);
    // At N = 1e5 the intervals' half widths are 0.005-0.02 (standard errors up to 0.01): 0.03 is
    // about 3 of the widest.
    CHECK(std::abs(s.first(i, 0) - first[i]) < 0.03);
    CHECK(std::abs(s.total(i, 0) - total[i]) < 0.03);
  }
}
