#include "growthuq/sensitivity/rank_first_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <gsl/gsl_cdf.h>

#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/stats/ranks.hpp"

namespace growthuq {
namespace {

// Sums of Eq. (S1) over one set of samples, each counted w times (1 for the sample itself, its
// multiplicity in a bootstrap resample). With s_1 < ... < s_m the held samples in the order of x
// and N(k) = k + 1 (N(m) = m, the largest its own neighbour),
//   S = sum_k w_k (y_k - ybar)(y_N(k) - ybar) / sum_k w_k (y_k - ybar)^2,   ybar = sum w y / W.
struct Sums {
  double weight = 0, y = 0, y2 = 0, cross = 0, neighbour = 0;  // W, sum w y, sum w y^2, sum w y y_N, sum w y_N

  void add_pair(double w, double y_k, double y_next) {
    cross += w * y_k * y_next;
    neighbour += w * y_next;
  }
  double index() const {
    const double mean = y / weight;
    const double centred_cross = cross - mean * (neighbour + y) + weight * mean * mean;
    const double centred_squares = y2 - weight * mean * mean;
    return centred_squares > 0 ? centred_cross / centred_squares : std::numeric_limits<double>::quiet_NaN();
  }
};

// Eq. (S1) of `y` (already standardized) in the order `by_x`, for every group at once: sample j
// belongs to group[j] (all to group 0 when `group` is empty) and is held weight[j] times (once
// when empty). Within a group the neighbour of a sample is the next sample of the same group
// that is held; copies of one sample are one point of x and all take the next distinct sample as
// their neighbour (pairing a copy with itself would give y_j^2, the numerator of S = 1).
std::vector<Sums> grouped_sums(std::span<const std::uint32_t> by_x, std::span<const double> y, std::span<const std::uint32_t> weight,
                               std::span<const std::uint32_t> group, std::size_t groups) {
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<Sums> sums(groups);
  std::vector<std::size_t> previous(groups, none);
  const auto w_of = [&](std::size_t j) { return weight.empty() ? 1.0 : static_cast<double>(weight[j]); };
  for (const std::uint32_t j : by_x) {
    const double w = w_of(j);
    if (w == 0) continue;
    const std::size_t g = group.empty() ? 0 : group[j];
    Sums& s = sums[g];
    if (previous[g] != none) s.add_pair(w_of(previous[g]), y[previous[g]], y[j]);
    s.weight += w;
    s.y += w * y[j];
    s.y2 += w * y[j] * y[j];
    previous[g] = j;
  }
  // The largest x of each group is its own neighbour: closing the ranks into a cycle (its
  // neighbour the smallest, as Chatterjee's cyclic form) pairs the extremes of a monotone output,
  // a bias of order 1/n (1 % at n = 500 on tanh(X), measured), this choice 1e-4.
  for (std::size_t g = 0; g < groups; ++g) {
    if (previous[g] != none) sums[g].add_pair(w_of(previous[g]), y[previous[g]], y[previous[g]]);
  }
  return sums;
}

// The standardized output (S is invariant to an affine map of y, Eq. (S1); the sums then lose no
// digits to a large mean).
std::vector<double> standardized(std::span<const double> y) {
  const double n = static_cast<double>(y.size());
  double mean = 0;
  for (const double v : y) mean += v;
  mean /= n;
  double squares = 0;
  for (const double v : y) squares += (v - mean) * (v - mean);
  const double sd = std::sqrt(squares / n);
  if (!(sd > 0) || !std::isfinite(sd)) throw std::invalid_argument("rank_first_order_indices: an output is constant or not finite");
  std::vector<double> z(y.size());
  for (std::size_t j = 0; j < y.size(); ++j) z[j] = (y[j] - mean) / sd;
  return z;
}

// The (B + 1) p-th of the sorted replicates, 1-based and interpolated (Hyndman and Fan 1996,
// type 6, as the line comparisons, src/stats/README.md Eq. (T5)), clamped to the extremes.
double percentile(std::vector<double> values, double p) {
  std::sort(values.begin(), values.end());
  const double h = (static_cast<double>(values.size()) + 1) * p;
  if (h <= 1) return values.front();
  if (h >= static_cast<double>(values.size())) return values.back();
  const auto below = static_cast<std::size_t>(std::floor(h));
  return values[below - 1] + (h - static_cast<double>(below)) * (values[below] - values[below - 1]);
}

void check_arguments(const std::vector<std::span<const double>>& inputs, const std::vector<std::span<const double>>& outputs,
                     const RankIndexSettings& settings) {
  if (inputs.empty() || outputs.empty()) throw std::invalid_argument("rank_first_order_indices: no input or no output");
  const std::size_t n = inputs.front().size();
  if (n < 3) throw std::invalid_argument("rank_first_order_indices: fewer than 3 samples");
  for (const auto& column : inputs) {
    if (column.size() != n) throw std::invalid_argument("rank_first_order_indices: columns differ in length");
    for (const double v : column) {
      if (!std::isfinite(v)) throw std::invalid_argument("rank_first_order_indices: an input is not finite");
    }
  }
  for (const auto& column : outputs) {
    if (column.size() != n) throw std::invalid_argument("rank_first_order_indices: columns differ in length");
  }
  if (settings.interval == RankInterval::bootstrap && settings.replicates < 39) {
    throw std::invalid_argument("rank_first_order_indices: fewer than 39 replicates cannot resolve a 2.5 % tail");
  }
  if (settings.interval == RankInterval::sectioning && (settings.sections < 2 || n < 3 * settings.sections)) {
    throw std::invalid_argument("rank_first_order_indices: sectioning needs 2 sections or more, of 3 samples or more");
  }
}

using Table = std::vector<std::vector<RankIndexEstimate>>;

// Eq. (S2a): the percentile interval of B resamples; resample b is n draws with replacement from
// RandomStream(counter_bits(key, b)), one resample for every input and output.
void bootstrap_interval(const std::vector<std::vector<std::uint32_t>>& order, const std::vector<std::vector<double>>& z,
                        const RankIndexSettings& settings, Table& table) {
  const std::size_t n = z.front().size();
  std::vector<std::vector<std::vector<double>>> replicates(
      order.size(), std::vector<std::vector<double>>(z.size(), std::vector<double>(settings.replicates)));
  std::vector<std::uint32_t> weight(n);
  for (std::size_t b = 0; b < settings.replicates; ++b) {
    std::fill(weight.begin(), weight.end(), 0u);
    RandomStream stream(counter_bits(settings.key, b));
    for (std::size_t draw = 0; draw < n; ++draw) ++weight[stream.below(n)];
    for (std::size_t i = 0; i < order.size(); ++i) {
      for (std::size_t o = 0; o < z.size(); ++o) {
        const double s = grouped_sums(order[i], z[o], weight, {}, 1)[0].index();
        replicates[i][o][b] = std::isfinite(s) ? s : table[i][o].index;  // a constant resample (tiny n only)
      }
    }
  }
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (std::size_t o = 0; o < z.size(); ++o) {
      table[i][o].low = percentile(replicates[i][o], 0.025);
      table[i][o].high = percentile(replicates[i][o], 0.975);
    }
  }
}

// Eq. (S2b), sectioning (Asmussen and Glynn 2007, III.5a): the samples split at random into K
// sections of (nearly) equal size; S_k of each; the interval S +- t_(K-1, 0.975) sd(S_k) / sqrt(K)
// around the whole sample's S. Valid when S is asymptotically normal with variance sigma^2 / n
// (Gamboa et al. 2022, their central limit theorem): then Var(S_k) = K sigma^2 / n.
void sectioning_interval(const std::vector<std::vector<std::uint32_t>>& order, const std::vector<std::vector<double>>& z,
                         const RankIndexSettings& settings, Table& table) {
  const std::size_t n = z.front().size();
  const std::size_t k = settings.sections;
  std::vector<std::uint32_t> permutation(n);
  std::iota(permutation.begin(), permutation.end(), 0u);
  RandomStream stream(counter_bits(settings.key, 0));
  for (std::size_t j = n - 1; j > 0; --j) std::swap(permutation[j], permutation[stream.below(j + 1)]);
  std::vector<std::uint32_t> section(n);
  for (std::size_t p = 0; p < n; ++p) section[permutation[p]] = static_cast<std::uint32_t>(p * k / n);
  const double t = gsl_cdf_tdist_Pinv(0.975, static_cast<double>(k - 1));
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (std::size_t o = 0; o < z.size(); ++o) {
      const std::vector<Sums> sums = grouped_sums(order[i], z[o], {}, section, k);
      double mean = 0, squares = 0;
      std::size_t valid = 0;
      for (const Sums& s : sums) {
        const double value = s.index();
        if (!std::isfinite(value)) continue;  // a constant section (tiny n only)
        ++valid;
        const double delta = value - mean;
        mean += delta / static_cast<double>(valid);
        squares += delta * (value - mean);
      }
      const double half = valid < 2 ? std::numeric_limits<double>::infinity()
                                     : t * std::sqrt(squares / static_cast<double>(valid - 1) / static_cast<double>(valid));
      table[i][o].low = table[i][o].index - half;
      table[i][o].high = table[i][o].index + half;
    }
  }
}

}  // namespace

double rank_first_order_index(std::span<const double> x, std::span<const double> y) {
  const std::vector<double> z = standardized(y);
  return grouped_sums(argsort(x), z, {}, {}, 1)[0].index();
}

std::vector<std::vector<RankIndexEstimate>> rank_first_order_indices(const std::vector<std::span<const double>>& inputs,
                                                                     const std::vector<std::span<const double>>& outputs,
                                                                     const RankIndexSettings& settings) {
  check_arguments(inputs, outputs, settings);
  std::vector<std::vector<double>> z;
  for (const auto& y : outputs) z.push_back(standardized(y));
  std::vector<std::vector<std::uint32_t>> order;  // one sort per input
  for (const auto& x : inputs) order.push_back(argsort(x));
  Table table(inputs.size(), std::vector<RankIndexEstimate>(outputs.size()));
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    for (std::size_t o = 0; o < outputs.size(); ++o) table[i][o].index = grouped_sums(order[i], z[o], {}, {}, 1)[0].index();
  }
  if (settings.interval == RankInterval::bootstrap) {
    bootstrap_interval(order, z, settings, table);
  } else {
    sectioning_interval(order, z, settings, table);
  }
  return table;
}

}  // namespace growthuq
