// Per-quantity summaries: quantiles against numpy, the ranks of the median's confidence interval
// against exact binomial sums, and the interval's coverage by simulation.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "growthuq/core/units.hpp"
#include "growthuq/stats/quantity_summary.hpp"
#include "growthuq/stats/sample_summary.hpp"

using namespace growthuq;

namespace {

constexpr double missing = std::numeric_limits<double>::quiet_NaN();

ResultColumn column_of(const char* quantity, const char* unit, std::vector<double> values) {
  ResultColumn column;
  column.quantity = quantity;
  column.unit = &find_unit(unit, "test", "unit");
  column.values.assign(values.begin(), values.end());
  return column;
}

}  // namespace

TEST_CASE("summary of the samples holding a value equals numpy; the samples lacking one are counted, not used") {
  // /usr/bin/python3 -c "import numpy as np; x=np.array([0.73,2.9,1.4,-0.6,5.25,3.3,0.05,1.4,8.8,2.2,4.1,-1.7]);
  //   print([float(np.quantile(x,p)) for p in (0.1,0.25,0.5,0.75,0.9)], float(x.mean()), float(x.std(ddof=1)))"
  //   -> [-0.5349999999999999, 0.56, 1.8, 3.5, 5.135000000000001] 2.319166666666667 2.8462973023444573
  // (numpy 1.24.2). The same 12 values with three samples lacking the quantity (NaN, as a
  // model leaves what it did not compute) in between.
  const std::vector<double> values{0.73, 2.9, missing, 1.4, -0.6, 5.25, 3.3, 0.05, 1.4, missing, 8.8, 2.2, 4.1, missing, -1.7};
  const QuantitySummary s = summarize_quantity("wild_type", column_of("p", "MPa", values));
  CHECK(s.line == "wild_type");
  CHECK(s.quantity == "p");
  CHECK(s.unit == "MPa");
  CHECK(s.n == 12);
  CHECK(s.n_flagged == 3);
  // numpy interpolates with a + t (b - a) or b - (1 - t)(b - a): a few ulps apart at most.
  CHECK(s.p10 == doctest::Approx(-0.5349999999999999).epsilon(4e-16));
  CHECK(s.q1 == doctest::Approx(0.56).epsilon(4e-16));
  CHECK(s.median == doctest::Approx(1.8).epsilon(4e-16));
  CHECK(s.q3 == doctest::Approx(3.5).epsilon(4e-16));
  CHECK(s.p90 == doctest::Approx(5.135000000000001).epsilon(4e-16));
  CHECK(s.iqr == doctest::Approx(3.5 - 0.56).epsilon(4e-16));
  // Sums of 12 terms: a few roundings of 1e-16 each.
  CHECK(s.mean == doctest::Approx(2.319166666666667).epsilon(1e-15));
  CHECK(s.sd == doctest::Approx(2.8462973023444573).epsilon(1e-15));
  // n = 12: P(B <= 2) = 79/4096 = 0.0193 <= 0.025 < P(B <= 3) = 299/4096, so ranks 3 and 10 of
  // the sorted values -1.7, -0.6, 0.05, 0.73, 1.4, 1.4, 2.2, 2.9, 3.3, 4.1, 5.25, 8.8.
  CHECK(s.median_ci_low == 0.05);
  CHECK(s.median_ci_high == 4.1);
}

