// The two halves of a Latin hypercube column (latin_hypercube.hpp) on a caller-owned generator,
// so a design can shuffle every column first and draw the stratum points later, a block at a
// time, straight into the quantile transform (no n-long array of points).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "growthuq/sampling/latin_hypercube.hpp"
#include "sampling/mt19937_64_block.hpp"

namespace growthuq::detail {

// A uniformly random permutation of `source` written to `out` (same size, in [1, 2^32 - 1]), by
// the "inside-out" Fisher-Yates shuffle (Durstenfeld 1964 as rearranged by Knuth, TAOCP vol. 2,
// 3.4.2; it copies while it shuffles): for i = 1, ..., n-1 in turn, j uniform in [0, i] by
// Lemire's method on 32-bit words (each 64-bit draw giving its high then its low half), then
// out[i] = out[j] and out[j] = source[i] (out[0] = source[0] to start). A low half left over at
// the end is discarded. The draws do not depend on the elements, so shuffling any source with
// the same generator state moves its elements as it moves 0, 1, ..., n-1:
// out[r] = source[shuffled_iota[r]].
void shuffled_copy(std::span<const double> source, std::span<double> out, Mt19937_64Block& random);

// sample_of_stratum = 0, 1, ..., n-1 shuffled (above): stratum k goes to sample sample_of_stratum[k].
void shuffle_strata(std::span<std::uint32_t> sample_of_stratum, Mt19937_64Block& random);

// The points u_k of strata k = first .. first + u.size() - 1 of n, in increasing k, one fresh
// draw per stratum for StratumPosition::random (none for centred).
void stratum_points(Mt19937_64Block& random, std::size_t n, std::size_t first, std::span<double> u,
                    StratumPosition position);

}  // namespace growthuq::detail
