// The readable summary `growthuq run` prints on stdout: per line and quantity the median with
// its data-uncertainty interval (when a bootstrap ran) and then its Monte Carlo 95 % confidence
// interval, the IQR, the 10-90 % range and the flagged count; kappa; and per line the input rank
// correlation the design achieved next to its target.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/evaluation/line_result.hpp"

namespace growthuq {

// A fixed-width table, one row per summary, four significant digits; "-" for undefined cells.
// The column "data 95 % interval" is there when a summary has one (data_ci_low/high finite).
std::string format_summary_table(std::span<const QuantitySummary> summaries);

// Whether the data 95 % interval [low, high] has zero width but for rounding: a median the
// bootstrap does not move (a law held fixed in every replicate, or the reference line's v
// calibrated to a fixed v_exp). The tables print "fixed" for it rather than "[0.028, 0.028]".
bool data_interval_is_fixed(double low, double high);

// The line under the summary table saying what its intervals are: the bootstrap that gave the
// data intervals (`replicates` > 0), or that the intervals are Monte Carlo only, and why
// (replicates = 0 on raw-data lines, or no raw-data line). `measurement_error_lines`: the lines
// whose k of force curves the bootstrap also drew within each tube's measurement uncertainty
// ([force_curves] measurement_error = bootstrap): the note says their intervals include it.
std::string format_interval_note(const Campaign& campaign, const std::vector<std::string>& measurement_error_lines);

// "  k, d: target +0.450  achieved +0.447" for each pair with a non-zero target, then the
// largest |achieved| over the pairs meant to be independent. Empty when fewer than two inputs.
std::string format_input_correlation(const LineResult& result);

}  // namespace growthuq