TEST_CASE("a quantity counts every sample holding a value of it, whatever flag the sample carries") {
  // Six samples: ok, no_growth (p and E computed, v = 0), burst (nothing computed), ok,
  // invalid_input raised by the viscosity model (p and E computed, eta and v not), ok.
  // pandas' median of each samples.csv column is the summary's (tests/campaign/check_flagged_cells.py).
  const QuantitySummary v = summarize_quantity("xeg113", column_of("v", "um/s", {0.02, 0.0, missing, 0.03, missing, 0.05}));
  CHECK(v.n == 4);
  CHECK(v.n_flagged == 2);
  CHECK(v.median == doctest::Approx(0.025).epsilon(1e-15));  // sorted 0, 0.02, 0.03, 0.05
  const QuantitySummary p = summarize_quantity("xeg113", column_of("p", "MPa", {0.2, 0.1, missing, 0.3, 0.05, 0.4}));
  CHECK(p.n == 5);
  CHECK(p.n_flagged == 1);
  CHECK(p.median == 0.2);  // sorted 0.05, 0.1, 0.2, 0.3, 0.4: the flagged samples' p included
  // An input holds every drawn value: nothing flagged, even a draw that got a sample flagged.
  ResultColumn h = column_of("h", "nm", {145, 160, 150, 130, -3, 170});
  h.is_input = true;
  const QuantitySummary drawn = summarize_quantity("xeg113", h);
  CHECK(drawn.n == 6);
  CHECK(drawn.n_flagged == 0);
  CHECK(drawn.median == 147.5);
}

TEST_CASE("undefined statistics are NaN, never a made-up number") {
  const QuantitySummary empty = summarize_quantity("pme48", column_of("E", "MPa", {missing, missing}));
  CHECK(empty.n == 0);
  CHECK(empty.n_flagged == 2);
  for (const double cell : {empty.median, empty.q1, empty.q3, empty.iqr, empty.p10, empty.p90, empty.mean,
                            empty.sd, empty.median_ci_low, empty.median_ci_high}) {
    CHECK(std::isnan(cell));
  }
  const QuantitySummary one = summarize_quantity("pme48", column_of("E", "MPa", {42.0}));
  CHECK(one.median == 42.0);
  CHECK(one.mean == 42.0);
  CHECK(one.iqr == 0.0);
  CHECK(std::isnan(one.sd));
  CHECK(std::isnan(one.median_ci_low));
  // n = 5: even [min, max] covers only 1 - 2/32 = 0.9375 < 95 %: no interval. n = 6: [min, max].
  const QuantitySummary s5 = summarize_quantity("l", column_of("E", "MPa", {5, 1, 4, 2, 3}));
  CHECK(std::isnan(s5.median_ci_low));
  CHECK(std::isnan(s5.median_ci_high));
  const QuantitySummary s6 = summarize_quantity("l", column_of("E", "MPa", {5, 1, 4, 2, 3, 6}));
  CHECK(s6.median_ci_low == 1.0);
  CHECK(s6.median_ci_high == 6.0);
}

TEST_CASE("confidence ranks of the median equal exact binomial sums") {
  // Exact ranks from 50-digit sums, largest l with sum_{k<l} C(n,k)/2^n <= 0.025:
  //   /usr/bin/python3 -c "import mpmath as mp; mp.mp.dps=50
  //   for n in (6,7,10,25,100,1000,100000):
  //     c=mp.mpf(0); k=0
  //     while c+mp.binomial(n,k)/mp.mpf(2)**n <= mp.mpf('0.025'): c+=mp.binomial(n,k)/mp.mpf(2)**n; k+=1
  //     print(n, k, n+1-k, mp.nstr(1-2*c,17))"
  // n = 100 gives ranks 40 and 61, the entry of Conover's (1999) table A3 for 95 %.
  struct Case {
    std::size_t n, lower, upper;
    double coverage;
  };
  const Case cases[] = {{6, 1, 6, 0.96875},
                        {7, 1, 7, 0.984375},
                        {10, 2, 9, 0.978515625},
                        {25, 8, 18, 0.95671474933624268},
                        {100, 40, 61, 0.96479979978229518},
                        {1000, 469, 532, 0.95370880263950185},
                        {100000, 49690, 50311, 0.95044428533047507}};
  for (const Case& c : cases) {
    CAPTURE(c.n);
    const MedianConfidenceRanks ranks = median_confidence_ranks(c.n);
    CHECK(ranks.reached);
    CHECK(ranks.lower == c.lower);
    CHECK(ranks.upper == c.upper);
    // GSL's binomial CDF (incomplete beta) is accurate to ~1e-14 relative on the tail.
    CHECK(ranks.coverage == doctest::Approx(c.coverage).epsilon(1e-12));
  }
  const MedianConfidenceRanks five = median_confidence_ranks(5);
  CHECK_FALSE(five.reached);
  CHECK(five.lower == 1);
  CHECK(five.upper == 5);
  CHECK(five.coverage == doctest::Approx(0.9375).epsilon(1e-14));
  CHECK(median_confidence_ranks(0).upper == 0);
  // Another level, 90 % (tail 0.05): n = 10 has P(B <= 1) = 11/1024 <= 0.05 < P(B <= 2) = 56/1024,
  // so rank 2; n = 11 has P(B <= 2) = 67/2048 <= 0.05 < P(B <= 3) = 232/2048, so rank 3.
  CHECK(median_confidence_ranks(10, 0.90).lower == 2);
  CHECK(median_confidence_ranks(11, 0.90).lower == 3);
  CHECK_THROWS_AS(median_confidence_ranks(10, 1.0), std::invalid_argument);
}

