#include "growthuq/stats/line_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "growthuq/stats/pca.hpp"
#include "growthuq/stats/rank_correlation.hpp"

namespace growthuq {

namespace {

// Fewer samples make every rank correlation +-1 or undefined and the PCA rank-deficient.
constexpr std::size_t minimum_samples = 3;

struct UsedColumn {
  std::string name;
  bool is_input;
  std::vector<double> values;  // over the samples with status ok
};

std::string fixed(double value, int decimals = 3) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string padded_left(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

std::string padded_right(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

std::size_t longest(const std::vector<std::string>& names) {
  std::size_t width = 0;
  for (const std::string& name : names) width = std::max(width, name.size());
  return width;
}

}  // namespace

LineAnalysis analyze_line(const LineResult& result) {
  LineAnalysis analysis;
  analysis.line = result.name;
  std::vector<std::size_t> used_samples;
  for (std::size_t i = 0; i < result.status.size(); ++i) {
    if (result.status[i] == SampleStatus::ok) used_samples.push_back(i);
  }
  analysis.samples_used = used_samples.size();
  if (used_samples.size() < minimum_samples) {
    analysis.notes.push_back("only " + std::to_string(used_samples.size()) +
                             " samples have status ok: at least 3 are needed for rank correlations "
                             "and principal components");
    return analysis;
  }

  std::vector<UsedColumn> used;
  for (const ResultColumn& column : result.columns) {
    UsedColumn candidate{column.column_name(), column.is_input, {}};
    candidate.values.reserve(used_samples.size());
    bool finite = true;
    for (const std::size_t i : used_samples) {
      const double value = i < column.values.size() ? column.values[i] : std::nan("");
      finite = finite && std::isfinite(value);
      candidate.values.push_back(value);
    }
    if (!finite) {
      analysis.notes.push_back(candidate.name + " left out: a sample with status ok has no finite value");
      continue;
    }
    const auto [low, high] = std::minmax_element(candidate.values.begin(), candidate.values.end());
    if (*low == *high) {
      analysis.notes.push_back(candidate.name + " left out: constant over the samples used, so its correlations are undefined");
      continue;
    }
    // A spread whose square under- or overflows (|values| beyond ~1e150 or spread below ~1e-150)
    // cannot be standardized for the PCA.
    const Eigen::Map<const Eigen::ArrayXd> values(candidate.values.data(), static_cast<Eigen::Index>(candidate.values.size()));
    const double sd = std::sqrt((values - values.mean()).matrix().squaredNorm() / static_cast<double>(values.size() - 1));
    if (!(sd > 0 && std::isfinite(sd))) {
      analysis.notes.push_back(candidate.name + " left out: its spread is beyond double precision range for standardizing");
      continue;
    }
    used.push_back(std::move(candidate));
  }
  // Inputs first, then outputs, each in the order of the result's columns.
  std::stable_partition(used.begin(), used.end(), [](const UsedColumn& column) { return column.is_input; });
  for (const UsedColumn& column : used) {
    (column.is_input ? analysis.inputs : analysis.outputs).push_back(column.name);
    analysis.pca_names.push_back(column.name);
  }
  const auto inputs = static_cast<Eigen::Index>(analysis.inputs.size());
  const auto outputs = static_cast<Eigen::Index>(analysis.outputs.size());
  analysis.input_output_spearman.resize(inputs, outputs);
  if (used.empty()) return analysis;

  std::vector<std::span<const double>> spans;
  for (const UsedColumn& column : used) spans.emplace_back(column.values);
  if (used.size() >= 2) {
    const Eigen::MatrixXd spearman = spearman_matrix(spans);
    analysis.input_output_spearman = spearman.block(0, inputs, inputs, outputs);
  }

  Eigen::MatrixXd data(static_cast<Eigen::Index>(used_samples.size()), static_cast<Eigen::Index>(used.size()));
  for (std::size_t j = 0; j < used.size(); ++j) {
    data.col(static_cast<Eigen::Index>(j)) = Eigen::Map<const Eigen::VectorXd>(
        used[j].values.data(), static_cast<Eigen::Index>(used[j].values.size()));
  }
  PcaResult pca = correlation_pca(data);
  analysis.explained_variance_ratio = std::move(pca.explained_variance_ratio);
  analysis.loadings = std::move(pca.loadings);
  return analysis;
}

std::string format_line_analysis(const LineAnalysis& analysis) {
  std::string text = "line '" + analysis.line + "': " + std::to_string(analysis.samples_used) +
                     " samples with status ok\n";
  if (analysis.inputs.size() > 0 && analysis.outputs.size() > 0) {
    text += "  Spearman rank correlation, inputs (rows) x outputs (columns):\n";
    const std::size_t name_width = longest(analysis.inputs) + 4;
    const std::size_t cell = std::max<std::size_t>(9, longest(analysis.outputs) + 2);
    text += std::string(name_width, ' ');
    for (const std::string& output : analysis.outputs) text += padded_left(output, cell);
    text += "\n";
    for (std::size_t r = 0; r < analysis.inputs.size(); ++r) {
      text += padded_right("    " + analysis.inputs[r], name_width);
      for (std::size_t c = 0; c < analysis.outputs.size(); ++c) {
        text += padded_left(fixed(analysis.input_output_spearman(static_cast<Eigen::Index>(r),
                                                                 static_cast<Eigen::Index>(c))),
                            cell);
      }
      text += "\n";
    }
  }
  const Eigen::Index components = analysis.explained_variance_ratio.size();
  if (components > 0) {
    text += "  Principal components of the standardized inputs and outputs (loadings; largest entry positive):\n";
    const std::size_t name_width = std::max<std::size_t>(longest(analysis.pca_names), 9) + 4;
    const std::size_t cell = 8;
    text += std::string(name_width, ' ');
    for (Eigen::Index c = 0; c < components; ++c) text += padded_left("PC" + std::to_string(c + 1), cell);
    text += "\n" + padded_right("    explained", name_width);
    for (Eigen::Index c = 0; c < components; ++c) {
      text += padded_left(fixed(100 * analysis.explained_variance_ratio(c), 1) + "%", cell);
    }
    text += "\n";
    for (std::size_t r = 0; r < analysis.pca_names.size(); ++r) {
      text += padded_right("    " + analysis.pca_names[r], name_width);
      for (Eigen::Index c = 0; c < components; ++c) {
        text += padded_left(fixed(analysis.loadings(static_cast<Eigen::Index>(r), c)), cell);
      }
      text += "\n";
    }
  }
  for (const std::string& note : analysis.notes) text += "  note: " + note + "\n";
  return text;
}

}  // namespace growthuq
