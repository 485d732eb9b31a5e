// Per-line analyses of a campaign's samples, as the published study reports them: the Spearman
// rank correlation between every input and every output, and a principal component analysis of
// inputs and outputs together (correlation-matrix PCA, see pca.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "growthuq/evaluation/line_result.hpp"
#include "growthuq/core/large_vector.hpp"
#include "growthuq/stats/quantity_summary.hpp"

namespace growthuq {

struct LineAnalysis {
  std::string line;
  std::vector<std::string> inputs;        // column names (k_N_per_m, ...) used as rows below
  std::vector<std::string> outputs;       // column names used as columns below
  Eigen::MatrixXd input_output_spearman;  // inputs x outputs
  std::vector<std::string> pca_names;     // inputs then outputs: the rows of `loadings`
  Eigen::VectorXd explained_variance_ratio;  // per component, descending, sums to 1
  Eigen::MatrixXd loadings;                  // pca_names x components (see PcaResult)
  std::size_t samples_used = 0;              // samples with status ok
  // Why something is missing, one sentence each: a column left out because it is constant over
  // the samples used (its correlation is undefined), or no analysis at all because fewer than
  // 3 samples have status ok (matrices and vectors are then empty). Never NaN instead.
  std::vector<std::string> notes;
};

// The analysis over the samples of `result` with status ok (a no_growth sample is left out
// here: its v = 0 is a boundary value, not a draw of the continuous law the ranks describe).
LineAnalysis analyze_line(const LineResult& result);

// analyze_line in two parts, so that processes can share the columns out: one column at a time
// (its average ranks from one sort, and, on request, order statistics for its summary), then
// the matrices from all columns. analyze_line(result) is combine_column_analyses of
// analyze_column of every column over analysis_samples(result.status).
struct ColumnAnalysis {
  // Why the column is left out of the matrices (each gets a note), or `used`.
  enum class Verdict { used, not_finite, constant, spread_out_of_range };
  Verdict verdict = Verdict::used;
  SampleMoments moments;                  // of the samples used, summed in sample order
  LargeVector<std::uint32_t> twice_ranks;  // 2 x average ranks over the samples used (ColumnOrder), when used
  std::vector<double> order_statistics;    // at the requested positions (when used)
};

// The samples with status ok, in sample order.
std::vector<std::uint32_t> analysis_samples(std::span<const SampleStatus> status);

// `values` is a whole column (all samples); `used` from analysis_samples; `positions` are
// positions of the ascending order of the used values whose values are wanted. When the values
// are known to strictly increase with `strata` (a design's column whose
// LineDesign::strictly_increasing is set, and its ranks), the order comes from the strata
// without sorting; the result is the same.
ColumnAnalysis analyze_column(std::span<const double> values, std::span<const std::uint32_t> used,
                              std::span<const std::size_t> positions = {}, std::span<const std::uint32_t> strata = {});

// columns[c] is the analysis of result.columns[c] over `used`.
LineAnalysis combine_column_analyses(const LineResult& result, std::span<const std::uint32_t> used,
                                     const std::vector<ColumnAnalysis>& columns);

// Readable text: the input x output Spearman table, the explained variance and loadings of every
// component (three decimals), and the notes. Ends with a newline.
std::string format_line_analysis(const LineAnalysis& analysis);

}  // namespace growthuq
