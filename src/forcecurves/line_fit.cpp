#include "line_fit.hpp"

namespace growthuq::detail {

LineFit fit_line_where(const double* x, const double* y, std::size_t first, std::size_t last, double low, double high) {
  LineFit fit;
  double sum_x = 0.0, sum_y = 0.0;
  for (std::size_t i = first; i <= last; ++i) {
    if (y[i] < low || y[i] > high) continue;
    sum_x += x[i];
    sum_y += y[i];
    ++fit.n;
  }
  if (fit.n < 2) return fit;
  const double mean_x = sum_x / static_cast<double>(fit.n);
  const double mean_y = sum_y / static_cast<double>(fit.n);
  double sxy = 0.0;
  for (std::size_t i = first; i <= last; ++i) {
    if (y[i] < low || y[i] > high) continue;
    const double dx = x[i] - mean_x, dy = y[i] - mean_y;
    fit.sxx += dx * dx;
    fit.syy += dy * dy;
    sxy += dx * dy;
  }
  if (!(fit.sxx > 0.0)) return fit;
  fit.slope = sxy / fit.sxx;
  fit.intercept = mean_y - fit.slope * mean_x;
  // SSE = Syy - Sxy^2 / Sxx can lose every digit for a near-perfect line: summed directly.
  for (std::size_t i = first; i <= last; ++i) {
    if (y[i] < low || y[i] > high) continue;
    const double r = y[i] - mean_y - fit.slope * (x[i] - mean_x);
    fit.sse += r * r;
  }
  return fit;
}

}  // namespace growthuq::detail
