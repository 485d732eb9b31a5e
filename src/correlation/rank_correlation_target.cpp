#include "growthuq/correlation/rank_correlation_target.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/correlation/nearest_correlation.hpp"

namespace growthuq {

namespace {

// Smallest eigenvalue of a repaired normal-score correlation: keeps its Cholesky factor well
// defined while moving the matrix by no more than ~1e-6 from Higham's semidefinite answer.
constexpr double repair_min_eigenvalue = 1e-6;

std::string entry_name(const std::vector<std::string>& names, Eigen::Index i, Eigen::Index j) {
  auto name = [&](Eigen::Index k) {
    return static_cast<std::size_t>(k) < names.size() ? names[static_cast<std::size_t>(k)] : std::to_string(k + 1);
  };
  return "(" + name(i) + ", " + name(j) + ")";
}

}  // namespace

void validate_rank_correlation(const Eigen::MatrixXd& spearman, const std::vector<std::string>& names,
                               std::string_view location) {
  if (spearman.rows() != spearman.cols()) {
    throw InputError(std::string(location), "rank correlation matrix is " + std::to_string(spearman.rows()) + " x " +
                                                std::to_string(spearman.cols()) + ": expected a square matrix");
  }
  for (Eigen::Index i = 0; i < spearman.rows(); ++i) {
    for (Eigen::Index j = 0; j < spearman.cols(); ++j) {
      const double value = spearman(i, j);
      if (!(value >= -1.0 && value <= 1.0)) {
        throw_bad_value(location, "entry " + entry_name(names, i, j), format_double(value), "a number in [-1, 1]");
      }
      if (i == j && value != 1.0) {
        throw_bad_value(location, "entry " + entry_name(names, i, j), format_double(value),
                        "1 on the diagonal (a variable's rank correlation with itself)");
      }
      if (j > i && std::abs(value - spearman(j, i)) > 1e-12) {
        throw_bad_value(location, "entry " + entry_name(names, i, j), format_double(value),
                        "a symmetric matrix: entry " + entry_name(names, j, i) + " is " + format_double(spearman(j, i)));
      }
    }
  }
}

Eigen::MatrixXd spearman_to_normal_correlation(const Eigen::MatrixXd& spearman) {
  Eigen::MatrixXd rho = spearman.unaryExpr([](double s) { return 2.0 * std::sin(std::numbers::pi * s / 6.0); });
  rho.diagonal().setOnes();
  return rho;
}

Eigen::MatrixXd normal_to_spearman_correlation(const Eigen::MatrixXd& normal) {
  Eigen::MatrixXd s = normal.unaryExpr([](double rho) { return 6.0 / std::numbers::pi * std::asin(rho / 2.0); });
  s.diagonal().setOnes();
  return s;
}

ImanConoverTarget make_iman_conover_target(const Eigen::MatrixXd& spearman, const std::vector<std::string>& names,
                                           std::string_view location) {
  validate_rank_correlation(spearman, names, location);
  ImanConoverTarget target;
  target.names = names;
  target.requested_spearman = 0.5 * (spearman + spearman.transpose());
  target.normal_correlation = spearman_to_normal_correlation(target.requested_spearman);
  target.target_spearman = target.requested_spearman;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(target.normal_correlation, Eigen::EigenvaluesOnly);
  if (eigen.eigenvalues().minCoeff() >= repair_min_eigenvalue) return target;

  NearestCorrelationOptions options;
  options.min_eigenvalue = repair_min_eigenvalue;
  target.normal_correlation = nearest_correlation_matrix(target.normal_correlation, options).matrix;
  target.target_spearman = normal_to_spearman_correlation(target.normal_correlation);
  target.repaired = true;
  char smallest[32];
  std::snprintf(smallest, sizeof smallest, "%.3g", eigen.eigenvalues().minCoeff());
  target.warning = std::string(location) +
                   ": warning: the rank correlation target is not attainable: the normal-score correlation "
                   "2 sin(pi S/6) it implies is not positive definite (smallest eigenvalue " +
                   smallest +
                   "). Using the nearest correlation matrix instead (Higham 2002), whose Spearman target is:\n" +
                   format_matrix_table(target.target_spearman, names);
  target.warning.pop_back();  // the table's last line break: callers end the message
  return target;
}

std::string format_matrix_table(const Eigen::MatrixXd& matrix, const std::vector<std::string>& names, int precision) {
  std::size_t width = static_cast<std::size_t>(precision) + 4;
  for (const auto& name : names) width = std::max(width, name.size() + 1);
  auto pad = [&](const std::string& text) {
    return std::string(width > text.size() ? width - text.size() : 1, ' ') + text;
  };
  std::string text = pad("");
  for (const auto& name : names) text += pad(name);
  text += "\n";
  for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
    text += pad(names[static_cast<std::size_t>(i)]);
    for (Eigen::Index j = 0; j < matrix.cols(); ++j) {
      char cell[48];
      std::snprintf(cell, sizeof cell, "%.*f", precision, matrix(i, j));
      text += pad(cell);
    }
    text += "\n";
  }
  return text;
}

}  // namespace growthuq
