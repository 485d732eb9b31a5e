// The apparent stiffness k as the instrument's software measures it: the slope of a
// least-squares line of force against indentation over the points with the force inside a
// window (0.4 to 4 uN by default), the curve interpolated at the window's edges.
#pragma once

#include <span>

namespace growthuq::fe {

enum class WindowFitStatus {
  ok,
  window_not_reached,  // the curve's largest force is below the window's top
  invalid_curve,       // fewer than 2 points, different lengths, a non-finite value, low >= high,
                       // or a first point already at the window's top
};

struct WindowFit {
  WindowFitStatus status = WindowFitStatus::ok;
  double slope = 0.0;      // dF/d(delta): k in the curve's units
  double intercept = 0.0;  // F at delta = 0 of the fitted line
  int points = 0;          // samples in the fit (101)
  double low_depth = 0.0;  // delta where the curve first reaches the window's bottom
  double top_depth = 0.0;  // ... and its top
  double max_force = 0.0;  // the curve's largest force (what a short curve did reach)
};

// Fits F = intercept + slope delta (gsl_fit_linear, equal weights) to the curve between its
// first passage through `low` and its first passage through `high` (both interpolated linearly
// between the neighbouring points), read at 101 equally spaced depths as the instrument
// samples it at a fixed rate: k then changes continuously with the curve and does not jump
// with the solver's load steps. A curve that starts at or above `low` starts the window at its
// first point. Any units, as long as depth, force and the window agree.
WindowFit fit_force_window(std::span<const double> depth, std::span<const double> force, double low, double high);

}  // namespace growthuq::fe
