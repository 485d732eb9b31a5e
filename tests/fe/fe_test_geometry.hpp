// Shared helpers of the element tests: random rotations and triangles, central differences of an
// energy over a fixed-size dof vector.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "support/random_draws.hpp"

namespace growthuq::fe::testing {

inline Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  Eigen::Vector4d q;
  for (int i = 0; i < 4; ++i) q(i) = growthuq::testing::unit_uniform(rng) - 0.5;
  return Eigen::Quaterniond(q(0), q(1), q(2), q(3)).normalized().toRotationMatrix();
}

inline Eigen::Vector3d random_vector(std::mt19937_64& rng, double scale) {
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v(i) = scale * (2 * growthuq::testing::unit_uniform(rng) - 1);
  return v;
}

// Central differences of energy(x) and of gradient(x): step `step`, one dof at a time.
template <int N, class Energy, class Gradient>
void central_differences(const Eigen::Matrix<double, N, 1>& x, double step, Energy energy, Gradient gradient,
                         Eigen::Matrix<double, N, 1>& g_fd, Eigen::Matrix<double, N, N>& h_fd) {
  for (int i = 0; i < N; ++i) {
    Eigen::Matrix<double, N, 1> xp = x, xm = x;
    xp(i) += step;
    xm(i) -= step;
    g_fd(i) = (energy(xp) - energy(xm)) / (2 * step);
    h_fd.col(i) = (gradient(xp) - gradient(xm)) / (2 * step);
  }
}

}  // namespace growthuq::fe::testing
