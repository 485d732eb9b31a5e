// Reproducible random test points: uniform and log-uniform doubles from std::mt19937_64, whose
// sequence the C++ standard fixes bit for bit (unlike its distributions), so a sweep draws the
// same points with every standard library.
#pragma once

#include <cmath>
#include <random>

namespace growthuq::testing {

// Uniform double in [0, 1) from the top 53 bits.
inline double unit_uniform(std::mt19937_64& engine) { return static_cast<double>(engine() >> 11) * 0x1p-53; }

// Log-uniform in [low, high).
inline double log_uniform(std::mt19937_64& engine, double low, double high) {
  return low * std::exp(unit_uniform(engine) * std::log(high / low));
}

}  // namespace growthuq::testing
