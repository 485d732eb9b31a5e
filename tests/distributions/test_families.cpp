// The contract every distribution family keeps (Boost.Math style, one loop over instances of
// every family), and accuracy against mpmath reference values (reference_values.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/distributions/distribution.hpp"
#include "reference_values.hpp"

using namespace growthuq;

namespace {

constexpr double eps = DBL_EPSILON;
constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

// The u grid of the property checks: both deep tails, log-spaced, plus the centre.
std::vector<double> probability_grid() {
  std::vector<double> u;
  for (double e = -300; e < -0.31; e += 0.25) u.push_back(std::pow(10.0, e));
  const std::size_t lower = u.size();
  for (std::size_t i = 0; i < lower; ++i) u.push_back(1.0 - u[i]);  // rounds to 1 below 1e-16: skipped
  for (int i = 1; i < 100; ++i) u.push_back(i / 100.0);
  u.push_back(1.0 - 0x1p-53);
  std::sort(u.begin(), u.end());
  u.erase(std::unique(u.begin(), u.end()), u.end());
  while (!u.empty() && u.back() >= 1.0) u.pop_back();
  return u;
}

bool is_positive_law(const Distribution& d) {
  return std::holds_alternative<Lognormal>(d) || std::holds_alternative<Gamma>(d) ||
         std::holds_alternative<Weibull>(d);
}

}  // namespace

TEST_CASE("quantile, pdf and cdf against mpmath (40 digits)") {
  // Tolerances, in multiples of eps = 2^-52, as |computed - exact| <= tol * eps * scale:
  // - quantiles: scale = |x| (1 + |ln x|) for the positive laws, whose quantiles go through
  //   exp/pow, where an absolute error eps |ln x| in the exponent becomes a relative error of
  //   x; scale = |x| + sd-like spread for the others (so that x near 0 is held to an absolute
  //   bound). AS241 is accurate to ~1 eps relative (Wichura 1988), the lognormal's vector exp
  //   to 4 ulp, the gamma inverse is Newton-polished to a few eps; tol = 16 covers these with
  //   the few roundings of the composition.
  // - cdf: relative error; GSL's Phi and incomplete gamma are accurate to a few eps, but the
  //   standardization z = (g(x) - m)/s rounds z by ~eps |z|, amplified by |z f/F| ~ z^2 in
  //   the tail: scale ~ 1 + z^2, taken as F (2 + |ln F|) since |ln F| ~ z^2/2 in the normal
  //   tail, tol = 8 (plus half an ulp of 1 where F > 1/2 rounds near 1).
  // - pdf: the same amplification through exp(-z^2/2); scale = 1 + |ln pdf|, tol = 8.
  // Measured worst cases over these tables, in the units above: quantile 8.3 (gamma, shape
  // 0.5, u = 1e-150, where x = exp(2 ln(u Gamma(1.5))) carries the log-space rounding), pdf
  // 1.8, cdf 1.9.
  for (const auto& c : reference::cases()) {
    const std::string name = c.name;
    CAPTURE(name);
    const bool positive = is_positive_law(c.distribution);
    const double spread = quantile(c.distribution, 0.75) - quantile(c.distribution, 0.25);
    for (const auto& q : c.quantiles) {
      CAPTURE(q.u);
      const double x = quantile(c.distribution, q.u);
      const double scale = positive ? std::fabs(q.x) * (1.0 + std::fabs(std::log(q.x))) : std::fabs(q.x) + spread;
      CHECK(std::fabs(x - q.x) <= 16 * eps * scale);
    }
    for (const auto& p : c.points) {
      CAPTURE(p.x);
      const double f = pdf(c.distribution, p.x);
      const double F = cdf(c.distribution, p.x);
      CHECK(std::fabs(f - p.pdf) <= 8 * eps * p.pdf * (1.0 + std::fabs(std::log(p.pdf))));
      const double cdf_scale = p.cdf == 0.0 ? 0.0 : p.cdf * (2.0 + std::fabs(std::log(p.cdf)));
      CHECK(std::fabs(F - p.cdf) <= 8 * eps * cdf_scale + 0.5 * eps * (p.cdf > 0.5));
    }
  }
}

