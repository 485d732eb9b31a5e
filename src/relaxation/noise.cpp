#include "relaxation/noise.hpp"

#include <cmath>
#include <numbers>

namespace growthuq {

double GaussianNoise::uniform() {
  constexpr double two_to_minus_53 = 0x1p-53;
  return static_cast<double>((engine_() >> 11) + 1) * two_to_minus_53;
}

double GaussianNoise::normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double radius = std::sqrt(-2.0 * std::log(uniform()));
  const double angle = 2.0 * std::numbers::pi * uniform();
  spare_ = radius * std::sin(angle);
  has_spare_ = true;
  return radius * std::cos(angle);
}

}  // namespace growthuq
