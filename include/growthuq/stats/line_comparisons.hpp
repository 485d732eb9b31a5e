// All-pairwise comparisons of plant lines from bootstrap replicates of their medians (Eq. (T5),
// src/stats/README.md): per pair the ratio of medians with the percentile interval of the
// per-replicate ratios, a Bonferroni-adjusted interval for the family of all pairs, the decision
// (a pair differs when its adjusted interval excludes 1) and the compact letter display
// (compact_letters.hpp). Replicate b of every line must come from the same bootstrap replicate
// (the data-uncertainty replicates of a campaign: campaign/data_uncertainty.hpp), never from the
// Monte Carlo samples of one run, whose spread shrinks with their number.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace growthuq {

enum class PairDecision { differs, not_distinguishable, undetermined };

// "yes", "no" or "" (undetermined), as the tables write it.
const char* differs_cell(PairDecision decision);

struct PairComparison {
  std::size_t line_a = 0;  // indices into the lines compared, line_a < line_b
  std::size_t line_b = 0;
  double ratio = std::numeric_limits<double>::quiet_NaN();  // median_a / median_b
  double ci_low = std::numeric_limits<double>::quiet_NaN();  // 2.5 % of the per-replicate ratios
  double ci_high = std::numeric_limits<double>::quiet_NaN();  // 97.5 %
  double adjusted_low = std::numeric_limits<double>::quiet_NaN();   // alpha / (2 m)
  double adjusted_high = std::numeric_limits<double>::quiet_NaN();  // 1 - alpha / (2 m)
  std::size_t replicates = 0;  // replicates in which both lines have a median
  PairDecision decision = PairDecision::undetermined;
  std::string reason;  // why undetermined; empty otherwise
};

struct LineComparisons {
  double alpha = 0.05;               // family-wise error rate of the pairs together
  std::size_t pairs = 0;             // m = K (K - 1) / 2
  double adjusted_level = 0;         // 1 - alpha / m, the level of each adjusted interval
  std::size_t minimum_replicates = 0;  // paired replicates an adjusted interval needs
  std::vector<PairComparison> comparisons;  // (0,1), (0,2), ..., (1,2), ...
  std::vector<std::string> letters;         // per line; undetermined pairs count as not different
};

// Paired replicates an adjusted interval needs: B with (B + 1) alpha / (2 m) >= 1, so that at
// least one replicate lies beyond each end on average (Davison and Hinkley 1997, 5.2). 39 for one
// pair, 119 for 3, 399 for 10, 899 for 15, at alpha = 0.05.
std::size_t minimum_paired_replicates(std::size_t pairs, double alpha);

// `medians[i]`: line i's point estimate (the campaign's median); `replicate_medians[i][b]`: its
// median in replicate b, NaN where that replicate gave none. Every line has the same number of
// replicates. A pair is undetermined (and counts as not different for the letters) when a median
// or a paired replicate median is not positive (a ratio is then undefined) or the pair has fewer
// paired replicates than minimum_paired_replicates. std::invalid_argument for mismatched sizes
// or alpha outside (0, 1) (a programming error).
LineComparisons compare_lines(std::span<const double> medians, std::span<const std::vector<double>> replicate_medians,
                              double alpha = 0.05);

}  // namespace growthuq
