// Latin hypercube designs on the unit interval, one variable (column) at a time: [0,1) is cut
// into n equal strata, every stratum holds exactly one point, and the strata are assigned to the
// samples by a random permutation (McKay, Beckman & Conover 1979). The permutation is kept:
// the stratum of sample i is also its rank in the column, which Iman-Conover and the mapping
// through the marginal use instead of sorting.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace growthuq {

enum class StratumPosition {
  random,  // uniform inside the stratum (default)
  centred  // the stratum's midpoint
};

// One variable's column of a Latin hypercube.
struct LatinColumn {
  std::vector<std::uint32_t> stratum;  // stratum[i]: stratum (= rank, 0-based) of sample i; a permutation
  std::vector<double> u_by_stratum;    // u_by_stratum[k]: the point in stratum k, in (0,1), increasing in k
};

// Lower edge of stratum k of n: k * (1/n) in double precision. Stratum k is
// [stratum_edge(k, n), stratum_edge(k + 1, n)), the last one ends below 1.
double stratum_edge(std::size_t k, std::size_t n) noexcept;

// The column for n >= 1 samples (n < 2^32) from RandomStream(key) (see random_stream.hpp):
// first the permutation: 0, 1, ..., n-1 shuffled by the inside-out Fisher-Yates shuffle
// (i = 1 .. n-1: j uniform in [0, i] by Lemire's method on 32-bit words, each 64-bit draw
// giving its high then its low half; a[i] = a[j], a[j] = i; Eq. (S4), src/sampling/README.md)
// gives sigma, and stratum k goes to sample
// sigma[k] (stratum[sigma[k]] = k); then, for StratumPosition::random, one open uniform U_k
// per stratum from fresh 64-bit draws, in increasing k, u_k = (k + U_k)/n (kept inside its
// stratum and inside (0,1) against rounding). Handing strata to samples (rather than samples
// to strata) lets a design compute values in stratum order and write each one once.
LatinColumn latin_hypercube_column(std::size_t n, std::uint64_t key, StratumPosition position);

}  // namespace growthuq
