// Who does what for each line of a campaign run over several processes. Each line's design is
// made whole by one process, one line ahead: rank 0 makes line 0's while line 1's designer
// makes line 1's; then, while the processes compute line i's statistics, line i + 1's designer
// (process 1 + (i mod (K - 1)), never rank 0, which coordinates) takes no statistics and makes
// line i + 1's design. A design is the same whoever makes it, so results do not depend on K.
// Serially, the one process designs each line when it starts.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace growthuq {

class LineSchedule {
 public:
  // A run of `lines` lines over `processes` (>= 1) processes.
  LineSchedule(std::size_t lines, int processes);

  // The process that designs `line`.
  int designer_of(std::size_t line) const;

  // The lines process `rank` designs when line `line` starts, before it is shared (in order).
  std::vector<std::size_t> designed_at_start(std::size_t line, int rank) const;

  // The line designed ahead while `line`'s statistics are computed (its designer takes no
  // statistics columns), if any.
  std::optional<std::size_t> designed_during_statistics(std::size_t line) const;

  // Which process computes each statistics column of `line`, given each column's relative cost:
  // the next column (in order) goes to the process with the least work so far, ties to the
  // highest rank; the coordinator starts with coordinator_load for its writing, and the
  // designer of designed_during_statistics(line) gets none.
  std::vector<int> statistics_owners(std::size_t line, const std::vector<double>& costs) const;

  // What the coordinator does besides its statistics columns, in columns: it shares its core
  // with its writer thread, about half a column's work (measured).
  static constexpr double coordinator_load = 0.5;

 private:
  std::size_t lines_;
  int processes_;
};

}  // namespace growthuq
