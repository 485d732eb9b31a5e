// One column's share of a line's statistics (its rank analysis and, when the campaign reports
// the quantity, its summary), computed by whichever process the column was shared out to, and
// the message that carries a process's columns to the coordinator.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "growthuq/evaluation/line_result.hpp"
#include "growthuq/stats/line_analysis.hpp"
#include "growthuq/stats/quantity_summary.hpp"

namespace growthuq {

struct ColumnStatistics {
  ColumnAnalysis analysis;                 // without order_statistics once it has travelled
  std::optional<QuantitySummary> summary;  // line, quantity and unit left empty

  // As doubles: [verdict, count, mean, squared deviations, has summary,
  //   n, n_flagged, median, q1, q3, iqr, p10, p90, mean, sd, median_ci_low, median_ci_high,
  //   number of ranks, the ranks' bytes (two 32-bit ranks per double)].
  // decode(encode()) gives the same fields bit for bit, order statistics aside (they are used
  // where the column is computed); std::logic_error for a message of the wrong size.
  std::vector<double> encode() const;
  static ColumnStatistics decode(std::span<const double> message);
};

// The statistics of `column` (whose whole column of values is `values`): the analysis over the
// samples `used` (analysis_samples: the ok ones; none when fewer than 3, analyze_line's minimum)
// and, when `summarize`, its summary over the samples holding a value (holds_value). One sort
// serves both when they are the same samples (no sample holds a value without being ok, every ok
// value finite); otherwise summarize_quantity selects its own order statistics. `strata`: the
// design's ranks when the column's values strictly increase with them (analyze_column), else
// empty.
ColumnStatistics column_statistics(const ResultColumn& column, std::span<const double> values,
                                   std::span<const std::uint32_t> strata, std::span<const std::uint32_t> used,
                                   bool summarize);

// The columns one process computed, as it sends them to the coordinator:
//   for each column: [column index, message size, ColumnStatistics message].
struct ColumnStatisticsBatch {
  std::vector<std::pair<std::size_t, ColumnStatistics>> columns;

  std::vector<double> encode() const;
  static ColumnStatisticsBatch decode(std::span<const double> message);
};

}  // namespace growthuq
