#include "growthuq/sensitivity/shapley.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>
#include <gsl/gsl_cdf.h>

#include "growthuq/distributions/standard_normal.hpp"
#include "growthuq/sampling/random_stream.hpp"

namespace growthuq {
namespace {

using Mask = std::uint64_t;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
// Exact permutations up to this many inputs: 2^6 - 2 = 62 subsets; 7 would be 126 and the
// random-permutation estimator (Song et al. 2016, Algorithm 1) is then the cheaper one.
constexpr std::size_t exact_limit = 6;

std::vector<Eigen::Index> members(Mask mask, std::size_t d, bool in) {
  std::vector<Eigen::Index> chosen;
  for (std::size_t i = 0; i < d; ++i) {
    if (((mask >> i) & 1U) == (in ? 1U : 0U)) chosen.push_back(static_cast<Eigen::Index>(i));
  }
  return chosen;
}

Eigen::MatrixXd block(const Eigen::MatrixXd& m, const std::vector<Eigen::Index>& rows, const std::vector<Eigen::Index>& columns) {
  Eigen::MatrixXd b(rows.size(), columns.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) b(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = m(rows[r], columns[c]);
  }
  return b;
}

// The law of Z_J given Z_-J for a Gaussian copula (Gaussian conditioning): mean A z_-J,
// covariance R_JJ - A R_-J,J with A = R_J,-J R_-J,-J^-1; draws through Cholesky factors.
struct Conditional {
  std::vector<Eigen::Index> varied, fixed;
  Eigen::MatrixXd fixed_factor;  // chol(R_-J,-J)
  Eigen::MatrixXd gain;          // A
  Eigen::MatrixXd varied_factor;  // chol of the conditional covariance
};

Conditional conditional(const Eigen::MatrixXd& r, Mask varied, std::size_t d) {
  Conditional c;
  c.varied = members(varied, d, true);
  c.fixed = members(varied, d, false);
  const Eigen::MatrixXd rff = block(r, c.fixed, c.fixed);
  const Eigen::MatrixXd rvf = block(r, c.varied, c.fixed);
  const Eigen::LLT<Eigen::MatrixXd> fixed_llt(rff);
  c.fixed_factor = fixed_llt.matrixL();
  c.gain = fixed_llt.solve(rvf.transpose()).transpose();
  const Eigen::MatrixXd covariance = block(r, c.varied, c.varied) - c.gain * rvf.transpose();
  c.varied_factor = Eigen::LLT<Eigen::MatrixXd>(covariance).matrixL();
  return c;
}

class Sampler {
 public:
  Sampler(const BatchModel& model, const std::vector<Quantile>& marginals, const Eigen::MatrixXd& copula, const ShapleySettings& settings)
      : model_(model), marginals_(marginals), copula_(copula), settings_(settings), d_(marginals.size()) {}

  // Inputs from normal scores: X_i = F_i^-1(Phi(Z_i)), Phi kept inside the open unit interval;
  // column by column, as the laws transform batches.
  Eigen::MatrixXd inputs_of(const Eigen::MatrixXd& z) const {
    Eigen::MatrixXd x(z.rows(), z.cols());
    std::vector<double> u(static_cast<std::size_t>(z.rows()));
    for (Eigen::Index i = 0; i < z.cols(); ++i) {
      for (Eigen::Index s = 0; s < z.rows(); ++s) {
        u[static_cast<std::size_t>(s)] = std::clamp(0.5 * std::erfc(-z(s, i) * M_SQRT1_2), 0x1p-60, 1.0 - 0x1p-53);
      }
      marginals_[static_cast<std::size_t>(i)](u, std::span<double>(x.col(i).data(), u.size()));
    }
    return x;
  }

  // `count` standard normal draws from `stream` (uniforms in (0, 1), then Phi^-1 as a batch).
  static std::vector<double> normal_draws(RandomStream& stream, std::size_t count) {
    std::vector<double> u(count), z(count);
    for (double& value : u) value = stream.uniform_open();
    standard_normal_quantiles(u, z);
    return z;
  }

  Eigen::MatrixXd evaluate(const Eigen::MatrixXd& z) {
    const Eigen::MatrixXd y = model_(inputs_of(z));
    if (y.rows() != z.rows() || y.cols() < 1) throw std::invalid_argument("shapley_effects: the model returned the wrong shape");
    runs += static_cast<std::size_t>(z.rows());
    if (outputs == 0) outputs = static_cast<std::size_t>(y.cols());
    return y;
  }

