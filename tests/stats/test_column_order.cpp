// One sort per column for the line statistics: twice the average ranks against average_ranks
// (which ties, zeros of both signs and negatives test), order statistics against a full sort,
// ranks from design strata against the sort, a summary from order statistics against
// summarize_quantity, and sums of products against the plain loop.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "growthuq/core/units.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "stats/column_order.hpp"
#include "growthuq/stats/line_analysis.hpp"
#include "growthuq/stats/quantity_summary.hpp"
#include "growthuq/stats/ranks.hpp"
#include "stats/cross_products.hpp"

using namespace growthuq;

namespace {

// Values with exact ties, both zeros, negatives, and values a 32-bit key cannot tell apart.
std::vector<double> awkward_values(std::size_t n, std::uint64_t seed) {
  RandomStream stream(derive_key(seed, "column_order"));
  std::vector<double> values(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = stream.uniform();
    switch (stream.below(6)) {
      case 0: values[i] = std::floor(20 * u) - 10; break;                  // ties
      case 1: values[i] = u < 0.5 ? -0.0 : 0.0; break;                     // both zeros tie
      case 2: values[i] = 1.0 + std::floor(1000 * u) * 0x1.0p-45; break;  // equal in 45 bits
      default: values[i] = std::exp(3 * (u - 0.5)) * (u < 0.3 ? -1 : 1); break;
    }
  }
  return values;
}

}  // namespace

TEST_CASE("order_column: twice the average ranks and the order statistics of a full sort") {
  for (const std::size_t n : {std::size_t{1}, std::size_t{2}, std::size_t{1000}, std::size_t{100003}}) {
    CAPTURE(n);
    const std::vector<double> values = awkward_values(n, n);
    std::vector<std::size_t> positions{0, n - 1, n / 2, n / 3};
    const ColumnOrder order = order_column(values, positions);
    const std::vector<double> expected = average_ranks(values);
    for (std::size_t i = 0; i < n; ++i) REQUIRE(order.twice_ranks[i] == 2 * expected[i]);
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t k = 0; k < positions.size(); ++k) CHECK(order.order_statistics[k] == sorted[positions[k]]);
  }
  CHECK_THROWS_AS(order_column(std::vector<double>{1.0, std::nan("")}, {}), std::invalid_argument);
  CHECK_THROWS_AS(order_column(std::vector<double>{1.0, 2.0}, std::vector<std::size_t>{2}), std::out_of_range);
}

TEST_CASE("a column's order from its strata equals its order from a sort") {
  // Values strictly increasing with a random stratum per sample, some samples not used.
  const std::size_t n = 50000;
  RandomStream stream(derive_key(7, "strata"));
  std::vector<std::uint32_t> strata(n);
  std::iota(strata.begin(), strata.end(), 0u);
  for (std::size_t i = n - 1; i > 0; --i) std::swap(strata[i], strata[stream.below(i + 1)]);
  std::vector<double> values(n);
  for (std::size_t i = 0; i < n; ++i) values[i] = std::log1p(static_cast<double>(strata[i]));
  std::vector<std::uint32_t> used;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (stream.uniform() > 0.03) used.push_back(i);
  }
  for (const bool every_sample : {false, true}) {
    CAPTURE(every_sample);
    std::vector<std::uint32_t> samples = used;
    if (every_sample) {
      samples.resize(n);
      std::iota(samples.begin(), samples.end(), 0u);
    }
    const std::vector<std::size_t> wanted = summary_positions(samples.size());
    const ColumnAnalysis sorted = analyze_column(values, samples, wanted);
    const ColumnAnalysis from_strata = analyze_column(values, samples, wanted, strata);
    REQUIRE(sorted.verdict == ColumnAnalysis::Verdict::used);
    REQUIRE(from_strata.verdict == ColumnAnalysis::Verdict::used);
    CHECK(std::ranges::equal(sorted.twice_ranks, from_strata.twice_ranks));
    CHECK(sorted.order_statistics == from_strata.order_statistics);
    CHECK(sorted.moments.mean == from_strata.moments.mean);
  }
}

TEST_CASE("a summary from order statistics equals summarize_quantity") {
  ResultColumn column;
  column.quantity = "p";
  column.unit = &find_unit("MPa", "test", "unit");
  std::vector<SampleStatus> status;
  RandomStream stream(derive_key(3, "summary"));
  for (int i = 0; i < 20001; ++i) {
    const bool flagged = stream.uniform() < 0.05;
    column.values.push_back(flagged ? std::nan("") : std::exp(stream.uniform()));
    status.push_back(flagged ? SampleStatus::burst : SampleStatus::ok);
  }
  const std::vector<std::uint32_t> used = analysis_samples(status);
  const ColumnAnalysis analysis = analyze_column(column.values, used, summary_positions(used.size()));
  const QuantitySummary fast = summary_from_order("line", column, column.values.size() - used.size(), analysis.moments,
                                                  analysis.order_statistics);
  const QuantitySummary reference = summarize_quantity("line", column);
  CHECK(fast.n == reference.n);
  CHECK(fast.n_flagged == reference.n_flagged);
  for (const auto member : {&QuantitySummary::median, &QuantitySummary::q1, &QuantitySummary::q3, &QuantitySummary::iqr,
                            &QuantitySummary::p10, &QuantitySummary::p90, &QuantitySummary::mean, &QuantitySummary::sd,
                            &QuantitySummary::median_ci_low, &QuantitySummary::median_ci_high}) {
    CHECK(fast.*member == reference.*member);
  }
}

TEST_CASE("sums of products of shifted columns equal the plain loop") {
  const std::size_t n = 5003;
  RandomStream stream(derive_key(9, "products"));
  std::vector<std::vector<double>> columns(3, std::vector<double>(n));
  for (auto& column : columns) {
    for (double& x : column) x = stream.uniform() * 10;
  }
  const std::vector<double> shift{5.0, 4.5, 0.0};
  const std::vector<const double*> pointers{columns[0].data(), columns[1].data(), columns[2].data()};
  const Eigen::MatrixXd products = detail::cross_products(pointers, n, shift);
  std::vector<std::uint32_t> every(n);
  std::iota(every.begin(), every.end(), 0u);
  const Eigen::MatrixXd by_rows = detail::cross_products(pointers, every, shift);
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      long double plain = 0;
      for (std::size_t i = 0; i < n; ++i) plain += (columns[a][i] - shift[a]) * (columns[b][i] - shift[b]);
      // 4-lane sums round differently from one long double sum: a relative 1e-13 at n = 5e3.
      CHECK(products(a, b) == doctest::Approx(static_cast<double>(plain)).epsilon(1e-13));
      CHECK(products(a, b) == products(b, a));
      CHECK(by_rows(a, b) == products(a, b));
    }
  }
}