TEST_CASE("contract: probabilities outside [0, 1] are rejected, u = 0 and 1 are the support's ends") {
  for (const auto& c : reference::cases()) {
    const std::string name = c.name;
    CAPTURE(name);
    const Distribution& d = c.distribution;
    for (const double u : {-1e-300, -0.5, 1.0 + 2 * eps, 2.0, not_a_number, infinity, -infinity}) {
      CAPTURE(u);
      CHECK_THROWS_AS(quantile(d, u), InputError);
      std::vector<double> us{0.5, u, 0.25};
      std::vector<double> xs(3);
      CHECK_THROWS_AS(quantiles(d, us, xs), InputError);
    }
    const double lower = quantile(d, 0.0);
    const double upper = quantile(d, 1.0);
    CHECK(cdf(d, lower) == 0.0);
    CHECK(cdf(d, upper) == 1.0);
    CHECK(cdf(d, -infinity) == 0.0);
    CHECK(cdf(d, infinity) == 1.0);
    CHECK(pdf(d, -infinity) == 0.0);
    CHECK(pdf(d, infinity) == 0.0);
    if (std::isfinite(lower)) {
      const double below = lower - std::max(1.0, std::fabs(lower)) * 1e-9;
      CHECK(pdf(d, below) == 0.0);
      CHECK(cdf(d, below) == 0.0);
      CHECK(pdf(d, std::nextafter(lower, -infinity)) == 0.0);
    }
    if (std::isfinite(upper)) {
      const double above = upper + std::max(1.0, std::fabs(upper)) * 1e-9;
      CHECK(pdf(d, above) == 0.0);
      CHECK(cdf(d, above) == 1.0);
      CHECK(pdf(d, std::nextafter(upper, infinity)) == 0.0);
    }
    CHECK(std::isnan(cdf(d, not_a_number)));
  }
}

TEST_CASE("contract: quantile is finite and inside the support at both deep tails, and monotone") {
  const std::vector<double> u = probability_grid();
  for (const auto& c : reference::cases()) {
    const std::string name = c.name;
    CAPTURE(name);
    const Distribution& d = c.distribution;
    const bool continuous = !std::holds_alternative<Empirical>(d);
    const double lower = quantile(d, 0.0);
    const double upper = quantile(d, 1.0);
    double previous = lower;
    for (const double p : u) {
      const double x = quantile(d, p);
      CAPTURE(p);
      REQUIRE(std::isfinite(x));
      CHECK(x >= previous);
      CHECK(x <= upper);
      previous = x;
    }
    if (continuous && !std::isfinite(upper)) CHECK(quantile(d, 1.0 - 0x1p-53) < upper);
    // Strictly inside the support at the table's smallest u wherever the exact quantile is
    // above the end by more than rounding (a positive law's quantile may underflow to 0 only
    // when the exact value is below the smallest subnormal, e.g. shape 0.05 at u = 1e-150).
    const auto& first = c.quantiles.front();
    if (first.u > 0.0 && first.x - lower > 1e-15 * std::max(1.0, std::fabs(lower))) CHECK(quantile(d, first.u) > lower);
  }
}

TEST_CASE("contract: quantile(cdf(x)) == x across the support, deep tails included") {
  // x runs over quantiles of the grid; F = cdf(x) carries a relative error of a few eps,
  // which moves the quantile by F/f(x) times that (dx = dF / f), plus the quantile's own
  // rounding (|x| (1 + |ln x|), see the reference test). Points where F rounds to 0 or 1
  // carry no information and are skipped.
  const std::vector<double> u = probability_grid();
  for (const auto& c : reference::cases()) {
    const std::string name = c.name;
    CAPTURE(name);
    const Distribution& d = c.distribution;
    if (std::holds_alternative<Empirical>(d)) continue;  // checked exactly below
    // GSL's gamma cdf loses ~eps k ln k for large shapes (gamma.hpp); that case's quantiles
    // are checked against mpmath in the reference test instead.
    if (const auto* gamma = std::get_if<Gamma>(&d); gamma && gamma->shape() > 100) continue;
    const double spread = quantile(d, 0.75) - quantile(d, 0.25);
    for (const double p : u) {
      const double x = quantile(d, p);
      const double F = cdf(d, x);
      if (F <= 0.0 || F >= 1.0 || x == 0.0) continue;
      CAPTURE(p);
      CAPTURE(x);
      const double back = quantile(d, F);
      const double own = std::fabs(x) * (1.0 + std::fabs(std::log(std::fabs(x)))) + spread * 1e-3;
      CHECK(std::fabs(back - x) <= 32 * eps * (own + F / pdf(d, x)));
    }
  }
  const Empirical empirical({2.5, 1.0, 4.0, 2.5, 7.0});
  for (const double x : {1.0, 1.3, 2.49, 2.5, 3.9, 6.99}) CHECK(quantile(empirical, cdf(empirical, x)) == doctest::Approx(x).epsilon(4 * eps));
}

