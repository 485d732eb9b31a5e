// results.h5: a campaign's samples, summaries and analyses in one HDF5 file, written one line at
// a time (memory stays proportional to one line) through "<path>.partial" and an atomic rename,
// so a file named results.h5 is always complete. Written by one process (the HDF5 C++ API).
//
// Layout (h5py: f["lines/wild_type/p_MPa"][:]; pandas: pd.DataFrame(f["summary"][:]); xarray:
// xr.open_dataset(path, group="lines/wild_type", engine="h5netcdf"); campaigns/README.md):
//   /                              attributes campaign_text, campaign_path, command_line,
//                                  engine_version (strings), seed (uint64), kappa (float64, NaN
//                                  when the campaign has no growth output), samples_per_line
//                                  (uint64), line_order (strings: the campaign's order of the
//                                  lines, declare_lines; /lines also lists its groups in it)
//   /summary                       compound table, one row per line and quantity, the columns of
//                                  summary.csv: line, quantity, unit (strings), n, n_flagged
//                                  (uint64), median, q1, q3, iqr, p10, p90, mean, sd,
//                                  median_ci_low, median_ci_high (the Monte Carlo 95 % CI),
//                                  data_ci_low, data_ci_high (the data-uncertainty interval,
//                                  NaN where no bootstrap ran) (float64; NaN where summary.csv
//                                  has an empty cell); dimension summary_row
//   /provenance/                   how the results were made (campaign/provenance.hpp): version,
//                                  campaign path and SHA-256, seed, samples, instrument, data-
//                                  interval settings (attributes); lines/<line> (fidelity, source,
//                                  correlation) and models/<model> (description, reference,
//                                  measured_error), string attributes
//   /lines/<line>/                 one group per line (attributes `samples`, and `columns`: the
//                                  column names in samples.csv's order, inputs then outputs)
//     sample                       uint64 [samples], 0-based index of the sample in its line: the
//                                  dimension scale of the columns and of status
//     <column>                     float64 [sample], in its quantity's default unit whatever the
//                                  line file's (einf_frac, never einf_pct: one name per quantity),
//                                  named like the CSV column of that unit (k_N_per_m, p_MPa, ...),
//                                  attributes `quantity`, `unit` and `units` (symbol, e.g. "MPa"),
//                                  `long_name` and `role` ("input" or "output"); NaN for flagged
//                                  samples
//     status                       uint8 [sample], attribute `names`: status names by code
//                                  (names[0] = "ok", ...)
//     summary                      the rows of /summary for this line (same compound type)
//     input_rank_correlation/      achieved (and target, when one was requested): float64
//                                  [row, column] Spearman matrices; row and column hold the names
//                                  (also the group attribute `names`)
//     analysis/                    input_output_spearman [input, output] (attributes `rows`,
//                                  `columns`), explained_variance_ratio [component], loadings
//                                  [variable, component] (attribute `rows`); group attributes
//                                  samples_used (uint64) and notes (strings, may be empty)
// Every dataset has its dimensions as HDF5 dimension scales (H5DS), so xarray needs no
// phony_dims; a row index other than `sample` (`<table>_row`, `point`, `replicate`,
// `component`) is netCDF's "dimension but not a variable", never written, taking no room.
// Every other numeric dataset has the attribute `units` ("1" for sample, codes, correlations).
// Text is variable-length UTF-8: h5py returns attributes as str, and string datasets (label
// dimensions) and the text of compound tables as bytes (h5py 3; xarray and pandas decode them).
// Datasets are contiguous and uncompressed: sampled doubles barely compress (deflate saves
// 5-15 % at 10x the write time, measured in results_h5.cpp).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "growthuq/evaluation/line_result.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/stats/line_analysis.hpp"

