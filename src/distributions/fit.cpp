#include "growthuq/distributions/fit.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_gamma.h>
#include <gsl/gsl_sf_psi.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "distributions/checks.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/stats/goodness_of_fit.hpp"

namespace growthuq {
namespace {

std::string location_of(FitFamily family) { return "fit " + std::string(to_string(family)); }

// Root of f in [lower, upper] (f(lower), f(upper) of opposite signs) by GSL's Brent solver,
// to a relative width of 1e-14.
double brent_root(const std::function<double(double)>& f, double lower, double upper, FitFamily family) {
  gsl_function function{[](double x, void* params) { return (*static_cast<const std::function<double(double)>*>(params))(x); },
                        const_cast<std::function<double(double)>*>(&f)};
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
  if (gsl_root_fsolver_set(solver.get(), &function, lower, upper) != GSL_SUCCESS) {
    throw InputError(location_of(family), "the likelihood equation has no bracketed root (degenerate data)");
  }
  for (int iteration = 0; iteration < 200; ++iteration) {
    gsl_root_fsolver_iterate(solver.get());
    const double lo = gsl_root_fsolver_x_lower(solver.get());
    const double hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lo, hi, 0.0, 1e-14) == GSL_SUCCESS) break;
  }
  return gsl_root_fsolver_root(solver.get());
}

struct Moments {
  double mean = 0;
  double mean_log = 0;  // only for positive data
  double sum_log = 0;
};

Moments validate(FitFamily family, std::span<const double> data, double fraction_upper) {
  const std::string location = location_of(family);
  if (data.size() < 2) {
    throw InputError(location, "needs at least two values, got " + std::to_string(data.size()));
  }
  Moments m;
  const bool positive = needs_positive_data(family);
  for (std::size_t i = 0; i < data.size(); ++i) {
    const double x = data[i];
    if (!std::isfinite(x) || (positive && !(x > 0.0))) {
      throw_bad_value(location, "value " + std::to_string(i + 1), format_double(x),
                      family == FitFamily::beta ? "a number in (0, " + format_double(fraction_upper) + ")"
                      : positive               ? "a positive finite number (this family lives on x > 0)"
                                               : "a finite number");
    }
    if (family == FitFamily::beta && !(x < fraction_upper)) {
      throw_bad_value(location, "value " + std::to_string(i + 1), format_double(x),
                      "a number in (0, " + format_double(fraction_upper) + ") (the beta law lives strictly inside)");
    }
    m.mean += x;
    if (positive) m.sum_log += std::log(x);
  }
  if (std::all_of(data.begin(), data.end(), [&](double x) { return x == data[0]; })) {
    throw InputError(location, "all " + std::to_string(data.size()) + " values equal " + format_double(data[0]) +
                                   ": expected a sample with spread");
  }
  const double n = static_cast<double>(data.size());
  m.mean /= n;
  m.mean_log = m.sum_log / n;
  return m;
}

// Normal ML on values g(x_i): (mean, sd with divisor n), by two passes for accuracy.
std::pair<double, double> normal_ml(std::span<const double> data, double (*g)(double)) {
  double mean = 0.0;
  for (const double x : data) mean += g(x);
  mean /= static_cast<double>(data.size());
  double squares = 0.0;
  for (const double x : data) squares += (g(x) - mean) * (g(x) - mean);
  return {mean, std::sqrt(squares / static_cast<double>(data.size()))};
}

