// exp for the lognormal quantile, written so that a batch loop vectorizes it (branch-free, no
// table, no library call) and gives the same bits in every lane width: SSE2 scalar, SSE2 and
// AVX2 vectors use the same IEEE operations in the same order (no fused multiply-add, see
// core/avx2_clone.hpp). The algorithm is Moshier's Cephes exp (Cephes Math Library, 1984-
// 2000, exp.c): k = round(x / ln 2), r = x - k ln 2 in two parts (Cody & Waite 1980), the
// Pade form exp(r) = 1 + 2 r P(r^2) / (Q(r^2) - r P(r^2)) on |r| <= ln(2)/2, whose relative
// error Cephes reports as 2.2e-16 peak over the double range (here without fused multiply-add:
// within 2 ulps of glibc's exp, tests/distributions/test_vector_exp.cpp; glibc's own 2-lane
// vector exp, used before, is within 4). 1.7 ns per value with AVX2 against 2.6 for that one,
// measured. The scale 2^k is applied as two powers of two, so results that underflow into
// subnormals are rounded once.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

namespace growthuq::detail {

// Beyond [-746, 710] every result is 0 or +inf, so arguments are clamped there first; NaN passes
// through unchanged. (Both clamps in the form x < c ? c : x, which compilers turn into vector
// max; the upper one on -x. Batch loops clamp in a pass of their own: a compiler that sees the
// clamp before the rest folds the clamped cases into constants behind branches, and then does
// not vectorize.)
inline double clamp_exp_argument(double x) {
  const double low_clamped = x < -746.0 ? -746.0 : x;
  const double negated = -low_clamped < -710.0 ? -710.0 : -low_clamped;
  return -negated;
}

// exp(x) for x in [-746, 710] or NaN.
inline double cephes_exp_clamped(double x) {
  constexpr double log2e = 1.4426950408889634073599;
  constexpr double ln2_high = 6.93145751953125e-1;  // few bits: k * ln2_high is exact
  constexpr double ln2_low = 1.42860682030941723212e-6;
  constexpr double round_shift = 0x1.8p52;  // adding it rounds a double below 2^51 to an integer
  const double k = (x * log2e + round_shift) - round_shift;
  const double r = (x - k * ln2_high) - k * ln2_low;
  const double rr = r * r;
  const double p = r * ((1.26177193074810590878e-4 * rr + 3.02994407707441961300e-2) * rr + 9.99999999999999999910e-1);
  const double q = ((3.00198505138664455042e-6 * rr + 2.52448340349684104192e-3) * rr + 2.27265548208155028766e-1) * rr +
                   2.00000000000000000009e0;
  const double e = 1.0 + 2.0 * (p / (q - p));
  // 2^k = 2^k1 2^k2, k1 = round(k / 2): each factor a normal double for |k| <= 1100. The
  // exponent field of 2^m is m + 1023; (m + 1023 + 2^52) holds it in its low mantissa bits.
  const double k1 = (k * 0.5 + round_shift) - round_shift;
  const double k2 = k - k1;
  const double scale1 = std::bit_cast<double>(std::bit_cast<std::uint64_t>(k1 + (1023.0 + 0x1p52)) << 52);
  const double scale2 = std::bit_cast<double>(std::bit_cast<std::uint64_t>(k2 + (1023.0 + 0x1p52)) << 52);
  return e * scale1 * scale2;
}

inline double cephes_exp(double x) { return cephes_exp_clamped(clamp_exp_argument(x)); }

// y[i] = exp(a + b x[i]) for i < n (in place allowed).
void exp_affine(const double* x, double* y, std::size_t n, double a, double b);

inline double exp_affine(double x, double a, double b) { return cephes_exp(a + b * x); }

}  // namespace growthuq::detail
