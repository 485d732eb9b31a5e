// Line comparisons from bootstrap replicates (Eq. (T5), src/stats/README.md): the intervals and
// decisions against hand-computed order statistics, the undetermined cases, and the family-wise
// false-positive rate on lines drawn from one law, with the power to see a real difference.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "growthuq/distributions/standard_normal.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/stats/line_comparisons.hpp"

using namespace growthuq;

namespace {

constexpr double missing = std::numeric_limits<double>::quiet_NaN();  // a replicate without a median

// Values 1, 2, ..., n times `scale`, in a shuffled but fixed order.
std::vector<double> ladder(std::size_t n, double scale, std::uint64_t seed) {
  std::vector<double> values(n);
  for (std::size_t i = 0; i < n; ++i) values[i] = scale * static_cast<double>(i + 1);
  RandomStream stream(seed);
  for (std::size_t i = n - 1; i > 0; --i) std::swap(values[i], values[stream.below(i + 1)]);
  return values;
}

}  // namespace

TEST_CASE("line comparisons: the replicates an adjusted interval needs") {
  // (B + 1) alpha / (2 m) >= 1: B >= 2 m / alpha - 1.
  CHECK(minimum_paired_replicates(1, 0.05) == 39);
  CHECK(minimum_paired_replicates(3, 0.05) == 119);
  CHECK(minimum_paired_replicates(10, 0.05) == 399);
  CHECK(minimum_paired_replicates(15, 0.05) == 599);
  CHECK(minimum_paired_replicates(0, 0.05) == 0);
}

TEST_CASE("line comparisons: two lines, intervals from the order statistics of the per-replicate ratios") {
  // Line B's replicate medians are all 1; line A's are 0.50, 0.51, ..., 0.88 (39 values),
  // shuffled. The ratios are A's values. m = 1 pair needs 39 replicates, and its adjusted interval
  // is the 95 % one: order statistics h = (39 + 1) 0.025 = 1 and (39 + 1) 0.975 = 39, the
  // smallest and the largest ratio, 0.50 and 0.88.
  std::vector<double> a = ladder(39, 0.01, 7);
  for (double& x : a) x += 0.49;
  const std::vector<std::vector<double>> replicates{a, std::vector<double>(39, 1.0)};
  const std::vector<double> medians{0.7, 1.0};
  const LineComparisons result = compare_lines(medians, replicates);
  REQUIRE(result.comparisons.size() == 1);
  const PairComparison& pair = result.comparisons.front();
  CHECK(result.pairs == 1);
  CHECK(result.adjusted_level == doctest::Approx(0.95));
  CHECK(pair.line_a == 0);
  CHECK(pair.line_b == 1);
  CHECK(pair.ratio == doctest::Approx(0.7));
  CHECK(pair.replicates == 39);
  CHECK(pair.ci_low == doctest::Approx(0.50));
  CHECK(pair.ci_high == doctest::Approx(0.88));
  CHECK(pair.adjusted_low == doctest::Approx(0.50));
  CHECK(pair.adjusted_high == doctest::Approx(0.88));
  CHECK(pair.decision == PairDecision::differs);  // 0.88 < 1
  CHECK(result.letters == std::vector<std::string>{"a", "b"});
  CHECK(std::string(differs_cell(pair.decision)) == "yes");

  // With 79 replicates (0.50 ... 1.28) the 95 % interval lies between order statistics:
  // h = 80 x 0.025 = 2 and 80 x 0.975 = 78, the 2nd smallest and 2nd largest, 0.51 and 1.27.
  std::vector<double> wide = ladder(79, 0.01, 9);
  for (double& x : wide) x += 0.49;
  const LineComparisons straddling = compare_lines(medians, std::vector<std::vector<double>>{wide, std::vector<double>(79, 1.0)});
  CHECK(straddling.comparisons[0].ci_low == doctest::Approx(0.51));
  CHECK(straddling.comparisons[0].ci_high == doctest::Approx(1.27));
  CHECK(straddling.comparisons[0].decision == PairDecision::not_distinguishable);
  CHECK(straddling.letters == std::vector<std::string>{"a", "a"});
}

