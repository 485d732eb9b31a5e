// Eq. (C5), src/forcecurves/README.md: Savitzky-Golay smoothing with a quadratic (Savitzky and
// Golay 1964). GSL has no such filter; the convolution weights of a least-squares quadratic (or
// cubic) over 2m + 1 equally spaced samples, evaluated at the centre, are in closed form
// (Madden 1978, Eq. (7); Press et al., Numerical Recipes 3rd ed., section 14.9):
//   c_i = 3 (3m^2 + 3m - 1 - 5 i^2) / ((2m + 1)(4m^2 + 4m - 3)),   i = -m..m
// (m = 2 gives the textbook (-3, 12, 17, 12, -3) / 35).
#include <stdexcept>
#include <vector>

#include "growthuq/forcecurves/curve_processing.hpp"

namespace growthuq {

void savitzky_golay_quadratic(const double* in, double* out, std::size_t n, int window) {
  if (window < 5 || window % 2 == 0) throw std::logic_error("savitzky_golay_quadratic: window must be odd and >= 5");
  const long m = (window - 1) / 2;
  const double denominator = static_cast<double>((2 * m + 1) * (4 * m * m + 4 * m - 3));
  std::vector<double> weights(static_cast<std::size_t>(window));
  for (long i = -m; i <= m; ++i) {
    weights[static_cast<std::size_t>(i + m)] = 3.0 * static_cast<double>(3 * m * m + 3 * m - 1 - 5 * i * i) / denominator;
  }
  const auto count = static_cast<long>(n);
  for (long j = 0; j < count; ++j) {
    if (j < m || j + m >= count) {
      out[j] = in[j];  // too close to an end for a centred window: kept as recorded
      continue;
    }
    double sum = 0.0;
    for (long i = -m; i <= m; ++i) sum += weights[static_cast<std::size_t>(i + m)] * in[j + i];
    out[j] = sum;
  }
}

}  // namespace growthuq
