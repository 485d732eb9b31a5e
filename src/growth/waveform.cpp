#include "growthuq/growth/waveform.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"

namespace growthuq {
namespace {

void require_finite(double value, std::string_view shape, std::string_view key) {
  if (!std::isfinite(value)) {
    throw_bad_value(std::string(shape) + " waveform", key, format_double(value), "a finite number");
  }
}

void require_positive(double value, std::string_view shape, std::string_view key) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw_bad_value(std::string(shape) + " waveform", key, format_double(value),
                    "a positive finite time in s");
  }
}

}  // namespace

Waveform Waveform::constant(double value) {
  require_finite(value, "constant", "value");
  return Waveform(Shape::constant, value, value, 0.0, 0.0);
}

Waveform Waveform::ramp(double from, double to, double start, double duration) {
  require_finite(from, "ramp", "from");
  require_finite(to, "ramp", "to");
  require_finite(start, "ramp", "start");
  require_positive(duration, "ramp", "duration");
  return Waveform(Shape::ramp, from, to, start, duration);
}

Waveform Waveform::smooth_step(double from, double to, double start, double rise) {
  require_finite(from, "step", "from");
  require_finite(to, "step", "to");
  require_finite(start, "step", "start");
  require_positive(rise, "step", "rise");
  return Waveform(Shape::smooth_step, from, to, start, rise);
}

Waveform Waveform::sine(double mean, double amplitude, double period, double phase) {
  require_finite(mean, "sine", "mean");
  require_finite(amplitude, "sine", "amplitude");
  require_positive(period, "sine", "period");
  require_finite(phase, "sine", "phase");
  return Waveform(Shape::sine, mean, amplitude, period, phase);
}

double Waveform::value(double t) const noexcept {
  switch (shape_) {
    case Shape::constant: return a_;
    case Shape::ramp:
    case Shape::smooth_step: {
      const double s = std::clamp((t - c_) / e_, 0.0, 1.0);
      const double weight = shape_ == Shape::ramp ? s : s * s * (3.0 - 2.0 * s);
      return a_ + (b_ - a_) * weight;
    }
    case Shape::sine: return a_ + b_ * std::sin(2.0 * std::numbers::pi * t / c_ + e_);
  }
  return a_;
}

double Waveform::rate(double t) const noexcept {
  switch (shape_) {
    case Shape::constant: return 0.0;
    case Shape::ramp:
    case Shape::smooth_step: {
      // Inside [start, start + duration) only; at the end the rate is the one after it.
      const double s = (t - c_) / e_;
      if (!(s >= 0.0 && s < 1.0)) return 0.0;
      const double slope = shape_ == Shape::ramp ? 1.0 : 6.0 * s * (1.0 - s);
      return (b_ - a_) * slope / e_;
    }
    case Shape::sine: {
      const double omega = 2.0 * std::numbers::pi / c_;
      return b_ * omega * std::cos(omega * t + e_);
    }
  }
  return 0.0;
}

double Waveform::minimum() const noexcept {
  return shape_ == Shape::sine ? a_ - std::abs(b_) : std::min(a_, b_);
}

double Waveform::maximum() const noexcept {
  return shape_ == Shape::sine ? a_ + std::abs(b_) : std::max(a_, b_);
}

std::vector<double> Waveform::breakpoints() const {
  if (shape_ == Shape::ramp || shape_ == Shape::smooth_step) return {c_, c_ + e_};
  return {};
}

double Waveform::period() const noexcept {
  return shape_ == Shape::sine ? c_ : std::numeric_limits<double>::infinity();
}

}  // namespace growthuq