TEST_CASE("line comparisons: three lines, Bonferroni over three pairs, a non-transitive outcome") {
  // 120 replicates (>= 119 for m = 3). Replicate medians: A = r, B = 1.2 r, C = 1.44 r with r
  // the same in every line: every ratio is constant, so each interval is a point: A/B = 1/1.2,
  // A/C = 1/1.44, B/C = 1/1.2, all excluding 1: three letters. Then B is made noisy so that
  // its ratios to both neighbours straddle 1 while A/C stays 1/1.44: A ~ B, B ~ C, A != C.
  const std::size_t replicates = 120;
  const std::vector<double> r = ladder(replicates, 0.001, 3);
  std::vector<std::vector<double>> lines(3, std::vector<double>(replicates));
  for (std::size_t b = 0; b < replicates; ++b) {
    lines[0][b] = 1.0 + r[b];
    lines[1][b] = 1.2 * (1.0 + r[b]);
    lines[2][b] = 1.44 * (1.0 + r[b]);
  }
  const std::vector<double> medians{1.06, 1.2 * 1.06, 1.44 * 1.06};
  LineComparisons result = compare_lines(medians, lines);
  CHECK(result.pairs == 3);
  CHECK(result.adjusted_level == doctest::Approx(1.0 - 0.05 / 3));
  CHECK(result.minimum_replicates == 119);
  REQUIRE(result.comparisons.size() == 3);
  CHECK(result.comparisons[0].adjusted_high == doctest::Approx(1 / 1.2));
  CHECK(result.comparisons[1].adjusted_low == doctest::Approx(1 / 1.44));
  CHECK(result.comparisons[2].line_a == 1);
  CHECK(result.comparisons[2].line_b == 2);
  CHECK(result.letters == std::vector<std::string>{"a", "b", "c"});

  // B's replicates spread from 0.9 to 1.5 times A's (uniformly, independent of r): B/A and
  // B/C each have replicates on both sides of 1 beyond the 1/120 tails.
  const std::vector<double> spread = ladder(replicates, 0.6 / static_cast<double>(replicates), 11);
  for (std::size_t b = 0; b < replicates; ++b) lines[1][b] = (0.9 + spread[b]) * lines[0][b];
  result = compare_lines(medians, lines);
  CHECK(result.comparisons[0].decision == PairDecision::not_distinguishable);
  CHECK(result.comparisons[1].decision == PairDecision::differs);
  CHECK(result.comparisons[2].decision == PairDecision::not_distinguishable);
  CHECK(result.letters == std::vector<std::string>{"a", "ab", "b"});
}

