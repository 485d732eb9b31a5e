#include "growthuq/sensitivity/line_sensitivity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>

#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/stats/line_analysis.hpp"
#include "sensitivity/table_text.hpp"

namespace growthuq {
namespace {

// Sections of at least this many samples: a section's estimate must itself be near its normal
// limit for the t interval of (S2b) to hold (coverage measured at 50 and 100 per section).
constexpr std::size_t minimum_per_section = 10;
constexpr std::size_t default_sections = 20;
constexpr std::size_t minimum_sections = 3;
// At most this many samples per line: the indices' standard error is then about 0.003, far below
// what matters, and a line of 1e7 samples costs 10 MB and 0.1 s instead of 1 GB and 10 s (the
// columns are copied and sorted). The first samples of a Latin hypercube are a random subset of it
// (every column's strata are a random permutation).
constexpr std::size_t maximum_samples = 100'000;

// An output whose variance is this much held by its 1 % most extreme samples gets a note: its
// variance-based indices then rest on a handful of samples (pme48's modulus in the shipped study:
// 95 %, measured; its turgor 8 %).
constexpr double tail_variance_limit = 0.5;

// The fraction of the squared deviations from the mean that the 1 % largest of them hold.
double tail_share(const std::vector<double>& y) {
  double mean = 0;
  for (const double v : y) mean += v;
  mean /= static_cast<double>(y.size());
  std::vector<double> squares(y.size());
  for (std::size_t j = 0; j < y.size(); ++j) squares[j] = (y[j] - mean) * (y[j] - mean);
  const std::size_t top = std::max<std::size_t>(1, y.size() / 100);
  std::nth_element(squares.begin(), squares.end() - static_cast<std::ptrdiff_t>(top), squares.end());
  double total = 0, tail = 0;
  for (std::size_t j = 0; j < squares.size(); ++j) {
    total += squares[j];
    if (j >= squares.size() - top) tail += squares[j];
  }
  return tail / total;
}

}  // namespace

LineSensitivity line_sensitivity(const LineResult& result, std::uint64_t seed) {
  LineSensitivity sensitivity;
  sensitivity.line = result.name;
  std::vector<std::uint32_t> used = analysis_samples(result.status);
  if (used.size() > maximum_samples) {
    sensitivity.notes.push_back("sensitivity indices from the first " + std::to_string(maximum_samples) + " of the " +
                                std::to_string(used.size()) + " samples with status ok (a random subset of the design)");
    used.resize(maximum_samples);
  }
  sensitivity.samples_used = used.size();
  if (used.size() < minimum_sections * minimum_per_section) {
    sensitivity.notes.push_back("no sensitivity indices: only " + std::to_string(used.size()) +
                                " samples have status ok, at least 30 are needed for an interval");
    return sensitivity;
  }
  std::vector<std::vector<double>> input_values, output_values;
  for (const ResultColumn& column : result.columns) {
    std::vector<double> values(used.size());
    bool finite = true;
    for (std::size_t u = 0; u < used.size(); ++u) {
      values[u] = column.values[used[u]];
      finite = finite && std::isfinite(values[u]);
    }
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    const std::string name = column.column_name();
    if (!finite) {
      sensitivity.notes.push_back(name + " left out of the sensitivity indices: a sample with status ok has no finite value");
    } else if (*low == *high) {
      sensitivity.notes.push_back(name + " left out of the sensitivity indices: constant over the samples used");
    } else {
      (column.is_input ? sensitivity.inputs : sensitivity.outputs).push_back(name);
      (column.is_input ? input_values : output_values).push_back(std::move(values));
    }
  }
  if (input_values.empty() || output_values.empty()) return sensitivity;
  for (std::size_t o = 0; o < output_values.size(); ++o) {
    const double share = tail_share(output_values[o]);
    if (share > tail_variance_limit) {
      sensitivity.notes.push_back(sensitivity.outputs[o] + ": its 1 % most extreme samples hold " +
                                  std::to_string(static_cast<int>(std::lround(100 * share))) +
                                  " % of its variance, so its variance-based indices rest on a handful of samples and are "
                                  "unstable; read its rank correlations instead");
    }
  }
  sensitivity.sections = std::min(default_sections, used.size() / minimum_per_section);
  const std::vector<std::span<const double>> inputs(input_values.begin(), input_values.end());
  const std::vector<std::span<const double>> outputs(output_values.begin(), output_values.end());
  sensitivity.first_order = rank_first_order_indices(
      inputs, outputs, {.sections = sensitivity.sections, .key = stream_key(seed, result.name, "sensitivity")});
  return sensitivity;
}

std::string format_line_sensitivity(const LineSensitivity& sensitivity) {
  std::string text;
  if (!sensitivity.first_order.empty()) {
    text += "  First-order sensitivity S = Var(E[output | input]) / Var(output), inputs (rows) x outputs (columns),\n"
            "  rank estimator with its 95 % interval (inputs correlated: S counts what an input explains through its\n"
            "  partners too, so a column need not sum to 1):\n";
    std::size_t name_width = 0;
    for (const std::string& input : sensitivity.inputs) name_width = std::max(name_width, input.size());
    name_width += 4;
    std::size_t cell = 22;  // "-0.06 [-0.10, -0.01]" and two blanks
    for (const std::string& output : sensitivity.outputs) cell = std::max(cell, output.size() + 2);
    text += std::string(name_width, ' ');
    for (const std::string& output : sensitivity.outputs) text += padded_left(output, cell);
    text += "\n";
    for (std::size_t i = 0; i < sensitivity.inputs.size(); ++i) {
      std::string row = "    " + sensitivity.inputs[i];
      row += std::string(name_width - row.size(), ' ');
      for (const RankIndexEstimate& e : sensitivity.first_order[i]) {
        row += padded_left(two_decimals(e.index) + " [" + two_decimals(e.low) + ", " + two_decimals(e.high) + "]", cell);
      }
      text += row + "\n";
    }
  }
  for (const std::string& note : sensitivity.notes) text += "  note: " + note + "\n";
  return text;
}

}  // namespace growthuq
