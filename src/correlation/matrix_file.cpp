#include "growthuq/correlation/matrix_file.hpp"

#include <cmath>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/correlation/rank_correlation_target.hpp"
#include "growthuq/io/csv.hpp"

namespace growthuq {

RankCorrelationFile read_rank_correlation_csv(const std::string& path) {
  const CsvTable table = read_csv(path);
  RankCorrelationFile file;
  file.path = path;
  file.names = table.header;
  const std::size_t m = table.header.size();
  if (table.rows.size() != m) {
    throw InputError(file_location(path, 0), "has " + std::to_string(table.rows.size()) + " matrix rows below the header of " +
                                                 std::to_string(m) + " names: expected one row per variable, in the header's order");
  }
  file.spearman.resize(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < m; ++j) {
      file.spearman(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          parse_double(table.rows[i][j], table.row_location(i), "entry (" + table.header[i] + ", " + table.header[j] + ")");
    }
  }
  // Each problem is reported on the line that holds it; for an asymmetric pair, the later row.
  for (std::size_t i = 0; i < m; ++i) {
    const auto ii = static_cast<Eigen::Index>(i);
    for (std::size_t j = 0; j < m; ++j) {
      const auto jj = static_cast<Eigen::Index>(j);
      const double value = file.spearman(ii, jj);
      const std::string key = "entry (" + table.header[i] + ", " + table.header[j] + ")";
      if (!(value >= -1.0 && value <= 1.0)) throw_bad_value(table.row_location(i), key, table.rows[i][j], "a number in [-1, 1]");
      if (i == j && value != 1.0) {
        throw_bad_value(table.row_location(i), key, table.rows[i][j], "1 on the diagonal (a variable's rank correlation with itself)");
      }
      if (j < i && std::abs(value - file.spearman(jj, ii)) > 1e-12) {
        throw_bad_value(table.row_location(i), key, table.rows[i][j],
                        "a symmetric matrix: entry (" + table.header[j] + ", " + table.header[i] + ") on line " +
                            std::to_string(table.line_numbers[j]) + " is " + table.rows[j][i]);
      }
    }
  }
  validate_rank_correlation(file.spearman, file.names, file_location(path, 0));
  return file;
}

std::string format_rank_correlation_csv(const std::vector<std::string>& names, const Eigen::MatrixXd& spearman) {
  CsvWriter writer(names);
  for (Eigen::Index i = 0; i < spearman.rows(); ++i) {
    std::vector<std::string> cells;
    for (Eigen::Index j = 0; j < spearman.cols(); ++j) cells.push_back(format_double(spearman(i, j)));
    writer.add_row(cells);
  }
  return writer.text();
}

}  // namespace growthuq
