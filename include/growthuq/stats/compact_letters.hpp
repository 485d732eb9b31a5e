// Compact letter display of all-pairwise comparisons: each line gets one or more letters, and two
// lines share a letter exactly when their comparison did not find them different, as published
// box plots mark them ("a", "ab", "b"). Built by the insert-and-absorb algorithm with the sweep
// that removes redundant letters (Piepho 2004; Eq. (T6), src/stats/README.md).
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace growthuq {

// The letters of `lines` lines (indices 0 .. lines - 1) given the pairs found different (each
// pair once, in any order of its two indices). Letters are ordered by the first line (lowest
// index) that carries them, so the first line always has "a"; after z come A-Z, then a', b', ...
// std::invalid_argument for an index out of range or a pair of a line with itself (a
// programming error, not user input).
std::vector<std::string> compact_letters(std::size_t lines,
                                         std::span<const std::pair<std::size_t, std::size_t>> differing);

}  // namespace growthuq