TEST_CASE("contract: the batch quantile equals the scalar one bit for bit") {
  const std::vector<double> u = probability_grid();
  std::vector<double> x(u.size());
  for (const auto& c : reference::cases()) {
    const std::string name = c.name;
    CAPTURE(name);
    quantiles(c.distribution, u, x);
    for (std::size_t i = 0; i < u.size(); ++i) REQUIRE(x[i] == quantile(c.distribution, u[i]));
  }
  std::vector<double> shorter(3);
  CHECK_THROWS_AS(quantiles(Normal(0, 1), u, shorter), std::invalid_argument);
}

TEST_CASE("contract: NaN, infinite and out-of-domain parameters are rejected, naming the parameter") {
  const std::vector<std::pair<std::function<void()>, const char*>> bad{
      {[] { (void)Lognormal(not_a_number, 1); }, "lognormal: mu = 'nan': expected a finite number"},
      {[] { (void)Lognormal(0, infinity); }, "lognormal: sigma = 'inf': expected a positive finite number"},
      {[] { (void)Lognormal(0, 0); }, "lognormal: sigma = '0': expected a positive finite number"},
      {[] { (void)Lognormal::from_median_iqr(-2, 1); }, "lognormal: median = '-2': expected a positive finite number"},
      {[] { (void)Lognormal::from_median_iqr(2, -0.3); }, "lognormal: iqr = '-0.3': expected a positive finite number"},
      {[] { (void)Lognormal::from_median_iqr(2, not_a_number); }, "lognormal: iqr = 'nan': expected a positive finite number"},
      {[] { (void)Normal(infinity, 1); }, "normal: mean = 'inf': expected a finite number"},
      {[] { (void)Normal(0, -1); }, "normal: sd = '-1': expected a positive finite number"},
      {[] { (void)Normal(0, not_a_number); }, "normal: sd = 'nan': expected a positive finite number"},
      {[] { (void)TruncatedNormal(0, 1, not_a_number, 1); }, "truncated_normal: lower = 'nan': expected a number or -inf"},
      {[] { (void)TruncatedNormal(0, 1, -1, not_a_number); }, "truncated_normal: upper = 'nan': expected a number or inf"},
      {[] { (void)TruncatedNormal(0, 1, 2, 1); }, "truncated_normal: upper = '1': expected a number above lower = 2"},
      {[] { (void)TruncatedNormal(0, infinity, 0, 1); }, "truncated_normal: sd = 'inf': expected a positive finite number"},
      {[] { (void)TruncatedNormal(0, 1, 40, 41); }, nullptr},
      {[] { (void)Uniform(1, 1); }, "uniform: upper = '1': expected a number above lower = 1"},
      {[] { (void)Uniform(-infinity, 1); }, "uniform: lower = '-inf': expected a finite number"},
      {[] { (void)Gamma(0, 1); }, "gamma: shape = '0': expected a positive finite number"},
      {[] { (void)Gamma(1, infinity); }, "gamma: scale = 'inf': expected a positive finite number"},
      {[] { (void)Weibull(not_a_number, 1); }, "weibull: shape = 'nan': expected a positive finite number"},
      {[] { (void)Weibull(1, -2); }, "weibull: scale = '-2': expected a positive finite number"},
      {[] { (void)Beta(0, 1); }, "beta: alpha = '0': expected a positive finite number"},
      {[] { (void)Beta(1, not_a_number); }, "beta: beta = 'nan': expected a positive finite number"},
      {[] { (void)Beta(1, 1, -100); }, "beta: upper = '-100': expected a positive finite number"},
      {[] { (void)Empirical({1.0}); }, nullptr},
      {[] { (void)Empirical({2.0, 2.0, 2.0}); }, nullptr},
      {[] { (void)Empirical({1.0, not_a_number}); }, "empirical: values[2] = 'nan': expected a finite number"},
  };
  for (const auto& [construct, message] : bad) {
    CAPTURE(message);
    if (message) {
      CHECK_THROWS_WITH_AS(construct(), message, InputError);
    } else {
      CHECK_THROWS_AS(construct(), InputError);
    }
  }
  // Windows far in either tail are fine while they hold > 1e-300 of the parent's mass. Median
  // of N(0,1) on [30, 31] (mpmath, 40 digits: bisection of Q(30) - Q(x) = (Q(30) - Q(31))/2).
  CHECK(quantile(TruncatedNormal(0, 1, 30, 31), 0.5) == doctest::Approx(30.023070467827308926).epsilon(16 * eps));
  CHECK(quantile(TruncatedNormal(0, 1, -31, -30), 0.5) == doctest::Approx(-30.023070467827308926).epsilon(16 * eps));
}

