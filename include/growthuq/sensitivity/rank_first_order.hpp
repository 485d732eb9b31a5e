// Full first-order sensitivity indices S_i = Var(E[Y | X_i]) / Var(Y) from one sample of
// (X, Y), with no further model run: the rank (nearest neighbour in rank) estimator of
// Chatterjee (2021) in the form of Gamboa, Klein and Lagnoux (2022), Eq. (S1) of
// src/sensitivity/README.md. "Full" because X_i keeps its dependence on the other inputs: under
// correlated inputs S_i counts the part of Var(Y) that X_i explains through its correlated
// partners as well, which is what "how much would knowing X_i tell about Y" means.
// The interval: sectioning or a percentile bootstrap over the samples (Eq. (S2)).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace growthuq {

// The point estimate of S for one input column x and one output column y of equal length
// n >= 2 (finite values; y not constant). Ties in x keep their sample order.
double rank_first_order_index(std::span<const double> x, std::span<const double> y);

struct RankIndexEstimate {
  double index = 0;  // Eq. (S1)
  double low = 0;    // the 95 % interval, Eq. (S2)
  double high = 0;
};

// How the 95 % interval is made (Eq. (S2) of src/sensitivity/README.md, with the coverage each
// reached in the tests).
enum class RankInterval {
  sectioning,  // (S2b) the spread of S over K random sections of the sample, t interval
  bootstrap,   // (S2a) percentile interval of B resamples with replacement
};

struct RankIndexSettings {
  RankInterval interval = RankInterval::sectioning;
  std::size_t sections = 20;     // K of sectioning (>= 2, each of >= 3 samples)
  std::size_t replicates = 200;  // B of the bootstrap (>= 39, so that the 2.5 % tail holds one)
  std::uint64_t key = 0;         // the random split / resample b comes from counter_bits(key, 0 / b)
};

// Every input against every output: result[i][o]. All columns of one length n >= 3, finite;
// no output constant. std::invalid_argument otherwise (the caller checks its columns first and
// names them). Sections and resamples take the samples (X, Y) together, the same for all inputs
// and outputs, so the numbers depend on (settings, columns) only.
std::vector<std::vector<RankIndexEstimate>> rank_first_order_indices(const std::vector<std::span<const double>>& inputs,
                                                                     const std::vector<std::span<const double>>& outputs,
                                                                     const RankIndexSettings& settings);

}  // namespace growthuq