TEST_CASE("line comparisons: too few replicates, a zero median and missing replicates leave a pair undetermined") {
  const std::vector<double> medians{1.0, 2.0};
  // 38 replicates: one short of the 39 that one pair needs.
  std::vector<std::vector<double>> lines{std::vector<double>(38, 1.0), std::vector<double>(38, 2.0)};
  LineComparisons result = compare_lines(medians, lines);
  CHECK(result.comparisons[0].decision == PairDecision::undetermined);
  CHECK(result.comparisons[0].reason == "38 paired replicates; the adjusted interval of 1 pairs needs at least 39");
  CHECK(result.comparisons[0].ci_high == doctest::Approx(0.5));  // the 95 % interval is still given
  CHECK(std::isnan(result.comparisons[0].adjusted_low));
  CHECK(result.letters == std::vector<std::string>{"a", "a"});  // undetermined: no claim of a difference
  CHECK(std::string(differs_cell(PairDecision::undetermined)).empty());

  // 40 replicates, one missing in each line (different ones): 38 paired.
  lines = {std::vector<double>(40, 1.0), std::vector<double>(40, 2.0)};
  lines[0][3] = missing;
  lines[1][17] = missing;
  result = compare_lines(medians, lines);
  CHECK(result.comparisons[0].replicates == 38);
  CHECK(result.comparisons[0].decision == PairDecision::undetermined);
  lines[1][17] = 2.0;
  result = compare_lines(medians, lines);
  CHECK(result.comparisons[0].replicates == 39);
  CHECK(result.comparisons[0].decision == PairDecision::differs);

  // A growth rate whose median is 0 in some replicates (most tubes below the yield pressure).
  lines[0][5] = 0.0;
  result = compare_lines(medians, lines);
  CHECK(result.comparisons[0].decision == PairDecision::undetermined);
  CHECK(result.comparisons[0].reason == "a ratio of medians is undefined: a median is 0 or negative in 1 replicates");
  CHECK(std::isnan(result.comparisons[0].ratio));

  // The campaign's own median missing (every sample of the line flagged): no ratio either.
  lines[0][5] = 1.0;
  const std::vector<double> no_median{std::numeric_limits<double>::quiet_NaN(), 2.0};
  result = compare_lines(no_median, lines);
  CHECK(result.comparisons[0].decision == PairDecision::undetermined);
  CHECK(result.comparisons[0].reason == "a ratio of medians is undefined: a line's median is missing, 0 or negative");
}

TEST_CASE("line comparisons: mismatched sizes and alpha outside (0, 1) are programming errors") {
  const std::vector<double> medians{1.0, 2.0};
  const std::vector<std::vector<double>> uneven{std::vector<double>(40, 1.0), std::vector<double>(39, 2.0)};
  CHECK_THROWS_AS(compare_lines(medians, uneven), std::invalid_argument);
  const std::vector<std::vector<double>> one{std::vector<double>(40, 1.0)};
  CHECK_THROWS_AS(compare_lines(medians, one), std::invalid_argument);
  const std::vector<std::vector<double>> even{std::vector<double>(40, 1.0), std::vector<double>(40, 2.0)};
  CHECK_THROWS_AS(compare_lines(medians, even, 0.0), std::invalid_argument);
}

namespace {

// One simulated study: K lines of n tubes each, line k drawn from lognormal(ln(shift_k), sigma);
// each line's law fitted by maximum likelihood (mu = mean of ln x, sigma = its sd over n), and
// a parametric bootstrap over tubes as the campaigns run it: replicate b redraws n values per
// line from the fitted law, refits it and takes the fitted law's median exp(mu).
LineComparisons simulated_study(std::uint64_t key, const std::vector<double>& shifts, std::size_t tubes,
                                std::size_t replicates, double sigma) {
  const std::size_t lines = shifts.size();
  std::vector<double> u(tubes), z(tubes);
  auto fitted = [&](RandomStream& stream, double mu, double sd, double& fitted_sd) {
    for (double& x : u) x = stream.uniform_open();
    standard_normal_quantiles(u, z);
    double mean = 0.0;
    for (double& x : z) {
      x = mu + sd * x;
      mean += x;
    }
    mean /= static_cast<double>(tubes);
    double squares = 0.0;
    for (const double x : z) squares += (x - mean) * (x - mean);
    fitted_sd = std::sqrt(squares / static_cast<double>(tubes));
    return mean;
  };
  std::vector<double> medians(lines);
  std::vector<std::vector<double>> replicate_medians(lines, std::vector<double>(replicates));
  for (std::size_t k = 0; k < lines; ++k) {
    RandomStream stream(derive_key(key, "line " + std::to_string(k)));
    double sd = 0.0;
    const double mu = fitted(stream, std::log(shifts[k]), sigma, sd);
    medians[k] = std::exp(mu);
    double ignored = 0.0;
    for (double& median : replicate_medians[k]) median = std::exp(fitted(stream, mu, sd, ignored));
  }
  return compare_lines(medians, replicate_medians);
}

}  // namespace

