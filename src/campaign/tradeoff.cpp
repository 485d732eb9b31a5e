#include "growthuq/campaign/tradeoff.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

#include "growthuq/core/numbers.hpp"
#include "growthuq/io/csv.hpp"
#include "campaign/tradeoff_worst.hpp"

namespace growthuq {
namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

// 100 |value - reference| / |reference|. Equal values (the reference against itself, or two
// zero medians) are exactly 0; a zero reference makes a relative error meaningless (NaN).
double relative_error_pct(double value, double reference) {
  if (!std::isfinite(value) || !std::isfinite(reference)) return not_a_number;
  if (value == reference) return 0.0;
  if (reference == 0.0) return not_a_number;
  return 100.0 * std::abs(value - reference) / std::abs(reference);
}

double error_over_half_width(double median, double reference, double ci_low, double ci_high) {
  if (!std::isfinite(median) || !std::isfinite(reference) || !std::isfinite(ci_low) || !std::isfinite(ci_high)) {
    return not_a_number;
  }
  const double error = std::abs(median - reference);
  if (error == 0.0) return 0.0;
  const double half_width = 0.5 * (ci_high - ci_low);
  return half_width > 0 ? error / half_width : not_a_number;
}

std::string number_cell(double value) { return std::isfinite(value) ? format_double(value) : std::string(); }

void keep_worst(TradeoffWorst& worst, double value, const TradeoffRow& row, bool first) {
  keep_worst_error(worst, value, row.line, row.quantity, first);
}

// The smallest of 1, 2, 5 x 10^k that is >= `count`.
std::size_t round_up_to_1_2_5(double count) {
  double decade = 1;
  while (true) {
    for (const double step : {1.0, 2.0, 5.0}) {
      if (step * decade >= count) return static_cast<std::size_t>(step * decade);
    }
    decade *= 10;
  }
}

// The summary of `line` and `quantity` in `run`; nullptr when the run lacks it.
const QuantitySummary* find_summary(const TradeoffRun& run, const std::string& line, const std::string& quantity) {
  for (const QuantitySummary& s : run.summaries) {
    if (s.line == line && s.quantity == quantity) return &s;
  }
  return nullptr;
}

}  // namespace

