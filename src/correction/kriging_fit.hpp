// Fitting a ResidualKriging (growthuq/correction/residual_kriging.hpp): hyperparameters by
// maximum marginal likelihood, then the weights. Used by `growthuq fit-correction` only.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "growthuq/correction/residual_kriging.hpp"

namespace growthuq {

struct KrigingHyperparameters {
  std::vector<double> length_scales;
  double signal_sd = 0.0, noise_sd = 0.0;
};

// The hyperparameters that maximise the log marginal likelihood of `residuals` at `points` (row
// after row of `dimension` coordinates; Rasmussen and Williams 2006, eq. 5.8), found by GSL's
// Nelder-Mead simplex over their logarithms. The likelihood costs a Cholesky factorisation of
// the whole covariance, so it is evaluated on at most `likelihood_points` of the points, spread
// over them (a few hundred points fix eight hyperparameters; the weights then use them all). The
// noise never drops below 1e-4 (0.01 % in ln E: the data's own noise is 0.2 %), which keeps the
// covariance positive definite.
KrigingHyperparameters likeliest_hyperparameters(std::span<const double> points, std::size_t dimension,
                                                 std::span<const double> residuals, std::size_t likelihood_points = 600);

// The interpolant of `residuals` at `points` under `hyperparameters`: the weights of the
// posterior mean, by a Cholesky factorisation of the covariance. InputError naming "fit-correction"
// when that covariance is not positive definite in floating point.
ResidualKriging fit_kriging(std::span<const double> points, std::size_t dimension, std::span<const double> residuals,
                            const KrigingHyperparameters& hyperparameters);

}  // namespace growthuq