// Beta ML (Eq. (D5)) on y in (0, 1): Newton's method on the score of the concave
// log-likelihood per value, l(a, b) = (a - 1) S1 + (b - 1) S2 - ln B(a, b), from the
// method-of-moments start, each step halved until a and b stay positive and l does not fall.
std::pair<double, double> beta_ml(std::span<const double> y, FitFamily family) {
  const double n = static_cast<double>(y.size());
  double mean = 0.0, s1 = 0.0, s2 = 0.0;
  for (const double v : y) {
    mean += v;
    s1 += std::log(v);
    s2 += std::log1p(-v);
  }
  mean /= n;
  s1 /= n;
  s2 /= n;
  double variance = 0.0;
  for (const double v : y) variance += (v - mean) * (v - mean);
  variance /= n;
  // Method of moments: alpha + beta = mean (1 - mean) / variance - 1 (> 0 for data inside (0, 1)).
  const double total = variance > 0.0 ? mean * (1.0 - mean) / variance - 1.0 : 2.0;
  double a = total > 0.0 ? mean * total : 1.0;
  double b = total > 0.0 ? (1.0 - mean) * total : 1.0;
  const auto log_likelihood = [&](double alpha, double beta) {
    return (alpha - 1.0) * s1 + (beta - 1.0) * s2 - gsl_sf_lnbeta(alpha, beta);
  };
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double psi_sum = gsl_sf_psi(a + b);
    const double ga = s1 - gsl_sf_psi(a) + psi_sum;
    const double gb = s2 - gsl_sf_psi(b) + psi_sum;
    // Newton: J d = g with J = -Hessian, positive definite.
    const double t = gsl_sf_psi_1(a + b);
    const double jaa = gsl_sf_psi_1(a) - t, jbb = gsl_sf_psi_1(b) - t, jab = -t;
    const double determinant = jaa * jbb - jab * jab;
    double da = (jbb * ga - jab * gb) / determinant;
    double db = (jaa * gb - jab * ga) / determinant;
    const double current = log_likelihood(a, b);
    for (int halving = 0; halving < 60; ++halving) {
      if (a + da > 0.0 && b + db > 0.0 && log_likelihood(a + da, b + db) >= current - 1e-15 * std::fabs(current)) break;
      da /= 2.0;
      db /= 2.0;
    }
    a += da;
    b += db;
    // 1e-10: Newton converges quadratically, so the step after one this small is below
    // rounding. Tight samples (alpha + beta ~ 60) make the Jacobian nearly singular
    // (determinant ~ 1e-5), and the psi functions' rounding then moves the step by ~1e-11
    // relative for ever: a 1e-13 test never passed there.
    if (std::fabs(da) <= 1e-10 * a && std::fabs(db) <= 1e-10 * b) return {a, b};
  }
  throw InputError(location_of(family), "the likelihood equations did not converge in 200 Newton steps");
}

double identity(double x) { return x; }
double natural_log(double x) { return std::log(x); }

}  // namespace

std::string_view to_string(FitFamily family) {
  switch (family) {
    case FitFamily::lognormal: return "lognormal";
    case FitFamily::normal: return "normal";
    case FitFamily::gamma: return "gamma";
    case FitFamily::weibull: return "weibull";
    case FitFamily::beta: return "beta";
  }
  return "unknown";
}

std::optional<FitFamily> parse_fit_family(std::string_view name) {
  for (const FitFamily family : fraction_fit_families) {  // every family
    if (to_string(family) == name) return family;
  }
  return std::nullopt;
}

std::optional<FitFamily> fit_family_of(const Distribution& distribution) {
  return parse_fit_family(family_name(distribution));
}

bool needs_positive_data(FitFamily family) { return family != FitFamily::normal; }

