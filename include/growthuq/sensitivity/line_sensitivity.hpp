// The sensitivity indices of one campaign line from its own samples (no further model run): the
// full first-order index of every input for every output (rank_first_order.hpp, Eqs. (S1),
// (S2b) of src/sensitivity/README.md), over the samples with status ok, as the line's other
// analyses (src/stats/README.md, Eq. (T3)).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "growthuq/evaluation/line_result.hpp"
#include "growthuq/sensitivity/rank_first_order.hpp"

namespace growthuq {

struct LineSensitivity {
  std::string line;
  std::vector<std::string> inputs;   // column names (k_N_per_m, ...), the rows of first_order
  std::vector<std::string> outputs;  // column names (p_MPa, ...), its columns
  std::vector<std::vector<RankIndexEstimate>> first_order;  // [input][output]
  std::size_t samples_used = 0;
  std::size_t sections = 0;  // K of the interval (S2b)
  // Why something is missing, one sentence each: a column left out (not finite over the samples
  // used, or constant), no indices at all (too few samples with status ok), or an output whose
  // variance its 1 % most extreme samples hold for the most part (the indices are then unstable).
  std::vector<std::string> notes;
};

// Over the first 100,000 samples with status ok at most (a note says so when there are more).
// Sections of the interval: 20, or fewer for a small line so that each holds >= 10 samples.
// Below 30 samples with status ok (3 sections of 10) there are no indices, and a note says so.
LineSensitivity line_sensitivity(const LineResult& result, std::uint64_t seed);

// Inputs as rows, outputs as columns, each cell "S [low, high]" (two decimals), the notes, and
// one line saying what S is. Ends with a newline; empty when there is neither an index nor a note.
std::string format_line_sensitivity(const LineSensitivity& sensitivity);

}  // namespace growthuq
