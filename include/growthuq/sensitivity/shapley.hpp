// Shapley effects (Owen 2014; Song, Nelson and Staum 2016) of a model's inputs under their
// dependence: Sh_i shares Var(Y) among the inputs, each share non-negative and the shares summing
// to Var(Y) exactly, with interaction and dependence split fairly (Eqs. (S3)-(S5) of
// src/sensitivity/README.md). The inputs' dependence is a Gaussian copula: normal scores
// Z_i = Phi^-1(F_i(X_i)) jointly N(0, R), which is what an Iman-Conover design imposes
// (van der Waerden scores; src/correlation/README.md). Conditional draws are made in that space.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace growthuq {

// The model: rows of `inputs` (samples x d, in the inputs' own units) to outputs (samples x m).
// A non-finite output marks a sample the model could not evaluate.
using BatchModel = std::function<Eigen::MatrixXd(const Eigen::MatrixXd& inputs)>;
// The quantile function F_i^-1 of one input's marginal law, applied to every u in (0, 1) of the
// first span into the second (of equal size): batches, as the engine's laws transform columns.
using Quantile = std::function<void(std::span<const double> u, std::span<double> x)>;

struct ShapleySettings {
  std::size_t variance_samples = 1000;  // N_v: draws of the joint law for Var(Y)
  std::size_t outer = 200;              // N_o: draws of X_-J per subset (or per permutation step)
  std::size_t inner = 3;                // N_i: draws of X_J given X_-J (Song et al. 2016 advise 3)
  std::size_t permutations = 1000;      // random permutations when d > 6 (exact ones up to 6)
  std::size_t sections = 10;            // K of the interval (sectioning over the outer draws)
  std::uint64_t key = 0;                // every draw comes from derive_key(key, ...) and an index
};

struct ShapleyEffects {
  Eigen::MatrixXd effect;  // inputs x outputs, in the output's unit squared; each column sums to variance
  Eigen::MatrixXd low, high;  // 95 % interval (sectioning, Eq. (S5))
  Eigen::VectorXd variance;   // Var(Y) per output, estimated from N_v draws
  // Sh_i / Var(Y): each section's effects over its own variance, then as above; sums to 1.
  Eigen::MatrixXd share, share_low, share_high;
  std::size_t model_runs = 0;
  bool exact_permutations = true;  // false: random permutations (d > 6)
  std::vector<std::size_t> skipped;  // per output: inner groups left out for a non-finite value
};

// std::invalid_argument for d < 2, R not d x d or not positive definite, or settings of zero size.
ShapleyEffects shapley_effects(const BatchModel& model, const std::vector<Quantile>& marginals, const Eigen::MatrixXd& copula,
                               const ShapleySettings& settings);

// The exact Shapley effects of Y = b^T X with X ~ N(mu, Sigma) (Owen and Prieur 2017): the
// Shapley formula (S3) over every subset with the cost c(J) = E[Var(Y | X_-J)] =
// b_J^T (Sigma_JJ - Sigma_J,-J Sigma_-J,-J^-1 Sigma_-J,J) b_J. Sums to b^T Sigma b.
Eigen::VectorXd linear_gaussian_shapley(const Eigen::MatrixXd& sigma, const Eigen::VectorXd& b);

}  // namespace growthuq
