// Prescribed time histories for the time-dependent growth model (turgor p(t), viscosity
// eta(t)): constant, linear ramp, smoothed step, sinusoid. Each knows its value, its exact
// rate of change, and the times where it is not smooth, so an integrator can stop there.
#pragma once

#include <vector>

namespace growthuq {

class Waveform {
 public:
  enum class Shape { constant, ramp, smooth_step, sine };

  // `value` for all t.
  static Waveform constant(double value);

  // `from` until `start`, linear to `to` over [start, start + duration], then `to`.
  static Waveform ramp(double from, double to, double start, double duration);

  // A step from `from` to `to` smoothed over [start, start + rise] by the cubic
  // s^2 (3 - 2 s), s = (t - start) / rise: the rate is continuous (C1), and the mean over the
  // rise is exactly (from + to) / 2, so integrals have a closed form.
  static Waveform smooth_step(double from, double to, double start, double rise);

  // mean + amplitude sin(2 pi t / period + phase).
  static Waveform sine(double mean, double amplitude, double period, double phase = 0.0);

  Shape shape() const noexcept { return shape_; }
  double value(double t) const noexcept;
  double rate(double t) const noexcept;  // d value / dt

  // Lower and upper bounds of value(t) over all t (exact: the end values or mean -+ |amplitude|).
  double minimum() const noexcept;
  double maximum() const noexcept;

  // Times where the rate or its derivative jumps (ramp and step ends); empty otherwise.
  std::vector<double> breakpoints() const;

  // The period of a sine, infinity for the other shapes: integrators cap their step below it
  // so they cannot step over whole oscillations (the ends of ramps and steps are breakpoints).
  double period() const noexcept;

 private:
  Waveform(Shape shape, double a, double b, double c, double e) noexcept
      : shape_(shape), a_(a), b_(b), c_(c), e_(e) {}

  Shape shape_;
  // constant: a = value. ramp, smooth_step: a = from, b = to, c = start, e = duration.
  // sine: a = mean, b = amplitude, c = period, e = phase.
  double a_, b_, c_, e_;
};

}  // namespace growthuq
