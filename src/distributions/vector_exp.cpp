#include "distributions/vector_exp.hpp"

#include "core/avx2_clone.hpp"

namespace growthuq::detail {

GROWTHUQ_AVX2_CLONE
void exp_affine(const double* x, double* y, std::size_t n, double a, double b) {
  for (std::size_t i = 0; i < n; ++i) y[i] = clamp_exp_argument(a + b * x[i]);
  for (std::size_t i = 0; i < n; ++i) y[i] = cephes_exp_clamped(y[i]);
}

}  // namespace growthuq::detail
