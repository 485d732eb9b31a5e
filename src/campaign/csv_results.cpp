#include "growthuq/campaign/csv_results.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/io/csv.hpp"

namespace growthuq {
namespace {

std::string number_cell(double value) { return std::isfinite(value) ? format_double(value) : std::string(); }

}  // namespace

SamplesCsvWriter::SamplesCsvWriter(std::string path, std::vector<std::string> columns)
    : path_(std::move(path)), partial_(path_ + ".partial"), columns_(std::move(columns)) {
  out_.open(partial_, std::ios::binary | std::ios::trunc);
  if (!out_) throw InputError(partial_, std::string("cannot create: ") + std::strerror(errno));
  std::string header = "line,sample";
  for (const std::string& column : columns_) header += "," + csv_cell(column);
  out_ << header << ",status\n";
}

SamplesCsvWriter::~SamplesCsvWriter() {
  if (finished_) return;
  out_.close();
  std::remove(partial_.c_str());
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
    out_ << row;
  }
  if (!out_) throw InputError(partial_, std::string("write failed: ") + std::strerror(errno));
}

void SamplesCsvWriter::finish() {
  out_.flush();
  out_.close();
  if (!out_) throw InputError(partial_, std::string("write failed: ") + std::strerror(errno));
  std::error_code error;
  std::filesystem::rename(partial_, path_, error);
  if (error) throw InputError(path_, "cannot move the finished file into place: " + error.message());
  finished_ = true;
}

std::vector<std::string> summary_csv_header() {
  return {"line", "quantity", "unit", "n", "n_flagged", "median", "q1", "q3", "iqr", "p10", "p90", "mean", "sd",
          "median_ci_low", "median_ci_high"};
}

std::string summary_csv_text(std::span<const QuantitySummary> summaries) {
  CsvWriter writer(summary_csv_header());
  for (const QuantitySummary& s : summaries) {
    writer.add_row({s.line, s.quantity, s.unit, std::to_string(s.n), std::to_string(s.n_flagged), number_cell(s.median),
                    number_cell(s.q1), number_cell(s.q3), number_cell(s.iqr), number_cell(s.p10), number_cell(s.p90),
                    number_cell(s.mean), number_cell(s.sd), number_cell(s.median_ci_low), number_cell(s.median_ci_high)});
  }
  return writer.text();
}

}  // namespace growthuq
