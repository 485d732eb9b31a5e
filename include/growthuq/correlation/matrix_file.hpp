// The rank correlation matrix file (CSV): a header row of variable names, then one row per
// variable, in the header's order, holding numbers only; '#' lines are comments. Example:
//   k,h,d,d0
//   1,0.1,0.45,0.3
//   0.1,1,0.2,0.15
//   ...
// `growthuq sample --rank-correlation` reads it; `growthuq correlate` writes it.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace growthuq {

struct RankCorrelationFile {
  std::string path;
  std::vector<std::string> names;
  Eigen::MatrixXd spearman;
};

// Reads and validates the file: as many rows as names, numbers only, a valid rank correlation
// matrix (square, symmetric, entries in [-1, 1], unit diagonal). InputError naming file and line.
// A matrix that is valid but not attainable is repaired later (rank_correlation_target.hpp).
RankCorrelationFile read_rank_correlation_csv(const std::string& path);

// The CSV text of a matrix in this format (numbers in shortest round-trip form).
std::string format_rank_correlation_csv(const std::vector<std::string>& names, const Eigen::MatrixXd& spearman);

}  // namespace growthuq
