// The CSV results of a campaign: samples.csv, streamed one line at a time (one row per sample,
// every input and output as a `<quantity>_<unit>` column, then the status), and summary.csv
// (one row per line and quantity). Flagged values are empty cells, never "nan".
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "growthuq/evaluation/line_result.hpp"
#include "growthuq/io/output_file.hpp"

namespace growthuq {

// Writes samples.csv through "<path>.partial", renamed into place by finish(), so an
// interrupted run never leaves a file that looks complete. The header is fixed up front:
// line, sample, `columns`, status. A line lacking one of `columns` (a line file giving h in um
// where another gives nm) leaves its cells empty.
class SamplesCsvWriter {
 public:
  // InputError naming the path when the file cannot be created. An existing file at `path`
  // is replaced by finish() (the caller has already refused or allowed that).
  // Destroyed before finish(), it removes the .partial file (PartialFile).
  SamplesCsvWriter(std::string path, std::vector<std::string> columns);

  // Appends the line's rows: `sample` counts from 0 within the line; a value that is not
  // finite (a flagged sample's output) is an empty cell.
  void write_line(const LineResult& result);

  // Flushes, closes and renames to the final path; InputError on an I/O failure.
  void finish();

 private:
  PartialFile file_;
  std::vector<std::string> columns_;
};

// The columns of summary.csv, in order.
std::vector<std::string> summary_csv_header();

// summary.csv text: one row per summary, numbers in shortest round-trip form; a statistic
// that is undefined (no unflagged sample) is an empty cell. median_ci_low/high are the Monte
// Carlo 95 % CI of the median, data_ci_low/high its data-uncertainty interval (empty where no
// bootstrap ran).
std::string summary_csv_text(std::span<const QuantitySummary> summaries);

}  // namespace growthuq