  // Var(Y) per section of the N_v joint draws (sample variance, finite values only): sections x m.
  Eigen::MatrixXd section_variances() {
    RandomStream stream(derive_key(settings_.key, "variance"));
    const Eigen::MatrixXd factor = Eigen::LLT<Eigen::MatrixXd>(copula_).matrixL();
    const std::vector<double> draws = normal_draws(stream, settings_.variance_samples * d_);
    Eigen::MatrixXd e(settings_.variance_samples, d_);
    for (Eigen::Index s = 0; s < e.rows(); ++s) {
      for (Eigen::Index i = 0; i < e.cols(); ++i) e(s, i) = draws[static_cast<std::size_t>(s) * d_ + static_cast<std::size_t>(i)];
    }
    const Eigen::MatrixXd y = evaluate(e * factor.transpose());
    const std::size_t k = settings_.sections;
    Eigen::MatrixXd variances(k, y.cols());
    for (Eigen::Index o = 0; o < y.cols(); ++o) {
      for (std::size_t section = 0; section < k; ++section) {
        double mean = 0, squares = 0;
        std::size_t count = 0;
        for (std::size_t s = section * y.rows() / k; s < (section + 1) * y.rows() / k; ++s) {
          const double v = y(static_cast<Eigen::Index>(s), o);
          if (!std::isfinite(v)) continue;
          ++count;
          const double delta = v - mean;
          mean += delta / static_cast<double>(count);
          squares += delta * (v - mean);
        }
        variances(static_cast<Eigen::Index>(section), o) = count > 1 ? squares / static_cast<double>(count - 1) : nan;
      }
    }
    return variances;
  }

  // E[Var(Y | X_-J)] from `outer` draws of Z_-J, `inner` draws of Z_J given each (Song et al.
  // 2016, Eq. (11)): per outer draw l the sample variance of its inner outputs, outer x m (NaN
  // where an inner output is not finite).
  Eigen::MatrixXd inner_variances(Mask varied, std::size_t outer, std::uint64_t key) {
    const Conditional c = conditional(copula_, varied, d_);
    const std::size_t inner = settings_.inner;
    RandomStream stream(key);
    Eigen::MatrixXd z(outer * inner, d_);
    Eigen::VectorXd e_fixed(c.fixed.size()), e_varied(c.varied.size());
    // Per outer draw: its fixed inputs' draws, then each inner draw's varied ones.
    const std::vector<double> draws = normal_draws(stream, outer * (c.fixed.size() + inner * c.varied.size()));
    std::size_t next = 0;
    for (std::size_t l = 0; l < outer; ++l) {
      for (Eigen::Index f = 0; f < e_fixed.size(); ++f) e_fixed(f) = draws[next++];
      const Eigen::VectorXd z_fixed = c.fixed_factor * e_fixed;
      const Eigen::VectorXd mean = c.gain * z_fixed;
      for (std::size_t h = 0; h < inner; ++h) {
        for (Eigen::Index v = 0; v < e_varied.size(); ++v) e_varied(v) = draws[next++];
        const Eigen::VectorXd z_varied = mean + c.varied_factor * e_varied;
        const auto row = static_cast<Eigen::Index>(l * inner + h);
        for (std::size_t f = 0; f < c.fixed.size(); ++f) z(row, c.fixed[f]) = z_fixed(static_cast<Eigen::Index>(f));
        for (std::size_t v = 0; v < c.varied.size(); ++v) z(row, c.varied[v]) = z_varied(static_cast<Eigen::Index>(v));
      }
    }
    const Eigen::MatrixXd y = evaluate(z);
    Eigen::MatrixXd variances(outer, y.cols());
    for (Eigen::Index o = 0; o < y.cols(); ++o) {
      for (std::size_t l = 0; l < outer; ++l) {
        double mean = 0, squares = 0;
        bool finite = true;
        for (std::size_t h = 0; h < inner; ++h) {
          const double v = y(static_cast<Eigen::Index>(l * inner + h), o);
          finite = finite && std::isfinite(v);
          const double delta = v - mean;
          mean += delta / static_cast<double>(h + 1);
          squares += delta * (v - mean);
        }
        variances(static_cast<Eigen::Index>(l), o) = finite ? squares / static_cast<double>(inner - 1) : nan;
      }
    }
    return variances;
  }

  std::size_t runs = 0;
  std::size_t outputs = 0;

