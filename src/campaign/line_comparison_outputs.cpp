#include "campaign/line_comparison_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "campaign/report_text.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/io/output_file.hpp"

namespace growthuq {
namespace {

const std::vector<std::string> comparison_columns{"quantity",        "unit",           "line_a",         "line_b",
                                                   "ratio",           "data_ci_low",    "data_ci_high",   "adjusted_ci_low",
                                                   "adjusted_ci_high", "adjusted_level", "replicates",     "differs",
                                                   "note"};

constexpr const char* method_text =
    "ratio of medians line_a / line_b; data_ci_low/high: 2.5 and 97.5 % quantiles of the ratios of the two lines' "
    "medians in each replicate of the data-uncertainty bootstrap (replicate b of both lines is one replicate "
    "campaign); adjusted_ci_low/high: the Bonferroni-adjusted interval, quantiles alpha/(2m) and 1 - alpha/(2m) for "
    "the m pairs of the quantity, alpha = 0.05 (level adjusted_level = 1 - alpha/m); differs = yes when the adjusted "
    "interval excludes 1, so the family-wise false-positive rate per quantity is about 5 %; empty when "
    "undetermined (note says why). Letters: compact letter display (Piepho 2004), lines sharing a letter are not "
    "distinguishable. Never from the Monte Carlo sample count.";

// One pair's cells in the order of comparison_columns.
std::vector<std::string> pair_cells(const QuantityComparisons& q, const PairComparison& pair) {
  return {q.quantity,
          q.unit,
          q.lines[pair.line_a],
          q.lines[pair.line_b],
          number_cell(pair.ratio),
          number_cell(pair.ci_low),
          number_cell(pair.ci_high),
          number_cell(pair.adjusted_low),
          number_cell(pair.adjusted_high),
          number_cell(q.result.adjusted_level),
          std::to_string(pair.replicates),
          differs_cell(pair.decision),
          pair.reason};
}

std::string percent(double fraction) { return significant(100.0 * fraction) + " %"; }

std::string comma_joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

std::string report(const CampaignComparisons& comparisons) {
  std::size_t line_width = 8;
  for (const QuantityComparisons& q : comparisons.quantities) {
    for (const std::string& line : q.lines) line_width = std::max(line_width, line.size() + 2);
  }
  std::string text =
      "\nline comparisons (ratio of medians line_a / line_b with its data interval from the bootstrap's replicates, "
      "never from the Monte Carlo sample count; Bonferroni over the m pairs of a quantity: a pair differs when its "
      "1 - 0.05/m interval excludes 1):\n" +
      padded("quantity", 10) + padded("line_a", line_width) + padded("line_b", line_width) + padded("ratio", 10) +
      padded("data 95 % interval", 22) + padded("adjusted interval", 22) + padded("level", 9) +
      padded("replicates", 11) + "differs\n";
  std::vector<std::string> notes;
  for (const QuantityComparisons& q : comparisons.quantities) {
    for (const PairComparison& pair : q.result.comparisons) {
      const std::string decision = pair.decision == PairDecision::undetermined ? "undetermined" : differs_cell(pair.decision);
      text += padded(q.quantity, 10) + padded(q.lines[pair.line_a], line_width) + padded(q.lines[pair.line_b], line_width) +
              padded(significant(pair.ratio), 10) +
              padded("[" + significant(pair.ci_low) + ", " + significant(pair.ci_high) + "]", 22) +
              padded("[" + significant(pair.adjusted_low) + ", " + significant(pair.adjusted_high) + "]", 22) +
              padded(percent(q.result.adjusted_level), 9) + padded(std::to_string(pair.replicates), 11) + decision + "\n";
      if (!pair.reason.empty()) {
        notes.push_back("  " + q.quantity + " " + q.lines[pair.line_a] + " / " + q.lines[pair.line_b] + " undetermined: " +
                        pair.reason + "\n");
      }
    }
  }
  for (const std::string& note : notes) text += note;
  const auto trimmed = [](const std::string& row) { return row.substr(0, row.find_last_not_of(' ') + 1) + "\n"; };
  text += "letters (compact letter display, Piepho 2004: lines sharing a letter are not distinguishable; '-': not "
          "compared):\n";
  std::string header = padded("line", line_width);
  std::vector<std::string> lines;  // every line compared in some quantity, in campaign order of first appearance
  for (const QuantityComparisons& q : comparisons.quantities) {
    header += padded(q.quantity, 8);
    for (const std::string& line : q.lines) {
      if (std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
    }
  }
  text += trimmed(header);
  for (const std::string& line : lines) {
    std::string row = padded(line, line_width);
    for (const QuantityComparisons& q : comparisons.quantities) {
      const auto at = std::find(q.lines.begin(), q.lines.end(), line);
      row += padded(at == q.lines.end() ? "-" : q.result.letters[static_cast<std::size_t>(at - q.lines.begin())], 8);
    }
    text += trimmed(row);
  }
  if (!comparisons.left_out.empty()) {
    text += "not compared: " + comma_joined(comparisons.left_out) +
            " (laws from line files: the bootstrap keeps them, or redraws only those that state tubes, so their "
            "intervals are lower bounds)\n";
  }
  return text;
}

void write_h5(ResultsH5Writer& h5, const CampaignComparisons& comparisons) {
  // The columns of comparison_columns; ratios, levels and counts are pure numbers.
  std::vector<ExtraColumn> table;
  for (const std::string& name : comparison_columns) table.push_back(ExtraColumn{.name = name});
  for (std::size_t c = 4; c <= 10; ++c) table[c].unit = "1";
  for (const QuantityComparisons& q : comparisons.quantities) {
    for (const PairComparison& pair : q.result.comparisons) {
      const std::vector<std::string> cells = pair_cells(q, pair);
      for (const std::size_t c : {0, 1, 2, 3, 11, 12}) table[c].text.push_back(cells[c]);
      for (const auto& [c, value] : {std::pair{4, pair.ratio}, {5, pair.ci_low}, {6, pair.ci_high}, {7, pair.adjusted_low},
                                     {8, pair.adjusted_high}, {9, q.result.adjusted_level}}) {
        table[static_cast<std::size_t>(c)].real.push_back(value);
      }
      table[10].integer.push_back(static_cast<std::int64_t>(pair.replicates));
    }
  }
  h5.write_table("line_comparisons", table);
  h5.write_attribute("line_comparisons", "method", std::string(method_text));
  ExtraColumn quantity{"quantity"}, line{"line"}, letters{"letters"};
  for (const QuantityComparisons& q : comparisons.quantities) {
    for (std::size_t i = 0; i < q.lines.size(); ++i) {
      quantity.text.push_back(q.quantity);
      line.text.push_back(q.lines[i]);
      letters.text.push_back(q.result.letters[i]);
    }
  }
  h5.write_table("line_letters", {quantity, line, letters});
}

}  // namespace

CampaignComparisons compare_campaign_lines(std::span<const DataUncertainty> rows, std::span<const std::string> line_order) {
  CampaignComparisons comparisons;
  std::vector<std::string> quantities;
  for (const DataUncertainty& row : rows) {
    if (std::find(quantities.begin(), quantities.end(), row.quantity) == quantities.end()) quantities.push_back(row.quantity);
    const bool listed = std::find(comparisons.left_out.begin(), comparisons.left_out.end(), row.line) != comparisons.left_out.end();
    if (!row.resampled && !listed) comparisons.left_out.push_back(row.line);
  }
  for (const std::string& quantity : quantities) {
    QuantityComparisons q;
    q.quantity = quantity;
    std::vector<double> medians;
    std::vector<std::vector<double>> replicates;
    for (const std::string& line : line_order) {
      const auto row = std::find_if(rows.begin(), rows.end(), [&](const DataUncertainty& r) {
        return r.line == line && r.quantity == quantity && r.resampled;
      });
      if (row == rows.end()) continue;
      q.unit = row->unit;
      q.lines.push_back(line);
      medians.push_back(row->median);
      // Every replicate in its place b (NaN where this line had no median), so that replicate b
      // of two lines is compared with itself.
      std::vector<double> by_replicate(row->replicates + row->failed, std::numeric_limits<double>::quiet_NaN());
      for (std::size_t i = 0; i < row->replicate_medians.size(); ++i) {
        by_replicate.at(row->replicate_indices.at(i)) = row->replicate_medians[i];
      }
      replicates.push_back(std::move(by_replicate));
    }
    if (q.lines.size() < 2) continue;
    q.result = compare_lines(medians, replicates);
    comparisons.quantities.push_back(std::move(q));
  }
  return comparisons;
}

std::string comparisons_csv_text(const CampaignComparisons& comparisons) {
  CsvWriter writer(comparison_columns);
  for (const QuantityComparisons& q : comparisons.quantities) {
    for (const PairComparison& pair : q.result.comparisons) writer.add_row(pair_cells(q, pair));
  }
  return writer.text();
}

std::string letters_csv_text(const CampaignComparisons& comparisons) {
  CsvWriter writer({"quantity", "line", "letters"});
  for (const QuantityComparisons& q : comparisons.quantities) {
    for (std::size_t i = 0; i < q.lines.size(); ++i) writer.add_row({q.quantity, q.lines[i], q.result.letters[i]});
  }
  return writer.text();
}

std::string comparisons_need_data_interval() {
  return "\nline comparisons: not made: they need the data interval of a [data_uncertainty] bootstrap over raw-data "
         "lines, which this run has not (the Monte Carlo interval shrinks with the sample count and would tell any "
         "lines apart)\n";
}

std::string write_line_comparisons(const CampaignComparisons& comparisons, std::size_t lines, ResultsH5Writer* h5,
                                   const std::string& directory) {
  if (lines < 2) return {};
  if (comparisons.quantities.empty()) {
    const std::string names = comma_joined(comparisons.left_out);
    return "\nline comparisons: not made: they need two lines or more given by raw data (only their laws are "
           "all redrawn" + (names.empty() ? std::string() : "; " + names + " from line files") + ")\n";
  }
  namespace fs = std::filesystem;
  write_file_atomically((fs::path(directory) / comparisons_csv_name).string(), comparisons_csv_text(comparisons), Overwrite::allow);
  write_file_atomically((fs::path(directory) / letters_csv_name).string(), letters_csv_text(comparisons), Overwrite::allow);
  if (h5 != nullptr) write_h5(*h5, comparisons);
  return report(comparisons);
}

}  // namespace growthuq
