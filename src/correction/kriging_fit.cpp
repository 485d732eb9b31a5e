// The residual kriging's evaluation and fit (Rasmussen and Williams 2006, chapters 2 and 5).
#include "correction/kriging_fit.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multimin.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <vector>

#include <Eigen/Dense>

#include "core/gsl_errors.hpp"
#include "growthuq/core/error.hpp"

namespace growthuq {
namespace {

constexpr double noise_floor = 1e-4;

double squared_distance(const double* a, const double* b, std::span<const double> length_scales) noexcept {
  double sum = 0.0;
  for (std::size_t i = 0; i < length_scales.size(); ++i) {
    const double t = (a[i] - b[i]) / length_scales[i];
    sum += t * t;
  }
  return sum;
}

// K + noise^2 I over the points (eq. 2.21's covariance of the noisy targets).
Eigen::MatrixXd covariance(std::span<const double> points, std::size_t dimension, const KrigingHyperparameters& h) {
  const auto n = static_cast<Eigen::Index>(points.size() / dimension);
  Eigen::MatrixXd K(n, n);
  const double signal = h.signal_sd * h.signal_sd;
  for (Eigen::Index a = 0; a < n; ++a) {
    K(a, a) = signal + h.noise_sd * h.noise_sd;
    for (Eigen::Index b = 0; b < a; ++b) {
      K(a, b) = K(b, a) = signal * std::exp(-0.5 * squared_distance(&points[static_cast<std::size_t>(a) * dimension],
                                                                     &points[static_cast<std::size_t>(b) * dimension],
                                                                     h.length_scales));
    }
  }
  return K;
}

struct Likelihood {
  std::span<const double> points;
  std::size_t dimension = 0;
  Eigen::VectorXd residuals;
};

// log sd's and log length scales -> hyperparameters; the noise kept above its floor.
KrigingHyperparameters from_logs(const gsl_vector* x, std::size_t dimension) {
  KrigingHyperparameters h;
  for (std::size_t i = 0; i < dimension; ++i) h.length_scales.push_back(std::exp(gsl_vector_get(x, i)));
  h.signal_sd = std::exp(gsl_vector_get(x, dimension));
  h.noise_sd = std::hypot(noise_floor, std::exp(gsl_vector_get(x, dimension + 1)));
  return h;
}

// Minus the log marginal likelihood without its constant (eq. 5.8): r' K^-1 r / 2 + ln det L.
double negative_log_likelihood(const gsl_vector* x, void* data) {
  const auto& problem = *static_cast<const Likelihood*>(data);
  const Eigen::LLT<Eigen::MatrixXd> llt(covariance(problem.points, problem.dimension, from_logs(x, problem.dimension)));
  if (llt.info() != Eigen::Success) return std::numeric_limits<double>::max();
  const double value = 0.5 * problem.residuals.dot(llt.solve(problem.residuals)) +
                       llt.matrixLLT().diagonal().array().log().sum();
  return std::isfinite(value) ? value : std::numeric_limits<double>::max();
}

// At most `count` of the n points, spread over them: point (k p) mod n for k = 0, 1, ..., p
// coprime to n (so that no point comes twice). Every stride-th point would be biased where the points come in
// blocks (the training data: each tube's 12 windows in one order, so a stride of 4 keeps only the
// windows whose bottom is 0.05 of the top, and the likelihood would never see the window vary).
std::vector<std::size_t> likelihood_subset(std::size_t n, std::size_t count) {
  std::vector<std::size_t> subset;
  if (n <= count) {
    for (std::size_t a = 0; a < n; ++a) subset.push_back(a);
    return subset;
  }
  std::size_t step = 7919;  // a prime: coprime to n unless n is a multiple of it
  while (std::gcd(step, n) != 1) ++step;
  for (std::size_t k = 0; k < count; ++k) subset.push_back(k * step % n);
  return subset;
}

}  // namespace

double ResidualKriging::value(std::span<const double> z) const noexcept {
  double sum = 0.0;
  const std::size_t dimension = length_scales.size();
  for (std::size_t c = 0; c < weights.size(); ++c) {
    sum += weights[c] * std::exp(-0.5 * squared_distance(&centres[c * dimension], z.data(), length_scales));
  }
  return sum;
}

KrigingHyperparameters likeliest_hyperparameters(std::span<const double> points, std::size_t dimension,
                                                 std::span<const double> residuals, std::size_t likelihood_points) {
  detail::gsl_errors_return();  // GSL reports through return codes; it must never abort a run
  const std::size_t n = residuals.size();
  std::vector<double> subset;
  std::vector<double> subset_residuals;
  for (const std::size_t a : likelihood_subset(n, likelihood_points)) {
    subset.insert(subset.end(), points.begin() + static_cast<std::ptrdiff_t>(a * dimension),
                  points.begin() + static_cast<std::ptrdiff_t>((a + 1) * dimension));
    subset_residuals.push_back(residuals[a]);
  }
  Likelihood problem{subset, dimension, Eigen::Map<const Eigen::VectorXd>(subset_residuals.data(),
                                                                          static_cast<Eigen::Index>(subset_residuals.size()))};
  const double mean = std::accumulate(residuals.begin(), residuals.end(), 0.0) / static_cast<double>(n);
  double spread = 0.0;
  for (const double r : residuals) spread += (r - mean) * (r - mean);
  spread = std::sqrt(spread / static_cast<double>(n));

  // Start: length scales of a quarter of the scaled box ([-1, 1]), the residual's spread as the
  // signal, a tenth of it as the noise; steps of a factor e in every hyperparameter.
  const std::size_t unknowns = dimension + 2;
  std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> x(gsl_vector_alloc(unknowns), gsl_vector_free);
  std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> step(gsl_vector_alloc(unknowns), gsl_vector_free);
  for (std::size_t i = 0; i < dimension; ++i) gsl_vector_set(x.get(), i, std::log(0.5));
  gsl_vector_set(x.get(), dimension, std::log(std::max(spread, noise_floor)));
  gsl_vector_set(x.get(), dimension + 1, std::log(std::max(0.1 * spread, noise_floor)));
  gsl_vector_set_all(step.get(), 1.0);
  gsl_multimin_function function{negative_log_likelihood, unknowns, &problem};
  std::unique_ptr<gsl_multimin_fminimizer, decltype(&gsl_multimin_fminimizer_free)> minimizer(
      gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, unknowns), gsl_multimin_fminimizer_free);
  gsl_multimin_fminimizer_set(minimizer.get(), &function, x.get(), step.get());
  // 1e-3 in the logarithms: hyperparameters to 0.1 %, far finer than the prediction needs.
  for (int iteration = 0; iteration < 400 * static_cast<int>(unknowns); ++iteration) {
    if (gsl_multimin_fminimizer_iterate(minimizer.get()) != GSL_SUCCESS) break;
    if (gsl_multimin_test_size(gsl_multimin_fminimizer_size(minimizer.get()), 1e-3) == GSL_SUCCESS) break;
  }
  return from_logs(gsl_multimin_fminimizer_x(minimizer.get()), dimension);
}

ResidualKriging fit_kriging(std::span<const double> points, std::size_t dimension, std::span<const double> residuals,
                            const KrigingHyperparameters& hyperparameters) {
  const Eigen::LLT<Eigen::MatrixXd> llt(covariance(points, dimension, hyperparameters));
  if (llt.info() != Eigen::Success) {
    throw InputError("fit-correction", "the residual kriging's covariance is not positive definite (noise sd " +
                                           std::to_string(hyperparameters.noise_sd) +
                                           "): expected training rows that are not repeated");
  }
  const Eigen::VectorXd alpha =
      llt.solve(Eigen::Map<const Eigen::VectorXd>(residuals.data(), static_cast<Eigen::Index>(residuals.size())));
  ResidualKriging kriging;
  kriging.length_scales = hyperparameters.length_scales;
  kriging.signal_sd = hyperparameters.signal_sd;
  kriging.noise_sd = hyperparameters.noise_sd;
  kriging.centres.assign(points.begin(), points.end());
  const double signal = hyperparameters.signal_sd * hyperparameters.signal_sd;
  for (Eigen::Index c = 0; c < alpha.size(); ++c) kriging.weights.push_back(signal * alpha(c));
  return kriging;
}

}  // namespace growthuq
