// The speed/accuracy trade of a campaign (issue 4, "The trade"): the same campaign run at
// increasing sample counts and at several fidelities, each count's per-line, per-quantity median
// and IQR compared with those of the same fidelity's run with the most samples (its sampling
// convergence) and with the shell_fe run with the most samples (its distance from the
// finite-element model), and the smallest count that meets a requested accuracy. Pure functions
// of the runs' summaries; tradeoff_run.hpp runs the campaign, tradeoff_choice.hpp picks the
// cheapest run against the finite-element reference.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "growthuq/evaluation/line_result.hpp"

namespace growthuq {

// The campaign run once at one sample count per line.
struct TradeoffRun {
  std::string fidelity;     // to_string(Fidelity): "closed_form", "corrected" or "shell_fe"
  std::size_t samples = 0;  // per line
  double seconds = 0;       // wall time of the campaign's run at this count (not its preparation)
  std::vector<QuantitySummary> summaries;  // the rows summary.csv would hold
};

// One row of tradeoff.csv: one sample count, line and quantity against the reference (the run
// of the same fidelity with the most samples). Undefined numbers are NaN (empty cells).
struct TradeoffRow {
  std::string fidelity;
  std::size_t samples = 0;
  double seconds = 0;
  std::string line;
  std::string quantity;
  std::string unit;
  std::size_t n = 0;  // samples that count in the statistics (summary.csv's n)
  double median = 0, iqr = 0, median_ci_low = 0, median_ci_high = 0;
  double reference_median = 0, reference_iqr = 0;
  // 100 |x - reference| / |reference|: 0 when equal (the reference rows), NaN when the
  // reference is 0 (a relative error means nothing there) or either side is undefined.
  double median_error_pct = 0, iqr_error_pct = 0;
  // |median - reference_median| / ((median_ci_high - median_ci_low) / 2): below about 1 the
  // count's median agrees with the reference within its own 95 % interval. NaN without an
  // interval (n <= 5) or when the interval has zero width and the medians differ.
  double median_error_over_ci_half_width = 0;
  // The same line and quantity in the shell_fe run with the most samples (the finite-element
  // reference), and the errors against it as above: how far this fidelity and count are from the
  // finite-element model. All NaN without a shell_fe run (or when it lacks the line/quantity).
  double fe_reference_median = 0, fe_reference_iqr = 0;
  double fe_median_error_pct = 0, fe_iqr_error_pct = 0;
};

// The fidelity label of the finite-element runs, whose largest run is the fe_ reference.
inline constexpr std::string_view shell_fe_label = "shell_fe";

// Every run's summaries as rows, runs in the order given, summaries in their order. A row's
// reference is the summary of the same line and quantity in the run of the same fidelity with
// the most samples (NaN reference cells when that run lacks it); its fe_ reference that of the
// run labelled shell_fe_label with the most samples.
std::vector<TradeoffRow> tradeoff_rows(std::span<const TradeoffRun> runs);

// The columns of tradeoff.csv, in order.
std::vector<std::string> tradeoff_csv_header();

// tradeoff.csv text: numbers in shortest round-trip form, undefined numbers as empty cells.
std::string tradeoff_csv_text(std::span<const TradeoffRow> rows);

// The largest value of one error over the lines x quantities of a sample count, and where.
// An undefined error (NaN) counts as larger than any number, so it is never hidden.
struct TradeoffWorst {
  double value = 0;
  std::string line;
  std::string quantity;
};

// One sample count of one fidelity, condensed over lines x quantities.
struct TradeoffCount {
  std::size_t samples = 0;
  double seconds = 0;
  TradeoffWorst median_error_pct;
  TradeoffWorst iqr_error_pct;
  TradeoffWorst median_error_over_ci_half_width;
  bool meets_target = false;  // every median and IQR error defined and below the target
};

// The reference's own precision is "well below" the target when the worst 95 % half-width of
// its medians is at most this fraction of the target: then the reference's own error (one
// standard deviation is about half-width / 1.96) is about an eighth of the target or less,
// and an error measured against it is mostly the smaller run's.
inline constexpr double reference_precision_fraction_of_target = 0.25;

struct TradeoffVerdict {
  std::string fidelity;
  double target_pct = 1.0;
  std::size_t reference_samples = 0;
  std::vector<TradeoffCount> counts;  // increasing sample counts, the reference last
  // The smallest count below the reference that meets the target, as does every larger count
  // below the reference (a count that passes by chance while a larger one fails is not offered).
  // Empty when even the largest count below the reference fails.
  std::optional<std::size_t> smallest_meeting_target;
  // The reference run's worst 95 % CI half-width of the median, in % of its median.
  TradeoffWorst reference_ci_half_width_pct;
  bool reference_precise_enough = false;  // <= reference_precision_fraction_of_target x target
  // When no count meets the target: the worse of the median and IQR errors left at the largest
  // count below the reference ("median" or "IQR" in remaining_statistic), and the count that
  // would meet the target if errors fall like 1/sqrt(n) (the Monte Carlo rate), rounded up to
  // 1, 2 or 5 x 10^k; 0 when the remaining error is undefined.
  TradeoffWorst remaining_error_pct;
  std::string remaining_statistic;
  std::size_t estimated_samples_needed = 0;
};

// Condenses the rows of `fidelity` against `target_pct` (> 0). std::invalid_argument when the
// rows hold fewer than two sample counts of that fidelity (the reference alone proves nothing).
TradeoffVerdict judge_tradeoff(std::span<const TradeoffRow> rows, std::string_view fidelity, double target_pct);

// The readable report: one row per sample count (time, worst median error, worst IQR error,
// worst error over CI half-width, with line and quantity), then the answer for the target and
// whether the reference is precise enough for it to mean something.
std::string format_tradeoff_report(const TradeoffVerdict& verdict);

}  // namespace growthuq
