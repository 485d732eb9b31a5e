// Sobol' first-order and total indices for INDEPENDENT inputs by the pick-freeze estimators:
// first order of Saltelli et al. (2010), total of Jansen (1999) (Eq. (S6) of
// src/sensitivity/README.md). They swap one column between two independent designs, which
// presumes independent inputs: under dependence the swapped rows are draws of a law the inputs
// do not have, and the numbers are wrong without warning (why a campaign refuses them for a
// line with a rank correlation, campaign/line_sobol.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "growthuq/sensitivity/shapley.hpp"

namespace growthuq {

struct SobolSettings {
  std::size_t samples = 1000;  // N: rows of each of the designs A and B; N (d + 2) model runs
  std::size_t sections = 10;   // K of the interval (sectioning over the rows, Eq. (S5))
  std::uint64_t key = 0;
};

struct SobolIndices {
  Eigen::MatrixXd first, first_low, first_high;  // inputs x outputs, with 95 % intervals
  Eigen::MatrixXd total, total_low, total_high;
  std::size_t model_runs = 0;
};

// std::invalid_argument for fewer than 2 inputs, sections < 2 or samples < 2 sections.
SobolIndices sobol_indices(const BatchModel& model, const std::vector<Quantile>& marginals, const SobolSettings& settings);

}  // namespace growthuq
