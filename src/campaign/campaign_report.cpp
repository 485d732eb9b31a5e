#include "campaign/campaign_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace growthuq {
namespace {

std::string number(double value) {
  if (!std::isfinite(value)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

std::string signed_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%+.3f", value);
  return text;
}

std::string padded(const std::string& text, std::size_t width) {
  return text.size() >= width ? text + " " : text + std::string(width - text.size(), ' ');
}

bool has_data_interval(const QuantitySummary& summary) {
  return std::isfinite(summary.data_ci_low) && std::isfinite(summary.data_ci_high);
}

std::string data_interval_text(const QuantitySummary& summary) {
  if (!has_data_interval(summary)) return "-";
  if (data_interval_is_fixed(summary.data_ci_low, summary.data_ci_high)) return "fixed";
  return "[" + number(summary.data_ci_low) + ", " + number(summary.data_ci_high) + "]";
}

}  // namespace

bool data_interval_is_fixed(double low, double high) {
  // The replicates agree but for rounding: 0.027999999999999997 and 0.028000000000000008.
  return high - low <= 1e-12 * std::max(std::abs(low), std::abs(high));
}

std::string format_summary_table(std::span<const QuantitySummary> summaries) {
  std::size_t line_width = 6;
  for (const QuantitySummary& s : summaries) line_width = std::max(line_width, s.line.size() + 2);
  // The data interval, where a bootstrap gave one, comes first: it is the uncertainty a lab can
  // quote; the Monte Carlo CI only says how well the samples pin the campaign's own median.
  const bool data = std::any_of(summaries.begin(), summaries.end(), has_data_interval);
  std::string text = padded("line", line_width) + padded("quantity", 10) + padded("unit", 8) + padded("median", 10) +
                     (data ? padded("data 95 % interval", 22) : std::string()) + padded("Monte Carlo 95 % CI", 22) +
                     padded("IQR", 11) + padded("10-90 %", 22) + "flagged\n";
  for (const QuantitySummary& s : summaries) {
    const std::string monte_carlo = "[" + number(s.median_ci_low) + ", " + number(s.median_ci_high) + "]";
    const std::string range = number(s.p10) + " - " + number(s.p90);
    text += padded(s.line, line_width) + padded(s.quantity, 10) + padded(s.unit, 8) + padded(number(s.median), 10) +
            (data ? padded(data_interval_text(s), 22) : std::string()) + padded(monte_carlo, 22) + padded(number(s.iqr), 11) +
            padded(range, 22) + std::to_string(s.n_flagged) + " of " + std::to_string(s.n + s.n_flagged) + "\n";
  }
  const auto fixed = [](const QuantitySummary& s) {
    return has_data_interval(s) && data_interval_is_fixed(s.data_ci_low, s.data_ci_high);
  };
  if (std::any_of(summaries.begin(), summaries.end(), fixed)) {
    text += "fixed: the bootstrap does not move this median (a law held fixed in every replicate, or the reference "
            "line's v calibrated to a fixed v_exp); its only uncertainty is the Monte Carlo CI\n";
  }
  return text;
}

std::string format_interval_note(const Campaign& campaign, const std::vector<std::string>& measurement_error_lines) {
  const std::size_t replicates = campaign.data_uncertainty.replicates;
  if (replicates > 0) {
    std::string measured;
    for (const std::string& line : measurement_error_lines) measured += (measured.empty() ? "" : ", ") + line;
    if (!measured.empty()) {
      measured = ", for " + measured + " including each tube's measurement error of k from its force curves";
    }
    return "data 95 % interval: a parametric bootstrap over the tubes of the raw-data lines, " + std::to_string(replicates) +
           " replicates x " + std::to_string(data_uncertainty_samples(campaign)) +
           " samples per line (campaigns/README.md, \"Data uncertainty\")" + measured +
           "; Monte Carlo 95 % CI: the error of this run's " + std::to_string(campaign.samples) + " samples alone\n";
  }
  const std::string why = has_raw_data_line(campaign) ? "[data_uncertainty] replicates = 0 switched the bootstrap off"
                                                      : "no line is given by raw data, so there is no bootstrap over tubes";
  return "note: the intervals are Monte Carlo only (" + why +
         "): they shrink with more samples and hold nothing of the uncertainty of having measured a few dozen tubes\n";
}

std::string format_input_correlation(const LineResult& result) {
  const auto m = result.achieved_spearman.rows();
  if (m < 2 || static_cast<std::size_t>(m) != result.correlated_inputs.size()) return {};
  const bool has_target = result.target_spearman.rows() == m;
  std::string text;
  double largest_independent = 0;
  std::size_t independent_pairs = 0;
  for (Eigen::Index a = 0; a < m; ++a) {
    for (Eigen::Index b = a + 1; b < m; ++b) {
      const double target = has_target ? result.target_spearman(a, b) : 0.0;
      const double achieved = result.achieved_spearman(a, b);
      if (target == 0.0) {
        largest_independent = std::max(largest_independent, std::abs(achieved));
        ++independent_pairs;
        continue;
      }
      const std::string pair = result.correlated_inputs[static_cast<std::size_t>(a)] + ", " +
                               result.correlated_inputs[static_cast<std::size_t>(b)];
      text += "  " + padded(pair, 14) + "target " + signed_number(target) + "  achieved " + signed_number(achieved) + "\n";
    }
  }
  if (independent_pairs > 0) {
    text += "  " + padded(std::to_string(independent_pairs) + " independent pairs", 14) + " target +0.000  largest |achieved| " +
            number(largest_independent) + "\n";
  }
  return text;
}

}  // namespace growthuq
