#include "force_window.hpp"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace growthuq::fe {
namespace {

// The depth where the segment (d0, f0) -> (d1, f1) reaches `level`, f0 < level <= f1.
double passage(double d0, double f0, double d1, double f1, double level) {
  return d0 + (d1 - d0) * (level - f0) / (f1 - f0);
}

}  // namespace

WindowFit fit_force_window(std::span<const double> depth, std::span<const double> force, double low, double high) {
  WindowFit fit;
  const std::size_t n = depth.size();
  const bool finite = std::all_of(depth.begin(), depth.end(), [](double v) { return std::isfinite(v); }) &&
                      std::all_of(force.begin(), force.end(), [](double v) { return std::isfinite(v); });
  if (n < 2 || force.size() != n || !finite || !(low < high) || force[0] >= high) {
    fit.status = WindowFitStatus::invalid_curve;
    return fit;
  }
  fit.max_force = *std::max_element(force.begin(), force.end());
  if (fit.max_force < high) {
    fit.status = WindowFitStatus::window_not_reached;
    return fit;
  }
  // First passages through `low` and `high` (force[0] < high, so `top` > 0).
  std::size_t first = 0;
  if (force[0] >= low) {
    fit.low_depth = depth[0];
  } else {
    while (force[first + 1] < low) ++first;
    fit.low_depth = passage(depth[first], force[first], depth[first + 1], force[first + 1], low);
  }
  std::size_t top = first + 1;
  while (force[top] < high) ++top;
  fit.top_depth = passage(depth[top - 1], force[top - 1], depth[top], force[top], high);

  // The instrument records at a fixed rate, i.e. at equally spaced depths under displacement
  // control: the curve, linear between its points, is read at `samples` equally spaced depths
  // from the window's bottom to its top. A least-squares slope of equally spaced samples does
  // not depend on how the solver chose its steps (only through the linear interpolation,
  // O(step^2)), and it moves continuously with the curve, as a root in E needs. Reading the raw
  // solver points instead makes k jump by O(step) when a point enters or leaves the window.
  constexpr std::size_t samples = 101;
  std::array<double, samples> x{}, y{};
  std::size_t segment = first;
  for (std::size_t j = 0; j < samples; ++j) {
    const double at = fit.low_depth + (fit.top_depth - fit.low_depth) * static_cast<double>(j) / (samples - 1);
    while (segment + 1 < top && depth[segment + 1] < at) ++segment;
    const double width = depth[segment + 1] - depth[segment];
    const double t = width > 0 ? std::clamp((at - depth[segment]) / width, 0.0, 1.0) : 1.0;
    x[j] = at;
    y[j] = force[segment] + t * (force[segment + 1] - force[segment]);
  }
  y.front() = std::max(y.front(), low);  // the passages exactly, whatever the rounding
  y.back() = high;

  double c0 = 0, c1 = 0, cov00 = 0, cov01 = 0, cov11 = 0, sumsq = 0;
  gsl_fit_linear(x.data(), 1, y.data(), 1, samples, &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  fit.intercept = c0;
  fit.slope = c1;
  fit.points = static_cast<int>(samples);
  return fit;
}

}  // namespace growthuq::fe
