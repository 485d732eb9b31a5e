// A Gaussian-process (kriging) interpolant of what a least-squares polynomial leaves: the second
// stage of fidelity corrected's modulus correction (src/correction/README.md, "The model").
// One polynomial over the whole envelope leaves a few-percent residual that is smooth but has no
// low-order shape (it runs along every group at once); the interpolant follows it between the
// training tubes, with the squared-exponential covariance of Rasmussen and Williams (2006),
// Gaussian Processes for Machine Learning, eq. 5.1 (one length scale per coordinate), its
// prediction being the posterior mean, eq. 2.25.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace growthuq {

struct ResidualKriging {
  // Hyperparameters, in the coordinates the centres are given in: covariance
  // signal_sd^2 exp(-1/2 sum_i ((z_i - z'_i) / length_scales_i)^2), plus noise_sd^2 on the diagonal.
  std::vector<double> length_scales;
  double signal_sd = 0.0, noise_sd = 0.0;
  std::vector<double> centres;  // the training points, row after row of length_scales.size()
  std::vector<double> weights;  // per centre: signal_sd^2 times (K + noise_sd^2 I)^-1 r

  std::size_t size() const noexcept { return weights.size(); }
  // The posterior mean at z (z.size() == length_scales.size()); 0 with no centres.
  double value(std::span<const double> z) const noexcept;
};

}  // namespace growthuq