 private:
  const BatchModel& model_;
  const std::vector<Quantile>& marginals_;
  const Eigen::MatrixXd& copula_;
  const ShapleySettings& settings_;
  std::size_t d_;
};

// Mean of the finite values of `values` in rows [begin, end) of column o; counts those left out.
double finite_mean(const Eigen::MatrixXd& values, std::size_t begin, std::size_t end, Eigen::Index o, std::size_t& skipped) {
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t l = begin; l < end; ++l) {
    const double v = values(static_cast<Eigen::Index>(l), o);
    if (std::isfinite(v)) {
      sum += v;
      ++count;
    } else {
      ++skipped;
    }
  }
  return count > 0 ? sum / static_cast<double>(count) : nan;
}

double factorial(std::size_t n) { return std::tgamma(static_cast<double>(n) + 1.0); }

// Eq. (S3): Sh_i = sum over J not holding i of |J|! (d - |J| - 1)! / d! (c(J + i) - c(J)).
Eigen::VectorXd shapley_of_costs(const std::vector<double>& cost, std::size_t d) {
  Eigen::VectorXd effect = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(d));
  const Mask all = (Mask{1} << d) - 1;
  for (std::size_t i = 0; i < d; ++i) {
    const Mask bit = Mask{1} << i;
    for (Mask j = 0; j <= all; ++j) {
      if (j & bit) continue;
      const auto size = static_cast<std::size_t>(std::popcount(j));
      const double weight = factorial(size) * factorial(d - size - 1) / factorial(d);
      effect(static_cast<Eigen::Index>(i)) += weight * (cost[j | bit] - cost[j]);
    }
  }
  return effect;
}

void check(const std::vector<Quantile>& marginals, const Eigen::MatrixXd& copula, const ShapleySettings& s) {
  const auto d = static_cast<Eigen::Index>(marginals.size());
  if (d < 2) throw std::invalid_argument("shapley_effects: fewer than 2 inputs");
  if (d > 62) throw std::invalid_argument("shapley_effects: more than 62 inputs");
  if (copula.rows() != d || copula.cols() != d) throw std::invalid_argument("shapley_effects: the copula's correlation is not d x d");
  if (Eigen::LLT<Eigen::MatrixXd>(copula).info() != Eigen::Success) {
    throw std::invalid_argument("shapley_effects: the copula's correlation is not positive definite");
  }
  const bool exact = static_cast<std::size_t>(d) <= exact_limit;
  // Sections split the outer draws (exact) or the permutations (random), and the variance draws.
  if (s.inner < 2 || s.outer < 1 || s.sections < 2 || s.variance_samples < 2 * s.sections ||
      (exact ? s.outer : s.permutations) < s.sections) {
    throw std::invalid_argument("shapley_effects: inner >= 2, sections >= 2, and outer (exact permutations) or "
                                "permutations (random ones), and half the variance samples, at least the sections");
  }
}

}  // namespace