namespace growthuq {

// A column of an additional table (ResultsH5Writer::write_table): exactly one of the vectors is
// filled, giving the member type: variable-length UTF-8 text, float64 or int64. `unit` is the
// numbers' unit symbol ("s", "1" for counts and pure numbers); empty for text, and for numbers
// in the unit their row names (a `unit` member, as in the data-uncertainty table).
struct ExtraColumn {
  std::string name;
  std::vector<std::string> text{};
  std::vector<double> real{};
  std::vector<std::int64_t> integer{};
  std::string unit{};
};

struct CampaignMetadata {
  std::string campaign_text, campaign_path, command_line, engine_version;
  std::uint64_t seed = 0;
  double kappa = std::numeric_limits<double>::quiet_NaN();
  std::size_t samples_per_line = 0;
};

class ResultsH5Writer {
 public:
  // Creates "<path>.partial" (truncating a stale one). With Overwrite::refuse an existing `path`
  // is an InputError naming it. I/O failures are InputErrors naming the file and the reason.
  ResultsH5Writer(std::string path, Overwrite overwrite);
  ResultsH5Writer(const ResultsH5Writer&) = delete;
  ResultsH5Writer& operator=(const ResultsH5Writer&) = delete;

  // Creates the line groups in the campaign's order before any is written (lines run with the
  // reference line first), so /lines lists them in that order and the root attribute line_order
  // records it; without it both follow the order of write_line. InputError for a bad line name
  // (as write_line), std::logic_error after a line was written.
  void declare_lines(const std::vector<std::string>& names);

  // One line's group. InputError for a line name HDF5 cannot hold ("", ".", containing '/') or
  // written twice; std::invalid_argument when columns and status differ in length.
  void write_line(const LineResult& result, const std::vector<QuantitySummary>& summaries,
                  const LineAnalysis& analysis);

  // Additional content next to the campaign layout (e.g. the fits of raw-data lines, written
  // by campaign/raw_data_outputs.cpp), at slash-separated paths from the root; missing groups
  // are created. A table is a compound dataset with one member per column (all columns of equal
  // length; std::invalid_argument otherwise), readable as pandas.DataFrame(f[path][:]), with the
  // attribute column_units (one per member) and the row dimension "<name>_row" beside it.
  // An array has the attribute units and the index dimension `dimension` of its group (shared
  // by the arrays of that group, which then have its length; "<dimension>_<length>" otherwise).
  // InputError naming the file for HDF5 failures (e.g. a path written twice).
  void write_table(const std::string& path, const std::vector<ExtraColumn>& columns);
  void write_array(const std::string& path, const std::vector<double>& values, const std::string& unit,
                   const std::string& dimension);  // float64
  void write_array(const std::string& path, const std::vector<std::int32_t>& values, const std::string& unit,
                   const std::string& dimension);  // int32
  // A string, float64 or uint64 attribute on the group or dataset at `path` (created as a group
  // if missing).
  void write_attribute(const std::string& path, const std::string& name, const std::string& value);
  void write_attribute(const std::string& path, const std::string& name, double value);
  void write_attribute(const std::string& path, const std::string& name, std::uint64_t value);

  // Replaces the summaries of the lines written (the same rows, in the order written) in every
  // line's `summary` and for /summary: the data intervals (data_ci_low/high) of the bootstrap
  // are known only after the last line. std::invalid_argument for other rows.
  void replace_summaries(const std::vector<QuantitySummary>& summaries);

  // Writes /summary and the root attributes, closes the file and renames it to `path`.
  // Calling anything after finish() is a std::logic_error.
  void finish(const CampaignMetadata& metadata);

  // Without finish(): closes and removes the .partial file.
  ~ResultsH5Writer();

  const std::string& path() const { return path_; }

 private:
  void write_attribute_value(const std::string& path, const std::string& name,
                             const std::variant<std::string, double, std::uint64_t>& value);

  struct File;
  std::string path_;
  Overwrite overwrite_;
  std::unique_ptr<File> file_;
  std::vector<QuantitySummary> summaries_;  // every line's, for /summary
  std::vector<std::string> lines_declared_;
  std::vector<std::string> lines_written_;
};

}  // namespace growthuq