TEST_CASE("lognormal from median and IQR reproduces them (Eq. D1)") {
  for (const auto& [m, r] : std::vector<std::pair<double, double>>{{2.87, 0.83}, {145, 31}, {0.028, 0.011}, {1e-3, 5e-2}}) {
    const Lognormal law = Lognormal::from_median_iqr(m, r);
    CHECK(quantile(law, 0.5) == doctest::Approx(m).epsilon(4 * eps));
    CHECK(quantile(law, 0.75) - quantile(law, 0.25) == doctest::Approx(r).epsilon(16 * eps * (1 + 2 * m / r)));
    CHECK(law.iqr() == doctest::Approx(r).epsilon(8 * eps));
  }
}

TEST_CASE("beta quantile against closed forms: Beta(1, 1) is uniform, Beta(a, 1) is u^(1/a), Beta(1, b) is 1 - (1 - u)^(1/b)") {
  for (const double u : {1e-12, 0.01, 0.3, 0.5, 0.77, 0.999}) {
    CAPTURE(u);
    CHECK(quantile(Beta(1, 1), u) == doctest::Approx(u).epsilon(1e-14));
    CHECK(quantile(Beta(1, 1, 100), u) == doctest::Approx(100 * u).epsilon(1e-14));
    CHECK(quantile(Beta(3.5, 1), u) == doctest::Approx(std::pow(u, 1 / 3.5)).epsilon(1e-14));
    CHECK(quantile(Beta(1, 2.5), u) == doctest::Approx(-std::expm1(std::log1p(-u) / 2.5)).epsilon(1e-13));
    CHECK(cdf(Beta(3.5, 1, 100), 100 * std::pow(u, 1 / 3.5)) == doctest::Approx(u).epsilon(1e-13));
  }
  // Beta(0.5, 0.5), the arcsine law: F^-1(u) = sin^2(pi u / 2).
  for (const double u : {0.05, 0.3, 0.9}) {
    CHECK(quantile(Beta(0.5, 0.5), u) == doctest::Approx(std::pow(std::sin(std::numbers::pi * u / 2), 2)).epsilon(1e-13));
  }
  // scipy 1.10.1 (Debian 12), scipy.stats.beta.ppf(0.75, 30, 15) and .ppf(0.2, 0.7, 3):
  CHECK(quantile(Beta(30, 15), 0.75) == doctest::Approx(0.7154461097620011).epsilon(1e-13));
  CHECK(quantile(Beta(0.7, 3), 0.2) == doctest::Approx(0.031795261094028804).epsilon(1e-13));
}

TEST_CASE("family_name and describe") {
  CHECK(describe(Distribution(Beta(2, 5, 100))) == "beta(alpha=2, beta=5, upper=100)");
  CHECK(family_name(Distribution(Gamma(2, 3))) == "gamma");
  CHECK(family_name(Distribution(TruncatedNormal(0, 1, 0, 1))) == "truncated_normal");
  CHECK(describe(Distribution(Weibull(1.5, 2))) == "weibull(shape=1.5, scale=2)");
  CHECK(describe(Distribution(Normal(1, 0.25))) == "normal(mean=1, sd=0.25)");
}

TEST_CASE("parameter_values: the parameters describe() rounds, as the exact doubles") {
  using Parameters = std::vector<std::pair<std::string, double>>;
  // 25.950912345 prints as 25.9509 in describe(): the numbers keep every digit.
  CHECK(parameter_values(Distribution(Gamma(25.950912345, 0.10752412345))) ==
        Parameters{{"shape", 25.950912345}, {"scale", 0.10752412345}});
  CHECK(describe(Distribution(Gamma(25.950912345, 0.10752412345))) == "gamma(shape=25.9509, scale=0.107524)");
  CHECK(parameter_values(Distribution(Lognormal(-1.25, 0.3))) == Parameters{{"mu", -1.25}, {"sigma", 0.3}});
  CHECK(parameter_values(Distribution(TruncatedNormal(0.5, 2, 0, 1))) ==
        Parameters{{"mean", 0.5}, {"sd", 2}, {"lower", 0}, {"upper", 1}});
  CHECK(parameter_values(Distribution(Empirical({3, 1, 2, 7}))) == Parameters{{"n", 4}, {"min", 1}, {"max", 7}});
  CHECK(describe(Distribution(Empirical({3, 1, 2, 7}))) == "empirical(n=4, min=1, max=7)");
}
