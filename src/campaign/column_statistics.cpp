#include "campaign/column_statistics.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace growthuq {
namespace {

// The message's fixed part, before the ranks: see ColumnStatistics::encode.
constexpr std::size_t header_size = 18;

}  // namespace

std::vector<double> ColumnStatistics::encode() const {
  const std::size_t ranks = analysis.twice_ranks.size();
  std::vector<double> message = {static_cast<double>(analysis.verdict), static_cast<double>(analysis.moments.count),
                                 analysis.moments.mean, analysis.moments.squared_deviations, summary ? 1.0 : 0.0};
  const QuantitySummary s = summary.value_or(QuantitySummary{});
  message.insert(message.end(), {static_cast<double>(s.n), static_cast<double>(s.n_flagged), s.median, s.q1, s.q3, s.iqr,
                                 s.p10, s.p90, s.mean, s.sd, s.median_ci_low, s.median_ci_high, static_cast<double>(ranks)});
  message.resize(header_size + (ranks + 1) / 2);
  if (ranks > 0) std::memcpy(message.data() + header_size, analysis.twice_ranks.data(), ranks * sizeof(std::uint32_t));
  return message;
}

ColumnStatistics ColumnStatistics::decode(std::span<const double> message) {
  if (message.size() < header_size) throw std::logic_error("column statistics message too short");
  // Read in encode()'s order.
  std::size_t at = 0;
  const auto next = [&] { return message[at++]; };
  const auto next_count = [&] { return static_cast<std::size_t>(next()); };
  ColumnStatistics statistics;
  ColumnAnalysis& analysis = statistics.analysis;
  analysis.verdict = static_cast<ColumnAnalysis::Verdict>(static_cast<int>(next()));
  analysis.moments.count = next_count();
  analysis.moments.mean = next();
  analysis.moments.squared_deviations = next();
  const bool has_summary = next() != 0.0;
  QuantitySummary s;
  s.n = next_count();
  s.n_flagged = next_count();
  for (double* field : {&s.median, &s.q1, &s.q3, &s.iqr, &s.p10, &s.p90, &s.mean, &s.sd, &s.median_ci_low, &s.median_ci_high}) {
    *field = next();
  }
  if (has_summary) statistics.summary = s;
  const std::size_t ranks = next_count();
  if (message.size() != header_size + (ranks + 1) / 2) throw std::logic_error("column statistics message of unexpected size");
  analysis.twice_ranks.resize(ranks);
  if (ranks > 0) std::memcpy(analysis.twice_ranks.data(), message.data() + header_size, ranks * sizeof(std::uint32_t));
  return statistics;
}

ColumnStatistics column_statistics(const ResultColumn& column, std::span<const double> values,
                                   std::span<const std::uint32_t> strata, std::span<const std::uint32_t> used,
                                   bool summarize) {
  // The summary counts the samples holding a value (holds_value); the analysis the ok ones,
  // whose values an output always holds. They differ when a sample holds a value without being
  // ok: an input of a flagged sample, p and E of a sample a later model flagged, v = 0 of a
  // no_growth sample.
  const auto holding = static_cast<std::size_t>(std::count_if(values.begin(), values.end(), holds_value));
  const bool counts_more = holding != used.size();
  ColumnStatistics statistics;
  const bool analyzed = used.size() >= 3;  // analyze_line's minimum
  std::vector<std::size_t> positions;
  if (summarize && !counts_more) positions = summary_positions(used.size());
  if (analyzed) statistics.analysis = analyze_column(values, used, positions, strata);
  if (!summarize) return statistics;
  if (analyzed && !counts_more && statistics.analysis.verdict == ColumnAnalysis::Verdict::used) {
    statistics.summary = summary_from_order("", column, values.size() - used.size(), statistics.analysis.moments,
                                            statistics.analysis.order_statistics);
  } else {
    ResultColumn copy{column.quantity, column.unit, column.is_input, {values.begin(), values.end()}};
    statistics.summary = summarize_quantity("", copy);
  }
  return statistics;
}

std::vector<double> ColumnStatisticsBatch::encode() const {
  std::vector<double> message;
  for (const auto& [index, statistics] : columns) {
    const std::vector<double> column = statistics.encode();
    message.push_back(static_cast<double>(index));
    message.push_back(static_cast<double>(column.size()));
    message.insert(message.end(), column.begin(), column.end());
  }
  return message;
}

ColumnStatisticsBatch ColumnStatisticsBatch::decode(std::span<const double> message) {
  ColumnStatisticsBatch batch;
  for (std::size_t at = 0; at < message.size();) {
    if (message.size() - at < 2) throw std::logic_error("column statistics batch cut short");
    const auto index = static_cast<std::size_t>(message[at]);
    const auto size = static_cast<std::size_t>(message[at + 1]);
    if (message.size() - at - 2 < size) throw std::logic_error("column statistics batch cut short");
    batch.columns.emplace_back(index, ColumnStatistics::decode(message.subspan(at + 2, size)));
    at += 2 + size;
  }
  return batch;
}

}  // namespace growthuq
