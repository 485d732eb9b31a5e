// Multifidelity estimates (Eqs. (T7)-(T9), src/stats/README.md): the limits that reduce them to
// a plain sample (M = N; a low fidelity equal to the high), and, on pairs of models whose
// high-fidelity mean and median are known exactly, unbiasedness, the variance reduction that
// rho^2 predicts, and the coverage of the three intervals over 1000 replications.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "growthuq/stats/multifidelity.hpp"

using namespace growthuq;

namespace {

// One replication: M samples of x ~ N(0, 1); h = high(x) on the first N, l = low(x) + noise on all.
template <class High, class Low>
MultifidelityEstimate replicate(std::mt19937_64& engine, std::size_t n, std::size_t m, High high, Low low, double noise) {
  std::normal_distribution<double> normal;
  std::vector<double> h(n), l(m);
  for (std::size_t j = 0; j < m; ++j) {
    const double x = normal(engine);
    l[j] = low(x) + noise * normal(engine);
    if (j < n) h[j] = high(x);
  }
  return estimate_multifidelity(h, std::span<const double>(l.data(), n), l);
}

struct Tally {
  std::vector<double> values;
  int covered = 0;
  void add(const IntervalEstimate& estimate, double truth) {
    values.push_back(estimate.estimate);
    if (estimate.low <= truth && truth <= estimate.high) ++covered;
  }
  double mean() const {
    double sum = 0;
    for (const double v : values) sum += v;
    return sum / static_cast<double>(values.size());
  }
  double variance() const {
    const double mu = mean();
    double sum = 0;
    for (const double v : values) sum += (v - mu) * (v - mu);
    return sum / static_cast<double>(values.size() - 1);
  }
  double coverage() const { return static_cast<double>(covered) / static_cast<double>(values.size()); }
};

constexpr int replications = 1000;
// 95 % nominal: a binomial count of 1000 has a standard error of 0.69 %; +-2.5 % is 3.6 of them.
constexpr double coverage_low = 0.925, coverage_high = 0.975;

}  // namespace

TEST_CASE("multifidelity: with M = N the estimates are the pairs' own") {
  const std::vector<double> h{3.0, 1.0, 4.0, 1.5, 5.0, 9.0, 2.0}, l{2.5, 1.2, 3.0, 1.0, 4.5, 7.0, 2.2};
  const MultifidelityEstimate estimate = estimate_multifidelity(h, l, l);
  CHECK(estimate.mean.estimate == doctest::Approx(25.5 / 7).epsilon(1e-14));  // the mean of h
  CHECK(estimate.bias.estimate == doctest::Approx((25.5 - 21.4) / 7).epsilon(1e-14));
  // The distribution function is h's own empirical one: the median is the 4th of 7.
  CHECK(estimate.quantile.estimate == doctest::Approx(3.0).epsilon(1e-12));
}

