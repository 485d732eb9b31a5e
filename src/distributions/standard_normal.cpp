// Phi^-1 by Wichura's AS241 (as GSL's gsl_cdf_ugaussian_Pinv), inlined from as241.hpp. The
// batch form runs in three passes so the compiler vectorizes the first two: validate every u,
// evaluate the central rational function everywhere (85 % of uniform u fall there), then redo
// the tail values with the logarithmic branches.
#include "growthuq/distributions/standard_normal.hpp"

#include <cmath>
#include <stdexcept>

#include "distributions/as241.hpp"
#include "distributions/checks.hpp"
#include "sampling/avx2_clone.hpp"

namespace growthuq {
namespace {

// The central rational function over a batch. Its Horner chains are latency-bound, so wider
// vectors help directly (AVX2 clone: 6.4 -> 2.7 ns per value measured); same bits as the
// scalar as241 in either clone (avx2_clone.hpp).
GROWTHUQ_AVX2_CLONE
void central_pass(const double* u, double* x, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) x[i] = detail::as241_central(u[i] - 0.5);
}

}  // namespace

double standard_normal_quantile(double u) {
  detail::require_probability("standard normal", u);
  return detail::as241(u);
}

void standard_normal_quantiles(std::span<const double> u, std::span<double> x) {
  if (u.size() != x.size()) throw std::invalid_argument("standard_normal_quantiles: spans of different sizes");
  const std::size_t n = u.size();
  long outside = 0;
  for (std::size_t i = 0; i < n; ++i) outside += (u[i] >= 0.0 && u[i] <= 1.0) ? 0 : 1;
  if (outside != 0) {
    for (std::size_t i = 0; i < n; ++i) detail::require_probability("standard normal", u[i]);
  }
  central_pass(u.data(), x.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    if (std::fabs(u[i] - 0.5) > 0.425) x[i] = detail::as241(u[i]);
  }
}

}  // namespace growthuq
