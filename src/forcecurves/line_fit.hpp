// Ordinary least-squares straight lines for the baseline (Eq. (C1)) and the window fit (Eq.
// (C6)), src/forcecurves/README.md. Sums are taken about the means (two passes), so that the
// slope of a window far from z = 0 keeps its digits (numpy.polyfit agrees to 1e-9 relative).
#pragma once

#include <cmath>
#include <cstddef>

namespace growthuq::detail {

struct LineFit {
  std::size_t n = 0;
  double slope = 0.0, intercept = 0.0;
  double sxx = 0.0, syy = 0.0, sse = 0.0;  // centred sums of squares and the residual sum

  // Standard error of the slope, sqrt(s^2 / Sxx) with s^2 = SSE / (n - 2) (e.g. Draper and Smith
  // 1998, Eq. (3.1.8)).
  double slope_se() const { return n > 2 && sxx > 0.0 ? std::sqrt(sse / static_cast<double>(n - 2) / sxx) : 0.0; }
  double r_squared() const { return syy > 0.0 ? 1.0 - sse / syy : 0.0; }
};

// The line through (x[i], y[i]) for i in [first, last] with low <= y[i] <= high (every sample
// when low = -inf and high = +inf).
LineFit fit_line_where(const double* x, const double* y, std::size_t first, std::size_t last, double low, double high);

}  // namespace growthuq::detail
