// The readable summary `growthuq run` prints on stdout: per line and quantity the median with
// its 95 % confidence interval, the IQR, the 10-90 % range and the flagged count; kappa; and per
// line the input rank correlation the design achieved next to its target.
#pragma once

#include <span>
#include <string>

#include "growthuq/evaluation/line_result.hpp"

namespace growthuq {

// A fixed-width table, one row per summary, four significant digits; "-" for undefined cells.
std::string format_summary_table(std::span<const QuantitySummary> summaries);

// "  k, d: target +0.450  achieved +0.447" for each pair with a non-zero target, then the
// largest |achieved| over the pairs meant to be independent. Empty when fewer than two inputs.
std::string format_input_correlation(const LineResult& result);

}  // namespace growthuq