FitResult fit_distribution(FitFamily family, std::span<const double> data, double fraction_upper) {
  detail::gsl_errors_return();
  const Moments m = validate(family, data, fraction_upper);
  const double n = static_cast<double>(data.size());
  const double half_log_two_pi = 0.5 * std::log(2.0 * std::numbers::pi);
  std::optional<Distribution> law;
  double log_likelihood = 0.0;

  switch (family) {
    case FitFamily::normal: {
      const auto [mean, sd] = normal_ml(data, identity);
      law = Normal(mean, sd);
      // At the ML estimate sum (x - mean)^2 / sd^2 = n.
      log_likelihood = -n * (half_log_two_pi + std::log(sd) + 0.5);
      break;
    }
    case FitFamily::lognormal: {
      const auto [mu, sigma] = normal_ml(data, natural_log);
      law = Lognormal(mu, sigma);
      log_likelihood = -n * (half_log_two_pi + std::log(sigma) + 0.5) - m.sum_log;
      break;
    }
    case FitFamily::gamma: {
      const double s = std::log(m.mean) - m.mean_log;  // > 0 by Jensen unless all equal
      if (!(s > 0.0)) throw InputError(location_of(family), "the values are too close to each other to fit a gamma law");
      const double k = brent_root([s](double shape) { return std::log(shape) - gsl_sf_psi(shape) - s; },
                                  0.45 / s, 1.05 / s, family);
      const double theta = m.mean / k;
      law = Gamma(k, theta);
      // sum x / theta = n k at the estimate.
      log_likelihood = (k - 1.0) * m.sum_log - n * k - n * k * std::log(theta) - n * gsl_sf_lngamma(k);
      break;
    }
    case FitFamily::weibull: {
      // In y = x / max(x) <= 1 the powers y^k never overflow; the shape is scale-free.
      const double largest = *std::max_element(data.begin(), data.end());
      std::vector<double> log_y(data.size());
      for (std::size_t i = 0; i < data.size(); ++i) log_y[i] = std::log(data[i] / largest);
      double mean_log_y = 0.0;
      for (const double l : log_y) mean_log_y += l;
      mean_log_y /= n;
      const auto power_sums = [&](double k) {
        double sum = 0.0, weighted = 0.0;
        for (const double l : log_y) {
          const double p = std::exp(k * l);
          sum += p;
          weighted += p * l;
        }
        return std::pair{sum, weighted};
      };
      const auto score = [&](double k) {
        const auto [sum, weighted] = power_sums(k);
        return weighted / sum - mean_log_y - 1.0 / k;
      };
      double lower = 1.0, upper = 1.0;
      for (int i = 0; i < 200 && score(lower) > 0.0; ++i) lower /= 2.0;
      for (int i = 0; i < 200 && score(upper) < 0.0; ++i) upper *= 2.0;
      const double k = brent_root(score, lower, upper, family);
      const double lambda = largest * std::pow(power_sums(k).first / n, 1.0 / k);
      law = Weibull(k, lambda);
      // sum (x / lambda)^k = n at the estimate.
      log_likelihood = n * std::log(k) - n * k * std::log(lambda) + (k - 1.0) * m.sum_log - n;
      break;
    }
    case FitFamily::beta: {
      std::vector<double> y(data.begin(), data.end());
      double sum_log_complement = 0.0;
      for (double& v : y) {
        v /= fraction_upper;
        sum_log_complement += std::log1p(-v);
      }
      const auto [a, b] = beta_ml(y, family);
      law = Beta(a, b, fraction_upper);
      // sum ln f(x) = (a - 1) sum ln y + (b - 1) sum ln(1 - y) - n ln B(a, b) - n ln upper, with
      // sum ln y = sum ln x - n ln upper.
      const double sum_log_y = m.sum_log - n * std::log(fraction_upper);
      log_likelihood = (a - 1.0) * sum_log_y + (b - 1.0) * sum_log_complement - n * gsl_sf_lnbeta(a, b) -
                       n * std::log(fraction_upper);
      break;
    }
  }

  std::vector<double> sorted(data.begin(), data.end());
  std::sort(sorted.begin(), sorted.end());
  for (double& x : sorted) x = cdf(*law, x);
  FitResult result{family, *law, data.size()};
  result.log_likelihood = log_likelihood;
  result.aic = 2.0 * result.parameter_count - 2.0 * log_likelihood;
  result.ks_statistic = kolmogorov_smirnov_statistic(sorted);
  result.ad_statistic = anderson_darling_statistic(sorted);
  return result;
}

}  // namespace growthuq
