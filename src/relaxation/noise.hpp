// Reproducible measurement noise for simulated relaxation curves: a seeded std::mt19937_64
// (whose output sequence the C++ standard fixes) turned into doubles and Gaussian deviates by
// formulas written here, so the same seed gives the same curve with every standard library.
#pragma once

#include <cstdint>
#include <random>

namespace growthuq {

class GaussianNoise {
 public:
  explicit GaussianNoise(std::uint64_t seed) : engine_(seed) {}

  // ((bits >> 11) + 1) * 2^-53: uniform on (0, 1], never 0 so that log(u) is finite.
  double uniform();

  // Standard normal deviate by the Box-Muller transform (Box and Muller 1958):
  // sqrt(-2 ln u1) (cos, sin)(2 pi u2); the sine deviate is kept for the next call.
  double normal();

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace growthuq
