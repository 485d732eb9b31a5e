#include "campaign/line_schedule.hpp"

#include <limits>
#include <stdexcept>

namespace growthuq {

LineSchedule::LineSchedule(std::size_t lines, int processes) : lines_(lines), processes_(processes) {
  if (processes < 1) throw std::invalid_argument("LineSchedule: at least one process");
}

int LineSchedule::designer_of(std::size_t line) const {
  if (processes_ == 1 || line == 0) return 0;
  return 1 + static_cast<int>((line - 1) % static_cast<std::size_t>(processes_ - 1));
}

std::vector<std::size_t> LineSchedule::designed_at_start(std::size_t line, int rank) const {
  std::vector<std::size_t> designed;
  if (processes_ == 1) {
    designed.push_back(line);
  } else if (line == 0) {
    if (rank == 0) designed.push_back(0);
    if (lines_ > 1 && rank == designer_of(1)) designed.push_back(1);
  }
  return designed;
}

std::optional<std::size_t> LineSchedule::designed_during_statistics(std::size_t line) const {
  const std::size_t next = line + 1;
  if (processes_ == 1 || next < 2 || next >= lines_) return std::nullopt;
  return next;
}

std::vector<int> LineSchedule::statistics_owners(std::size_t line, const std::vector<double>& costs) const {
  std::vector<double> load(static_cast<std::size_t>(processes_), 0.0);
  load[0] = coordinator_load;
  if (const std::optional<std::size_t> ahead = designed_during_statistics(line)) {
    load[static_cast<std::size_t>(designer_of(*ahead))] = std::numeric_limits<double>::infinity();
  }
  std::vector<int> owner;
  for (const double cost : costs) {
    int best = processes_ - 1;
    for (int p = processes_ - 1; p >= 0; --p) {
      if (load[static_cast<std::size_t>(p)] < load[static_cast<std::size_t>(best)]) best = p;
    }
    owner.push_back(best);
    load[static_cast<std::size_t>(best)] += cost;
  }
  return owner;
}

}  // namespace growthuq
