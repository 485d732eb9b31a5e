#include "growthuq/stats/line_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <span>
#include <string>
#include <vector>

#include "stats/column_order.hpp"
#include "growthuq/stats/pca.hpp"
#include "stats/cross_products.hpp"

namespace growthuq {

namespace {

// Fewer samples make every rank correlation +-1 or undefined and the PCA rank-deficient.
constexpr std::size_t minimum_samples = 3;

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

std::vector<std::uint32_t> analysis_samples(std::span<const SampleStatus> status) {
  std::vector<std::uint32_t> used;
  for (std::size_t i = 0; i < status.size(); ++i) {
    if (status[i] == SampleStatus::ok) used.push_back(static_cast<std::uint32_t>(i));
  }
  return used;
}

namespace {

// The order of the used values from the strata, which they strictly increase with: the rank of
// a used sample is one more than the number of used samples in lower strata.
void order_from_strata(std::span<const double> values, std::span<const std::uint32_t> used,
                       std::span<const std::uint32_t> strata, std::span<const std::size_t> positions,
                       ColumnAnalysis& analysis) {
  const std::size_t n = values.size();
  analysis.twice_ranks.resize(used.size());
  if (used.size() == n) {
    for (std::size_t i = 0; i < n; ++i) analysis.twice_ranks[i] = 2 * (strata[i] + 1);
  } else {
    // Strata of used samples marked, then below[k] = used samples in strata below k.
    std::vector<std::uint8_t> holds_used(n, 1);
    std::size_t next = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (next < used.size() && used[next] == i) {
        ++next;
      } else {
        holds_used[strata[i]] = 0;
      }
    }
    LargeVector<std::uint32_t> below(n);
    std::uint32_t count = 0;
    for (std::size_t k = 0; k < n; ++k) {
      below[k] = count;
      count += holds_used[k];
    }
    for (std::size_t u = 0; u < used.size(); ++u) analysis.twice_ranks[u] = 2 * (below[strata[used[u]]] + 1);
  }
  if (positions.empty()) return;
  // The used sample at each wanted position: position p is held by the used sample of rank p + 1.
  LargeVector<std::uint32_t> sample_at(used.size());
  for (std::size_t u = 0; u < used.size(); ++u) sample_at[analysis.twice_ranks[u] / 2 - 1] = used[u];
  for (const std::size_t position : positions) {
    if (position >= used.size()) throw std::out_of_range("analyze_column: order statistic beyond the column");
    analysis.order_statistics.push_back(values[sample_at[position]]);
  }
}

}  // namespace

ColumnAnalysis analyze_column(std::span<const double> values, std::span<const std::uint32_t> used,
                              std::span<const std::size_t> positions, std::span<const std::uint32_t> strata) {
  ColumnAnalysis analysis;
  const bool every_sample = used.size() == values.size();
  const auto value = [&](std::size_t u) { return every_sample ? values[u] : values[used[u]]; };
  double low = HUGE_VAL, high = -HUGE_VAL;
  for (std::size_t u = 0; u < used.size(); ++u) {
    const double x = value(u);
    if (!std::isfinite(x)) {
      analysis.verdict = ColumnAnalysis::Verdict::not_finite;
      return analysis;
    }
    low = std::min(low, x);
    high = std::max(high, x);
  }
  if (used.empty() || low == high) {
    analysis.verdict = ColumnAnalysis::Verdict::constant;
    return analysis;
  }
  // The used values in sample order (gathered only when some sample is not used).
  std::vector<double> gathered;
  std::span<const double> x = values;
  if (!every_sample) {
    gathered.resize(used.size());
    for (std::size_t u = 0; u < used.size(); ++u) gathered[u] = values[used[u]];
    x = gathered;
  }
  analysis.moments = sample_moments(x);
  // A spread whose square under- or overflows (|values| beyond ~1e150 or spread below ~1e-150)
  // cannot be standardized for the PCA.
  const double sd = std::sqrt(analysis.moments.squared_deviations / static_cast<double>(x.size() - 1));
  if (!(sd > 0 && std::isfinite(sd))) {
    analysis.verdict = ColumnAnalysis::Verdict::spread_out_of_range;
    return analysis;
  }
  if (!strata.empty()) {
    if (strata.size() != values.size()) throw std::invalid_argument("analyze_column: one stratum per value");
    order_from_strata(values, used, strata, positions, analysis);
    return analysis;
  }
  ColumnOrder order = order_column(x, positions);
  analysis.twice_ranks = std::move(order.twice_ranks);
  analysis.order_statistics = std::move(order.order_statistics);
  return analysis;
}

LineAnalysis combine_column_analyses(const LineResult& result, std::span<const std::uint32_t> used,
                                     const std::vector<ColumnAnalysis>& columns) {
  if (columns.size() != result.columns.size()) {
    throw std::invalid_argument("combine_column_analyses: one analysis per column of the result");
  }
  LineAnalysis analysis;
  analysis.line = result.name;
  analysis.samples_used = used.size();
  if (used.size() < minimum_samples) {
    analysis.notes.push_back("only " + std::to_string(used.size()) +
                             " samples have status ok: at least 3 are needed for rank correlations "
                             "and principal components");
    return analysis;
  }
  // Inputs first, then outputs, each in the order of the result's columns.
  std::vector<std::size_t> kept;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const std::string name = result.columns[c].column_name();
    switch (columns[c].verdict) {
      case ColumnAnalysis::Verdict::used:
        kept.push_back(c);
        break;
      case ColumnAnalysis::Verdict::not_finite:
        analysis.notes.push_back(name + " left out: a sample with status ok has no finite value");
        break;
      case ColumnAnalysis::Verdict::constant:
        analysis.notes.push_back(name + " left out: constant over the samples used, so its correlations are undefined");
        break;
      case ColumnAnalysis::Verdict::spread_out_of_range:
        analysis.notes.push_back(name + " left out: its spread is beyond double precision range for standardizing");
        break;
    }
  }
  std::stable_partition(kept.begin(), kept.end(), [&](std::size_t c) { return result.columns[c].is_input; });
  for (const std::size_t c : kept) {
    (result.columns[c].is_input ? analysis.inputs : analysis.outputs).push_back(result.columns[c].column_name());
    analysis.pca_names.push_back(result.columns[c].column_name());
  }
  const auto inputs = static_cast<Eigen::Index>(analysis.inputs.size());
  const auto outputs = static_cast<Eigen::Index>(analysis.outputs.size());
  analysis.input_output_spearman.resize(inputs, outputs);
  if (kept.empty()) return analysis;