std::vector<TradeoffRow> tradeoff_rows(std::span<const TradeoffRun> runs) {
  // The reference run of each fidelity: the one with the most samples.
  std::map<std::string, const TradeoffRun*> references;
  for (const TradeoffRun& run : runs) {
    const TradeoffRun*& reference = references[run.fidelity];
    if (reference == nullptr || run.samples > reference->samples) reference = &run;
  }
  const auto fe_reference = references.find(std::string(shell_fe_label));
  const TradeoffRun* fe_reference_run = fe_reference == references.end() ? nullptr : fe_reference->second;
  std::vector<TradeoffRow> rows;
  for (const TradeoffRun& run : runs) {
    const TradeoffRun& reference_run = *references.at(run.fidelity);
    for (const QuantitySummary& s : run.summaries) {
      TradeoffRow row;
      row.fidelity = run.fidelity;
      row.samples = run.samples;
      row.seconds = run.seconds;
      row.line = s.line;
      row.quantity = s.quantity;
      row.unit = s.unit;
      row.n = s.n;
      row.median = s.median;
      row.iqr = s.iqr;
      row.median_ci_low = s.median_ci_low;
      row.median_ci_high = s.median_ci_high;
      const QuantitySummary* reference = find_summary(reference_run, s.line, s.quantity);
      row.reference_median = reference ? reference->median : not_a_number;
      row.reference_iqr = reference ? reference->iqr : not_a_number;
      row.median_error_pct = relative_error_pct(row.median, row.reference_median);
      row.iqr_error_pct = relative_error_pct(row.iqr, row.reference_iqr);
      row.median_error_over_ci_half_width =
          error_over_half_width(row.median, row.reference_median, row.median_ci_low, row.median_ci_high);
      const QuantitySummary* fe = fe_reference_run ? find_summary(*fe_reference_run, s.line, s.quantity) : nullptr;
      row.fe_reference_median = fe ? fe->median : not_a_number;
      row.fe_reference_iqr = fe ? fe->iqr : not_a_number;
      row.fe_median_error_pct = relative_error_pct(row.median, row.fe_reference_median);
      row.fe_iqr_error_pct = relative_error_pct(row.iqr, row.fe_reference_iqr);
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

std::vector<std::string> tradeoff_csv_header() {
  return {"fidelity", "samples", "seconds", "line", "quantity", "unit", "n", "median", "iqr", "median_ci_low",
          "median_ci_high", "reference_median", "reference_iqr", "median_error_pct", "iqr_error_pct",
          "median_error_over_ci_half_width", "fe_reference_median", "fe_reference_iqr", "fe_median_error_pct",
          "fe_iqr_error_pct"};
}

std::string tradeoff_csv_text(std::span<const TradeoffRow> rows) {
  CsvWriter writer(tradeoff_csv_header());
  for (const TradeoffRow& r : rows) {
    writer.add_row({r.fidelity, std::to_string(r.samples), number_cell(r.seconds), r.line, r.quantity, r.unit,
                    std::to_string(r.n), number_cell(r.median), number_cell(r.iqr), number_cell(r.median_ci_low),
                    number_cell(r.median_ci_high), number_cell(r.reference_median), number_cell(r.reference_iqr),
                    number_cell(r.median_error_pct), number_cell(r.iqr_error_pct),
                    number_cell(r.median_error_over_ci_half_width), number_cell(r.fe_reference_median),
                    number_cell(r.fe_reference_iqr), number_cell(r.fe_median_error_pct),
                    number_cell(r.fe_iqr_error_pct)});
  }
  return writer.text();
}

TradeoffVerdict judge_tradeoff(std::span<const TradeoffRow> rows, std::string_view fidelity, double target_pct) {
  if (!(target_pct > 0)) throw std::invalid_argument("judge_tradeoff: the target must be positive");
  TradeoffVerdict verdict;
  verdict.fidelity = std::string(fidelity);
  verdict.target_pct = target_pct;

  std::map<std::size_t, TradeoffCount> counts;  // ordered by sample count
  std::map<std::size_t, std::vector<const TradeoffRow*>> rows_of_count;
  for (const TradeoffRow& row : rows) {
    if (row.fidelity == fidelity) rows_of_count[row.samples].push_back(&row);
  }
  if (rows_of_count.size() < 2) {
    throw std::invalid_argument("judge_tradeoff: fewer than two sample counts of fidelity '" + verdict.fidelity + "'");
  }
  verdict.reference_samples = rows_of_count.rbegin()->first;

  for (const auto& [samples, members] : rows_of_count) {
    TradeoffCount count;
    count.samples = samples;
    count.seconds = members.front()->seconds;
    count.meets_target = true;
    bool first = true;
    for (const TradeoffRow* row : members) {
      keep_worst(count.median_error_pct, row->median_error_pct, *row, first);
      keep_worst(count.iqr_error_pct, row->iqr_error_pct, *row, first);
      keep_worst(count.median_error_over_ci_half_width, row->median_error_over_ci_half_width, *row, first);
      first = false;
      // NaN compares false: an undefined error never meets the target.
      if (!(row->median_error_pct < target_pct && row->iqr_error_pct < target_pct)) count.meets_target = false;
    }
    verdict.counts.push_back(count);
  }

  // Walk down from the largest count below the reference while counts keep meeting the target.
  const std::size_t reference_index = verdict.counts.size() - 1;
  for (std::size_t i = reference_index; i-- > 0;) {
    if (!verdict.counts[i].meets_target) break;
    verdict.smallest_meeting_target = verdict.counts[i].samples;
  }

  bool first = true;
  for (const TradeoffRow* row : rows_of_count.rbegin()->second) {
    double half_width_pct = not_a_number;
    if (std::isfinite(row->median_ci_low) && std::isfinite(row->median_ci_high) && row->median != 0) {
      half_width_pct = 100.0 * 0.5 * (row->median_ci_high - row->median_ci_low) / std::abs(row->median);
    }
    keep_worst(verdict.reference_ci_half_width_pct, half_width_pct, *row, first);
    first = false;
  }
  verdict.reference_precise_enough =
      verdict.reference_ci_half_width_pct.value <= reference_precision_fraction_of_target * target_pct;

  if (!verdict.smallest_meeting_target) {
    const TradeoffCount& last = verdict.counts[reference_index - 1];
    const bool iqr_worse = worse_error(last.iqr_error_pct.value, last.median_error_pct.value);
    verdict.remaining_error_pct = iqr_worse ? last.iqr_error_pct : last.median_error_pct;
    verdict.remaining_statistic = iqr_worse ? "IQR" : "median";
    const double remaining = verdict.remaining_error_pct.value;
    if (std::isfinite(remaining)) {
      // Errors of quantiles fall like 1/sqrt(n): n (remaining / target)^2 reaches the target.
      const double ratio = remaining / target_pct;
      const double needed = static_cast<double>(last.samples) * ratio * ratio;
      if (needed < 1e18) verdict.estimated_samples_needed = round_up_to_1_2_5(needed);
    }
  }
  return verdict;
}

}  // namespace growthuq