TEST_CASE("multifidelity: a low fidelity equal to the high one gives the M samples' own statistics") {
  const std::vector<double> all{0.3, 2.0, 1.1, 0.7, 5.0, 0.2, 1.9, 3.3, 0.9, 2.6, 1.4};
  const std::span<const double> pairs(all.data(), 4);
  const MultifidelityEstimate estimate = estimate_multifidelity(pairs, pairs, all);
  double sum = 0;
  for (const double v : all) sum += v;
  CHECK(estimate.alpha == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(estimate.correlation == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(estimate.bias.estimate == 0.0);
  CHECK(estimate.bias.standard_error == 0.0);
  CHECK(estimate.mean.estimate == doctest::Approx(sum / 11).epsilon(1e-14));
  CHECK(estimate.quantile.estimate == doctest::Approx(1.4).epsilon(1e-12));  // the 6th of the 11 sorted values
}

TEST_CASE("multifidelity: refuses what it cannot estimate") {
  const std::vector<double> two{1.0, 2.0}, three{1.0, 2.0, 3.0}, other{1.0, 2.0, 3.5};
  CHECK_THROWS_AS(estimate_multifidelity(two, two, two), std::invalid_argument);
  CHECK_THROWS_AS(estimate_multifidelity(three, three, two), std::invalid_argument);
  CHECK_THROWS_AS(estimate_multifidelity(three, three, other), std::invalid_argument);  // not the first N of M
  const std::vector<double> with_nan{1.0, std::nan(""), 3.0};
  CHECK_THROWS_AS(estimate_multifidelity(with_nan, three, three), std::invalid_argument);
}

TEST_CASE("multifidelity: Gaussian pair, a low fidelity at half the scale: unbiased, rho^2 reduction, coverage") {
  // h = 2 + x, l = 0.5 h + 0.1 + 0.2 e: mean = median of h = 2, bias E[h - l] = 0.9,
  // rho^2 = 0.25 / (0.25 + 0.04). The control-variate variance sigma_h^2 / N (1 - (1 - N/M) rho^2)
  // (Eq. (T8), src/stats/README.md) is 0.19 of the N pairs' alone.
  const std::size_t n = 30, m = 600;
  std::mt19937_64 engine(32);
  Tally mean, median, bias;
  double high_only_variance = 0;
  for (int r = 0; r < replications; ++r) {
    const MultifidelityEstimate estimate = replicate(
        engine, n, m, [](double x) { return 2.0 + x; }, [](double x) { return 0.5 * (2.0 + x) + 0.1; }, 0.2);
    mean.add(estimate.mean, 2.0);
    median.add(estimate.quantile, 2.0);
    bias.add(estimate.bias, 0.9);
    high_only_variance += estimate.high_only_standard_error * estimate.high_only_standard_error / replications;
  }
  const double rho2 = 0.25 / 0.29;
  const double predicted = 1.0 / n * (1.0 - (1.0 - static_cast<double>(n) / m) * rho2);
  MESSAGE("mean: average ", mean.mean(), ", variance ", mean.variance(), " (predicted ", predicted, "), coverage ",
          mean.coverage(), "; median: average ", median.mean(), ", coverage ", median.coverage(), "; bias coverage ",
          bias.coverage());
  // Unbiased: the average of 1000 estimates within 4 of its standard errors of the truth.
  CHECK(std::abs(mean.mean() - 2.0) < 4 * std::sqrt(mean.variance() / replications));
  CHECK(std::abs(bias.mean() - 0.9) < 4 * std::sqrt(bias.variance() / replications));
  CHECK(std::abs(median.mean() - 2.0) < 4 * std::sqrt(median.variance() / replications));
  // The variance as rho^2 predicts (1000 replications estimate a variance to +-4.5 %; the fitted
  // alpha adds about 1 / (N - 3) of the residual part), far below the pairs' alone.
  CHECK(mean.variance() == doctest::Approx(predicted).epsilon(0.15));
  CHECK(mean.variance() < 0.3 * high_only_variance);
  // The median too gains from the low fidelity: well below the sample median's pi / 2 sigma^2 / N.
  CHECK(median.variance() < 0.6 * (M_PI / 2) / n);
  for (const Tally* tally : {&mean, &median, &bias}) {
    CHECK(tally->coverage() >= coverage_low);
    CHECK(tally->coverage() <= coverage_high);
  }
}

TEST_CASE("multifidelity: skewed high fidelity, nonlinear low fidelity: unbiased and covered") {
  // h = exp(x / 2), lognormal: median 1, mean exp(1/8). l = 0.4 h^0.8 + 0.05 e, a fast model
  // about half as large and not proportional: the bias E[h - l] = exp(1/8) - 0.4 exp(0.08).
  const std::size_t n = 40, m = 800;
  std::mt19937_64 engine(2016);
  Tally mean, median, bias;
  for (int r = 0; r < replications; ++r) {
    const MultifidelityEstimate estimate = replicate(
        engine, n, m, [](double x) { return std::exp(0.5 * x); }, [](double x) { return 0.4 * std::exp(0.4 * x); }, 0.05);
    mean.add(estimate.mean, std::exp(0.125));
    median.add(estimate.quantile, 1.0);
    bias.add(estimate.bias, std::exp(0.125) - 0.4 * std::exp(0.08));
  }
  MESSAGE("mean: average ", mean.mean(), " (exact ", std::exp(0.125), "), coverage ", mean.coverage(),
          "; median: average ", median.mean(), ", coverage ", median.coverage(), "; bias coverage ", bias.coverage());
  CHECK(std::abs(mean.mean() - std::exp(0.125)) < 4 * std::sqrt(mean.variance() / replications));
  CHECK(std::abs(median.mean() - 1.0) < 4 * std::sqrt(median.variance() / replications));
  CHECK(std::abs(bias.mean() - (std::exp(0.125) - 0.4 * std::exp(0.08))) < 4 * std::sqrt(bias.variance() / replications));
  for (const Tally* tally : {&mean, &median, &bias}) {
    CHECK(tally->coverage() >= coverage_low);
    CHECK(tally->coverage() <= coverage_high);
  }
}
