#include "growthuq/sensitivity/sobol.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gsl/gsl_cdf.h>

#include "growthuq/sampling/random_stream.hpp"

namespace growthuq {
namespace {

// Design `name` (A or B): N x d inputs from independent uniforms through the marginals.
Eigen::MatrixXd design(const std::vector<Quantile>& marginals, std::size_t n, std::uint64_t key, const char* name) {
  const std::size_t d = marginals.size();
  Eigen::MatrixXd x(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(d));
  std::vector<double> u(n);
  for (std::size_t i = 0; i < d; ++i) {
    const std::uint64_t column = derive_key(key, std::string(name) + " " + std::to_string(i));
    for (std::size_t j = 0; j < n; ++j) u[j] = uniform_open(column, j);
    marginals[i](u, std::span<double>(x.col(static_cast<Eigen::Index>(i)).data(), n));
  }
  return x;
}

}  // namespace

SobolIndices sobol_indices(const BatchModel& model, const std::vector<Quantile>& marginals, const SobolSettings& settings) {
  const std::size_t d = marginals.size(), n = settings.samples, k = settings.sections;
  if (d < 2 || k < 2 || n < 2 * k) throw std::invalid_argument("sobol_indices: 2 inputs, 2 sections and 2 samples per section at least");
  const Eigen::MatrixXd a = design(marginals, n, settings.key, "A");
  const Eigen::MatrixXd b = design(marginals, n, settings.key, "B");
  // All runs at once: A, B, then A with column i from B (A_B^i) for each i.
  Eigen::MatrixXd rows(static_cast<Eigen::Index>(n * (d + 2)), static_cast<Eigen::Index>(d));
  const auto block = [&](std::size_t which) { return rows.middleRows(static_cast<Eigen::Index>(which * n), static_cast<Eigen::Index>(n)); };
  block(0) = a;
  block(1) = b;
  for (std::size_t i = 0; i < d; ++i) {
    block(2 + i) = a;
    block(2 + i).col(static_cast<Eigen::Index>(i)) = b.col(static_cast<Eigen::Index>(i));
  }
  const Eigen::MatrixXd y = model(rows);
  if (y.rows() != rows.rows() || y.cols() < 1) throw std::invalid_argument("sobol_indices: the model returned the wrong shape");
  const Eigen::Index m = y.cols();
  const auto at = [&](std::size_t which, std::size_t j, Eigen::Index o) { return y(static_cast<Eigen::Index>(which * n + j), o); };

  SobolIndices result;
  result.model_runs = static_cast<std::size_t>(rows.rows());
  const double t = gsl_cdf_tdist_Pinv(0.975, static_cast<double>(k - 1));
  for (auto* matrix : {&result.first, &result.first_low, &result.first_high, &result.total, &result.total_low, &result.total_high}) {
    matrix->resize(static_cast<Eigen::Index>(d), m);
  }
  for (Eigen::Index o = 0; o < m; ++o) {
    for (std::size_t i = 0; i < d; ++i) {
      // Per section: Var(Y) over f(A) and f(B), then (S6)
      //   V_i = (1/N) sum f(B) (f(A_B^i) - f(A))            (Saltelli et al. 2010, Table 2 (b)),
      //   T_i = (1/2N) sum (f(A) - f(A_B^i))^2 / Var(Y)      (Jansen 1999),
      // over the rows where the three outputs are finite.
      std::vector<double> first(k), total(k);
      for (std::size_t section = 0; section < k; ++section) {
        double sum = 0, squares = 0, v_first = 0, v_total = 0;
        std::size_t count = 0;
        for (std::size_t j = section * n / k; j < (section + 1) * n / k; ++j) {
          const double fa = at(0, j, o), fb = at(1, j, o), fab = at(2 + i, j, o);
          if (!std::isfinite(fa) || !std::isfinite(fb) || !std::isfinite(fab)) continue;
          ++count;
          sum += fa + fb;
          squares += fa * fa + fb * fb;
          v_first += fb * (fab - fa);
          v_total += 0.5 * (fa - fab) * (fa - fab);
        }
        const double rows_used = static_cast<double>(count);
        const double mean = sum / (2 * rows_used);
        const double variance = squares / (2 * rows_used) - mean * mean;
        first[section] = v_first / rows_used / variance;
        total[section] = v_total / rows_used / variance;
      }
      const auto sectioned = [&](const std::vector<double>& values, Eigen::MatrixXd& estimate, Eigen::MatrixXd& low,
                                 Eigen::MatrixXd& high) {
        double mean = 0, squares = 0;
        for (const double v : values) mean += v / static_cast<double>(k);
        for (const double v : values) squares += (v - mean) * (v - mean);
        const double half = t * std::sqrt(squares / static_cast<double>(k - 1) / static_cast<double>(k));
        const auto r = static_cast<Eigen::Index>(i);
        estimate(r, o) = mean;
        low(r, o) = mean - half;
        high(r, o) = mean + half;
      };
      sectioned(first, result.first, result.first_low, result.first_high);
      sectioned(total, result.total, result.total_low, result.total_high);
    }
  }
  return result;
}

}  // namespace growthuq
