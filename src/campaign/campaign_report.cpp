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

}  // namespace

std::string format_summary_table(std::span<const QuantitySummary> summaries) {
  std::size_t line_width = 6;
  for (const QuantitySummary& s : summaries) line_width = std::max(line_width, s.line.size() + 2);
  std::string text = padded("line", line_width) + padded("quantity", 10) + padded("unit", 8) +
                     padded("median [95 % CI]", 30) + padded("IQR", 11) + padded("10-90 %", 22) + "flagged\n";
  for (const QuantitySummary& s : summaries) {
    const std::string median = number(s.median) + " [" + number(s.median_ci_low) + ", " + number(s.median_ci_high) + "]";
    const std::string range = number(s.p10) + " - " + number(s.p90);
    text += padded(s.line, line_width) + padded(s.quantity, 10) + padded(s.unit, 8) + padded(median, 30) +
            padded(number(s.iqr), 11) + padded(range, 22) + std::to_string(s.n_flagged) + " of " +
            std::to_string(s.n + s.n_flagged) + "\n";
  }
  return text;
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