TEST_CASE("the interval covers the true median as often as its exact coverage says") {
  // Exponential law with rate 1: median ln 2. For n = 25 the exact coverage is 0.956715; 20000
  // independent samples estimate it with standard error sqrt(0.957 * 0.043 / 20000) = 0.0014,
  // so 4 standard errors (0.006) bound the difference (fixed seed: the test is deterministic).
  std::mt19937_64 engine(20240607);
  std::exponential_distribution<double> law(1.0);
  const double true_median = std::log(2.0);
  const std::size_t n = 25, repetitions = 20000;
  std::size_t covered = 0;
  for (std::size_t r = 0; r < repetitions; ++r) {
    ResultColumn column = column_of("tau", "s", {});
    for (std::size_t i = 0; i < n; ++i) column.values.push_back(law(engine));
    const QuantitySummary s = summarize_quantity("sim", column);
    if (s.median_ci_low <= true_median && true_median <= s.median_ci_high) ++covered;
  }
  const double coverage = static_cast<double>(covered) / static_cast<double>(repetitions);
  CHECK(std::abs(coverage - 0.95671474933624268) < 0.006);
}

TEST_CASE("selected order statistics equal those of a full sort") {
  // summarize_quantity selects order statistics; summarize() (sample_summary.hpp) sorts. Same
  // interpolation arithmetic on the same two order statistics: equal to the bit. Sizes cover
  // n - 1 divisible and not divisible by 4 and 10, ties (rounded values) and the CI ranks.
  std::mt19937_64 engine(5);
  std::lognormal_distribution<double> law(0.0, 1.0);
  for (const std::size_t n : {1u, 2u, 3u, 6u, 11u, 40u, 41u, 1001u, 77777u}) {
    CAPTURE(n);
    ResultColumn column = column_of("k", "N/m", {});
    for (std::size_t i = 0; i < n; ++i) column.values.push_back(std::round(law(engine) * 100) / 100);
    const QuantitySummary s = summarize_quantity("l", column);
    const SampleSummary reference = summarize(column.values);
    CHECK(s.p10 == reference.p10);
    CHECK(s.q1 == reference.q1);
    CHECK(s.median == reference.median);
    CHECK(s.q3 == reference.q3);
    CHECK(s.p90 == reference.p90);
    std::vector<double> sorted(column.values.begin(), column.values.end());
    std::sort(sorted.begin(), sorted.end());
    const MedianConfidenceRanks ranks = median_confidence_ranks(n);
    if (ranks.reached) {
      CHECK(s.median_ci_low == sorted[ranks.lower - 1]);
      CHECK(s.median_ci_high == sorted[ranks.upper - 1]);
    }
  }
}
