// Line comparisons of a campaign (stats/line_comparisons.hpp; campaigns/README.md, "Line
// comparisons") from its data-uncertainty bootstrap, never from its Monte Carlo samples: per
// quantity, every pair of lines whose laws the bootstrap redrew (DataUncertainty::resampled),
// the ratio of the campaign's medians with the percentile interval of the per-replicate ratios
// (replicate b of both lines is one replicate campaign), a Bonferroni-adjusted interval over the
// quantity's pairs, whether the pair differs, and the compact letters. Written as
// comparisons.csv and letters.csv, in results.h5 and on stdout after the data-uncertainty table.
//
// results.h5:
//   /line_comparisons   one row per quantity and pair: the columns of comparisons.csv
//                       (attribute method)
//   /line_letters       one row per quantity and line compared: quantity, line, letters
#pragma once

#include <span>
#include <string>
#include <vector>

#include "growthuq/campaign/data_uncertainty.hpp"
#include "growthuq/io/results_h5.hpp"
#include "growthuq/stats/line_comparisons.hpp"

namespace growthuq {

inline constexpr const char* comparisons_csv_name = "comparisons.csv";
inline constexpr const char* letters_csv_name = "letters.csv";

struct QuantityComparisons {
  std::string quantity;
  std::string unit;
  std::vector<std::string> lines;  // the lines compared, in campaign order
  LineComparisons result;
};

struct CampaignComparisons {
  std::vector<QuantityComparisons> quantities;  // those at least two resampled lines have
  std::vector<std::string> left_out;            // lines whose replicates vary by Monte Carlo only
};

// The comparisons of the bootstrap's `rows` (their median filled with the campaign's), lines in
// the order of `line_order` (the campaign's).
CampaignComparisons compare_campaign_lines(std::span<const DataUncertainty> rows, std::span<const std::string> line_order);

// Writes comparisons.csv and letters.csv to `directory` and the tables to `h5` (may be null),
// and returns the report for stdout; when nothing could be compared, writes nothing and returns
// one line saying why. `lines` is the campaign's number of lines (no line for fewer than two).
std::string write_line_comparisons(const CampaignComparisons& comparisons, std::size_t lines, ResultsH5Writer* h5,
                                   const std::string& directory);

// The line printed when the campaign has no data-uncertainty bootstrap (and two lines or more).
std::string comparisons_need_data_interval();

// comparisons.csv and letters.csv as text.
std::string comparisons_csv_text(const CampaignComparisons& comparisons);
std::string letters_csv_text(const CampaignComparisons& comparisons);

}  // namespace growthuq