  // Correlation matrices from sums of products of the centred columns: Spearman's is the Pearson
  // correlation of the average ranks (Spearman 1904), the PCA's that of the values.
  const auto correlation_of = [](const Eigen::MatrixXd& products) {
    const Eigen::VectorXd scale = products.diagonal().cwiseSqrt();
    Eigen::MatrixXd correlation = products.array() / (scale * scale.transpose()).array();
    correlation.diagonal().setOnes();
    return correlation;
  };
  const std::size_t n = used.size();
  std::vector<const std::uint32_t*> ranks;
  for (const std::size_t c : kept) ranks.push_back(columns[c].twice_ranks.data());
  // Twice the average ranks have mean n + 1 in every column.
  const std::vector<double> twice_mean(kept.size(), static_cast<double>(n) + 1.0);
  const Eigen::MatrixXd spearman = correlation_of(detail::cross_products(ranks, n, twice_mean));
  analysis.input_output_spearman = spearman.block(0, inputs, inputs, outputs);

  // The values over the samples used, centred on their means.
  std::vector<const double*> values;
  std::vector<double> means;
  for (const std::size_t c : kept) {
    values.push_back(result.columns[c].values.data());
    means.push_back(columns[c].moments.mean);
  }
  const Eigen::MatrixXd value_products = used.size() == result.status.size()
                                             ? detail::cross_products(values, used.size(), means)
                                             : detail::cross_products(values, used, means);
  PcaResult pca = pca_of_correlation(correlation_of(value_products));
  analysis.explained_variance_ratio = std::move(pca.explained_variance_ratio);
  analysis.loadings = std::move(pca.loadings);
  return analysis;
}

LineAnalysis analyze_line(const LineResult& result) {
  const std::vector<std::uint32_t> used = analysis_samples(result.status);
  std::vector<ColumnAnalysis> columns;
  for (const ResultColumn& column : result.columns) {
    columns.push_back(used.size() < minimum_samples ? ColumnAnalysis{} : analyze_column(column.values, used));
  }
  return combine_column_analyses(result, used, columns);
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
