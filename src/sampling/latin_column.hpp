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

// Fisher-Yates from the last position down with the draws documented in latin_hypercube.hpp
// (32-bit Lemire, high half of each draw first); a low half left over at the end is discarded.
// The draws do not depend on the elements, so shuffling any array with the same generator
// state moves its elements exactly as it moves 0, 1, ..., n-1: shuffle(x)[i] = x[shuffle(iota)[i]].
// values.size() must be in [1, 2^32 - 1].
void shuffle(std::span<std::uint32_t> values, Mt19937_64Block& random);
void shuffle(std::span<double> values, Mt19937_64Block& random);

// stratum = 0, 1, ..., n-1 shuffled (above): stratum[i] is the stratum of sample i.
void shuffle_strata(std::span<std::uint32_t> stratum, Mt19937_64Block& random);

// The points u_k of strata k = first .. first + u.size() - 1 of n, in increasing k, one fresh
// draw per stratum for StratumPosition::random (none for centred).
void stratum_points(Mt19937_64Block& random, std::size_t n, std::size_t first, std::span<double> u,
                    StratumPosition position);

}  // namespace growthuq::detail