ShapleyEffects shapley_effects(const BatchModel& model, const std::vector<Quantile>& marginals, const Eigen::MatrixXd& copula,
                               const ShapleySettings& settings) {
  check(marginals, copula, settings);
  const std::size_t d = marginals.size();
  const std::size_t k = settings.sections;
  Sampler sampler(model, marginals, copula, settings);
  const Eigen::MatrixXd variance = sampler.section_variances();  // sections x m
  const auto m = variance.cols();
  ShapleyEffects result;
  result.skipped.assign(static_cast<std::size_t>(m), 0);
  // Per section: the effects (d x m) of that section's outer draws (or permutations).
  std::vector<Eigen::MatrixXd> sections(k, Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(d), m));
  const Mask all = (Mask{1} << d) - 1;
  if (d <= exact_limit) {
    // Exact permutations through the subset form (S3): each cost once, from its own draws.
    std::vector<Eigen::MatrixXd> per_outer(all + 1);
    for (Mask j = 1; j < all; ++j) {
      per_outer[j] = sampler.inner_variances(j, settings.outer, derive_key(settings.key, "subset " + std::to_string(j)));
    }
    for (std::size_t section = 0; section < k; ++section) {
      const std::size_t begin = section * settings.outer / k, end = (section + 1) * settings.outer / k;
      for (Eigen::Index o = 0; o < m; ++o) {
        std::vector<double> cost(all + 1, 0.0);  // c(empty) = 0
        cost[all] = variance(static_cast<Eigen::Index>(section), o);
        for (Mask j = 1; j < all; ++j) cost[j] = finite_mean(per_outer[j], begin, end, o, result.skipped[static_cast<std::size_t>(o)]);
        sections[section].col(o) = shapley_of_costs(cost, d);
      }
    }
  } else {
    // Random permutations (Song et al. 2016, Algorithm 1): along a permutation, the cost of each
    // growing prefix from fresh draws, its increment credited to the input that joined.
    result.exact_permutations = false;
    const std::uint64_t permutation_key = derive_key(settings.key, "permutations");
    for (std::size_t p = 0; p < settings.permutations; ++p) {
      const std::size_t section = p * k / settings.permutations;
      std::vector<std::size_t> order(d);
      std::iota(order.begin(), order.end(), std::size_t{0});
      RandomStream shuffle(counter_bits(permutation_key, 2 * p));
      for (std::size_t i = d - 1; i > 0; --i) std::swap(order[i], order[shuffle.below(i + 1)]);
      Eigen::VectorXd previous = Eigen::VectorXd::Zero(m);
      Mask prefix = 0;
      for (std::size_t step = 0; step < d; ++step) {
        prefix |= Mask{1} << order[step];
        Eigen::VectorXd cost(m);
        if (prefix == all) {
          cost = variance.row(static_cast<Eigen::Index>(section)).transpose();
        } else {
          const Eigen::MatrixXd v = sampler.inner_variances(prefix, settings.outer, counter_bits(permutation_key, 2 * p + 1) ^ mix64(step));
          for (Eigen::Index o = 0; o < m; ++o) cost(o) = finite_mean(v, 0, settings.outer, o, result.skipped[static_cast<std::size_t>(o)]);
        }
        sections[section].row(static_cast<Eigen::Index>(order[step])) += (cost - previous).transpose();
        previous = cost;
      }
    }
    for (std::size_t section = 0; section < k; ++section) {
      const std::size_t count = (section + 1) * settings.permutations / k - section * settings.permutations / k;
      sections[section] /= static_cast<double>(count);
    }
  }
  // Eq. (S5): the mean over sections and the t interval of their spread (sectioning).
  const double t = gsl_cdf_tdist_Pinv(0.975, static_cast<double>(k - 1));
  const auto sectioned = [&](const std::vector<Eigen::MatrixXd>& parts, Eigen::MatrixXd& mean, Eigen::MatrixXd& low,
                             Eigen::MatrixXd& high) {
    mean = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(d), m);
    for (const Eigen::MatrixXd& s : parts) mean += s / static_cast<double>(k);
    Eigen::MatrixXd squares = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(d), m);
    for (const Eigen::MatrixXd& s : parts) squares += (s - mean).cwiseAbs2();
    const Eigen::MatrixXd half = t * (squares / static_cast<double>(k - 1) / static_cast<double>(k)).cwiseSqrt();
    low = mean - half;
    high = mean + half;
  };
  sectioned(sections, result.effect, result.low, result.high);
  std::vector<Eigen::MatrixXd> shares = sections;
  for (std::size_t section = 0; section < k; ++section) {
    for (Eigen::Index o = 0; o < m; ++o) shares[section].col(o) /= variance(static_cast<Eigen::Index>(section), o);
  }
  sectioned(shares, result.share, result.share_low, result.share_high);
  result.variance = variance.colwise().mean().transpose();
  result.model_runs = sampler.runs;
  return result;
}

Eigen::VectorXd linear_gaussian_shapley(const Eigen::MatrixXd& sigma, const Eigen::VectorXd& b) {
  const auto d = static_cast<std::size_t>(b.size());
  if (d < 1 || d > 20 || sigma.rows() != b.size() || sigma.cols() != b.size()) {
    throw std::invalid_argument("linear_gaussian_shapley: Sigma must be d x d with 1 <= d <= 20");
  }
  const Mask all = (Mask{1} << d) - 1;
  std::vector<double> cost(all + 1, 0.0);
  cost[all] = b.dot(sigma * b);
  for (Mask j = 1; j < all; ++j) {
    const std::vector<Eigen::Index> varied = members(j, d, true), fixed = members(j, d, false);
    const Eigen::MatrixXd svf = block(sigma, varied, fixed);
    const Eigen::MatrixXd conditional_covariance =
        block(sigma, varied, varied) - svf * Eigen::LLT<Eigen::MatrixXd>(block(sigma, fixed, fixed)).solve(svf.transpose());
    Eigen::VectorXd bj(varied.size());
    for (std::size_t v = 0; v < varied.size(); ++v) bj(static_cast<Eigen::Index>(v)) = b(varied[v]);
    cost[j] = bj.dot(conditional_covariance * bj);
  }
  return shapley_of_costs(cost, d);
}

}  // namespace growthuq
