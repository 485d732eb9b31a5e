// What a campaign produces for one plant line, handed from the runner to the writers
// (samples.csv, summary.csv, results.h5) and the analyses (summaries with confidence,
// rank correlations, principal components). One line is held at a time, so memory stays
// proportional to one line's samples.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "growthuq/core/large_vector.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/evaluation/sample_status.hpp"

namespace growthuq {

// One column of results, in the unit it is written in (inputs: the line file's unit; outputs:
// the quantity's default unit). An input holds every drawn value. An output holds NaN wherever
// its model did not compute it: the model flagged the sample, or an earlier model did (then it
// never ran), except v = 0 under no_growth (Evaluator::valued_statuses). Values computed before
// a later model flagged the sample stay (p and E of a sample whose viscosity failed).
struct ResultColumn {
  std::string quantity;        // "k", "p", ...
  const Unit* unit = nullptr;  // never null
  bool is_input = false;
  LargeVector<double> values;  // a std::vector whose storage is reused from line to line (large_vector.hpp)

  std::string column_name() const { return growthuq::column_name(quantity, *unit); }
};

struct LineResult {
  std::string name;
  std::vector<ResultColumn> columns;  // inputs first (line-file order), then outputs (campaign order)
  std::vector<SampleStatus> status;   // one per sample

  // Rank correlation of the inputs: what was asked for and what the design achieved.
  std::vector<std::string> correlated_inputs;  // names of the matrices' rows/columns
  Eigen::MatrixXd target_spearman;             // empty when no correlation was requested
  Eigen::MatrixXd achieved_spearman;           // over correlated_inputs (all inputs when no target)

  std::size_t samples() const { return status.size(); }
};

// The per-line, per-quantity row of summary.csv (src/stats/README.md: median, IQR, 10-90 %).
// Statistics are over the samples that hold a value of the quantity (holds_value in
// quantity_summary.hpp: the non-empty cells of samples.csv); n_flagged counts the samples the
// quantity lacks (0 for an input).
struct QuantitySummary {
  std::string line;
  std::string quantity;
  std::string unit;  // symbol, e.g. "MPa"
  std::size_t n = 0;
  std::size_t n_flagged = 0;
  double median = 0, q1 = 0, q3 = 0, iqr = 0, p10 = 0, p90 = 0, mean = 0, sd = 0;
  // Distribution-free 95 % confidence interval of the median from order statistics
  // (binomial(n, 1/2) ranks; exact coverage >= 95 %), e.g. Conover 1999, section 3.2.
  double median_ci_low = 0, median_ci_high = 0;
  // The data-uncertainty interval of the median (campaign/data_uncertainty.hpp: the 2.5 and
  // 97.5 % of the bootstrap's replicate medians); NaN where no bootstrap ran.
  double data_ci_low = std::numeric_limits<double>::quiet_NaN();
  double data_ci_high = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace growthuq
