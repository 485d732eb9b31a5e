// Per-line analyses of a campaign's samples, as the published study reports them: the Spearman
// rank correlation between every input and every output, and a principal component analysis of
// inputs and outputs together (correlation-matrix PCA, see pca.hpp).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "growthuq/campaign/line_result.hpp"

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

// Readable text: the input x output Spearman table, the explained variance and loadings of every
// component (three decimals), and the notes. Ends with a newline.
std::string format_line_analysis(const LineAnalysis& analysis);

}  // namespace growthuq
