// Ranks of a sample: ordinal ranks (every value its own rank, ties broken by position), used by
// Iman-Conover, and average ranks (ties share the mean of their positions), used for Spearman
// correlation of data that may tie. Also a fast argsort of doubles.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace growthuq {

// Indices that sort `values` ascending; equal values keep their order (stable). NaN is not
// allowed (the caller checks). Uses an LSD radix sort on the IEEE-754 bits for large inputs.
std::vector<std::uint32_t> argsort(std::span<const double> values);

// 0-based ordinal ranks: rank[i] = position of values[i] in the stable ascending order.
std::vector<std::uint32_t> ordinal_ranks(std::span<const double> values);

// 1-based average ranks ("fractional ranking"): tied values get the mean of their positions.
std::vector<double> average_ranks(std::span<const double> values);

}  // namespace growthuq