TEST_CASE("line comparisons: lines drawn from one law are found different in at most about 5 % of studies") {
  // 5 lines x 30 tubes from one lognormal law (median 3, sigma 0.35 on the log scale, about a
  // stiffness's spread), 400 replicates (>= 399 for 10 pairs), 1000 studies. The family-wise
  // false-positive rate (any pair found different) must be at most 5 % plus three Monte Carlo
  // standard errors at 5 % (sqrt(0.05 x 0.95 / 1000) = 0.0069): <= 0.0707. The unadjusted 95 %
  // intervals are counted too: they find a difference in far more studies (about 1 - 0.95^10
  // for independent pairs), which shows the simulation can see false positives.
  const std::size_t studies = 1000;
  const std::vector<double> same(5, 3.0);
  std::size_t family_errors = 0, unadjusted_errors = 0, letter_errors = 0;
  for (std::size_t s = 0; s < studies; ++s) {
    const LineComparisons result = simulated_study(derive_key(2004, "study " + std::to_string(s)), same, 30, 400, 0.35);
    bool any = false, any_unadjusted = false;
    for (const PairComparison& pair : result.comparisons) {
      REQUIRE(pair.decision != PairDecision::undetermined);
      any = any || pair.decision == PairDecision::differs;
      any_unadjusted = any_unadjusted || pair.ci_low > 1.0 || pair.ci_high < 1.0;
    }
    family_errors += any ? 1 : 0;
    unadjusted_errors += any_unadjusted ? 1 : 0;
    const bool one_letter = std::all_of(result.letters.begin(), result.letters.end(), [](const std::string& l) { return l == "a"; });
    letter_errors += one_letter ? 0 : 1;
  }
  const double rate = static_cast<double>(family_errors) / static_cast<double>(studies);
  const double unadjusted = static_cast<double>(unadjusted_errors) / static_cast<double>(studies);
  MESSAGE("family-wise false-positive rate " << rate << " (Bonferroni), " << unadjusted << " without adjustment");
  CHECK(rate <= 0.0707);
  CHECK(unadjusted >= 0.15);
  CHECK(letter_errors == family_errors);  // the letters show a difference exactly when a pair differs
}

TEST_CASE("line comparisons: a line whose median is 1.6 times the others' is found different") {
  // Same design, line 2 shifted: ln 1.6 = 0.47 against a standard error of the log ratio of
  // 0.35 sqrt(2 / 30) = 0.090, 5.2 standard errors, beyond Bonferroni's 2.81 by 2.4 (each pair
  // found in 99 % of studies, normal approximation); all four of its pairs required together
  // in 90 % of 200 studies. The other pairs keep the family-wise rate.
  const std::size_t studies = 200;
  const std::vector<double> shifted{3.0, 3.0, 4.8, 3.0, 3.0};
  std::size_t found = 0, false_positives = 0;
  for (std::size_t s = 0; s < studies; ++s) {
    const LineComparisons result = simulated_study(derive_key(1504, "study " + std::to_string(s)), shifted, 30, 400, 0.35);
    bool found_all = true, any_false = false;
    for (const PairComparison& pair : result.comparisons) {
      const bool real = pair.line_a == 2 || pair.line_b == 2;
      if (real) found_all = found_all && pair.decision == PairDecision::differs;
      if (!real) any_false = any_false || pair.decision == PairDecision::differs;
    }
    found += found_all ? 1 : 0;
    false_positives += any_false ? 1 : 0;
    if (found_all && !any_false) CHECK(result.letters == std::vector<std::string>{"a", "a", "b", "a", "a"});
  }
  MESSAGE("line 2 found different from all four others in " << found << " of " << studies << " studies");
  CHECK(static_cast<double>(found) >= 0.9 * studies);
  CHECK(static_cast<double>(false_positives) <= 0.09 * studies);
}
