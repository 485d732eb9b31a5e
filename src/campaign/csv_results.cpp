#include "campaign/csv_results.hpp"

#include <cmath>
#include <utility>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/io/csv.hpp"

namespace growthuq {
namespace {

std::string number_cell(double value) { return std::isfinite(value) ? format_double(value) : std::string(); }

}  // namespace

SamplesCsvWriter::SamplesCsvWriter(std::string path, std::vector<std::string> columns)
    : file_(std::move(path)), columns_(std::move(columns)) {
  std::string header = "line,sample";
  for (const std::string& column : columns_) header += "," + csv_cell(column);
  file_.write(header + ",status\n");
}

void SamplesCsvWriter::write_line(const LineResult& result) {
  // Where each header column comes from in this line (or nowhere).
  std::vector<const ResultColumn*> sources(columns_.size(), nullptr);
  for (const ResultColumn& column : result.columns) {
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      if (columns_[c] == column.column_name()) sources[c] = &column;
    }
  }
  const std::string line = csv_cell(result.name);
  std::string row;
  for (std::size_t i = 0; i < result.samples(); ++i) {
    row = line;
    row += ',';
    row += std::to_string(i);
    for (const ResultColumn* source : sources) {
      row += ',';
      if (source != nullptr) row += number_cell(source->values[i]);
    }
    row += ',';
    row += to_string(result.status[i]);
    row += '\n';
    file_.write(row);
  }
}

void SamplesCsvWriter::finish() { file_.commit(); }

std::vector<std::string> summary_csv_header() {
  return {"line", "quantity", "unit", "n", "n_flagged", "median", "q1", "q3", "iqr", "p10", "p90", "mean", "sd",
          "median_ci_low", "median_ci_high", "data_ci_low", "data_ci_high"};
}

std::string summary_csv_text(std::span<const QuantitySummary> summaries) {
  CsvWriter writer(summary_csv_header());
  for (const QuantitySummary& s : summaries) {
    writer.add_row({s.line, s.quantity, s.unit, std::to_string(s.n), std::to_string(s.n_flagged), number_cell(s.median),
                    number_cell(s.q1), number_cell(s.q3), number_cell(s.iqr), number_cell(s.p10), number_cell(s.p90),
                    number_cell(s.mean), number_cell(s.sd), number_cell(s.median_ci_low), number_cell(s.median_ci_high),
                    number_cell(s.data_ci_low), number_cell(s.data_ci_high)});
  }
  return writer.text();
}

}  // namespace growthuq
