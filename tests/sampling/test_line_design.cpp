// Designs of a line: columns independent of the other variables, values = the marginal's
// quantile at each stratum's point, correlation imposed without moving any value.
#include <doctest/doctest.h>

#include <algorithm>
#include <span>
#include <thread>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/distributions/families.hpp"
#include "growthuq/sampling/line_design.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/stats/rank_correlation.hpp"

using namespace growthuq;

namespace {

std::vector<DesignVariable> wild_type_variables() {
  // Published data (distributions/README.md), wild type: median (IQR) of k [N/m], h [nm],
  // d [um], d0 [um].
  return {{"k", Lognormal::from_median_iqr(2.87, 0.83)},
          {"h", Lognormal::from_median_iqr(145, 31)},
          {"d", Lognormal::from_median_iqr(6.56, 1.19)},
          {"d0", Lognormal::from_median_iqr(5.35, 1.15)}};
}

std::vector<double> sorted(std::span<const double> values) {
  std::vector<double> copy(values.begin(), values.end());
  std::sort(copy.begin(), copy.end());
  return copy;
}

}  // namespace

TEST_CASE("adding a variable to a line leaves the other columns unchanged") {
  SamplingOptions options;
  options.samples = 500;
  options.seed = 2022;
  auto variables = wild_type_variables();
  const LineDesign four = latin_hypercube_design("wild_type", variables, options, nullptr);
  variables.insert(variables.begin() + 1, DesignVariable{"tau", Lognormal::from_median_iqr(6.81, 3.61)});
  const LineDesign five = latin_hypercube_design("wild_type", variables, options, nullptr);
  CHECK(five.values[0] == four.values[0]);
  CHECK(five.values[2] == four.values[1]);
  CHECK(five.values[4] == four.values[3]);
  // ...while another seed or line gives another design.
  options.seed = 2023;
  CHECK(latin_hypercube_design("wild_type", variables, options, nullptr).values[0] != five.values[0]);
  options.seed = 2022;
  CHECK(latin_hypercube_design("pme48", variables, options, nullptr).values[0] != five.values[0]);
}

TEST_CASE("a value is the marginal's quantile at its stratum's point") {
  SamplingOptions options;
  options.samples = 257;
  options.seed = 4;
  const auto variables = wild_type_variables();
  const LineDesign design = latin_hypercube_design("wild_type", variables, options, nullptr);
  const LatinColumn column = latin_hypercube_column(257, stream_key(4, "wild_type", "h"), StratumPosition::random);
  for (std::size_t i = 0; i < 257; ++i) {
    REQUIRE(design.values[1][i] == quantile(variables[1].distribution, column.u_by_stratum[column.stratum[i]]));
  }
  CHECK(std::ranges::equal(design.ranks[1], column.stratum));
  CHECK_FALSE(design.correlation.imposed);
}

TEST_CASE("imposing a rank correlation only reorders each column") {
  SamplingOptions options;
  options.samples = 4000;
  options.seed = 8;
  const auto variables = wild_type_variables();
  Eigen::MatrixXd s(4, 4);
  s << 1, 0.25, 0.55, 0.3, 0.25, 1, -0.1, 0.05, 0.55, -0.1, 1, 0.7, 0.3, 0.05, 0.7, 1;
  const ImanConoverTarget target = make_iman_conover_target(s, {"k", "h", "d", "d0"}, "test");
  const LineDesign plain = latin_hypercube_design("wild_type", variables, options, nullptr);
  const LineDesign correlated = latin_hypercube_design("wild_type", variables, options, &target);
  CHECK(correlated.correlation.imposed);
  CHECK(correlated.warnings.empty());
  for (std::size_t j = 0; j < 4; ++j) CHECK(sorted(correlated.values[j]) == sorted(plain.values[j]));
  CHECK(correlated.values[0] == plain.values[0]);
  // Spearman of the values (with the general tie-aware estimator) against the target;
  // tolerance 1/sqrt(n) = 0.016 (see test_iman_conover.cpp for why the error is of that order).
  const Eigen::MatrixXd achieved = spearman_matrix({correlated.values[0], correlated.values[1], correlated.values[2], correlated.values[3]});
  CHECK((achieved - s).cwiseAbs().maxCoeff() < 0.016);
}

TEST_CASE("too few samples for the correlation: a warning, an uncorrelated design") {
  SamplingOptions options;
  options.samples = 4;
  Eigen::MatrixXd s = Eigen::MatrixXd::Identity(4, 4);
  s(0, 1) = s(1, 0) = 0.5;
  const ImanConoverTarget target = make_iman_conover_target(s, {"k", "h", "d", "d0"}, "test");
  const LineDesign design = latin_hypercube_design("wild_type", wild_type_variables(), options, &target);
  CHECK_FALSE(design.correlation.imposed);
  REQUIRE(design.warnings.size() == 1);
  CHECK(design.warnings[0].find("cannot be imposed on 4 samples") != std::string::npos);
}

TEST_CASE("a correlated design is Iman-Conover on its columns' permutations, rows in variable 0's stratum order") {
  // The fused design (line_design.cpp) against the documented steps done one by one: each
  // column's Latin hypercube (latin_hypercube_column), the score rows held in the order of
  // variable 0's strata (row r = the sample holding stratum r of variable 0), the public
  // iman_conover on those rows, and each value looked up from its final stratum. Exact equality:
  // both sum the same products in the same order.
  Eigen::MatrixXd s(4, 4);
  s << 1, 0.25, 0.55, 0.3, 0.25, 1, -0.1, 0.05, 0.55, -0.1, 1, 0.7, 0.3, 0.05, 0.7, 1;
  const ImanConoverTarget target = make_iman_conover_target(s, {"k", "h", "d", "d0"}, "test");
  const auto variables = wild_type_variables();
  for (const std::size_t n : {std::size_t{50}, std::size_t{1000}, std::size_t{4099}, std::size_t{100003}}) {
    CAPTURE(n);
    SamplingOptions options;
    options.samples = n;
    options.seed = 31;
    const LineDesign design = latin_hypercube_design("wild_type", variables, options, &target);
    REQUIRE(design.correlation.imposed);
    std::vector<LatinColumn> columns;
    std::vector<std::vector<std::uint32_t>> sample_of_stratum;
    for (const DesignVariable& variable : variables) {
      columns.push_back(latin_hypercube_column(n, stream_key(31, "wild_type", variable.name), StratumPosition::random));
      sample_of_stratum.emplace_back(n);
      for (std::size_t i = 0; i < n; ++i) sample_of_stratum.back()[columns.back().stratum[i]] = static_cast<std::uint32_t>(i);
    }
    // Row r: variable 0 in stratum r, variable j >= 1 in stratum sample_of_stratum[j][r] (its
    // shuffle applied to the rows).
    std::vector<std::vector<std::uint32_t>> rows(4, std::vector<std::uint32_t>(n));
    for (std::size_t r = 0; r < n; ++r) {
      rows[0][r] = static_cast<std::uint32_t>(r);
      for (std::size_t j = 1; j < 4; ++j) rows[j][r] = sample_of_stratum[j][r];
    }
    REQUIRE(iman_conover(rows, target.normal_correlation).imposed);
    for (std::size_t j = 0; j < 4; ++j) {
      for (std::size_t r = 0; r < n; ++r) {
        const std::uint32_t sample = sample_of_stratum[0][r];
        REQUIRE(design.ranks[j][sample] == rows[j][r]);
        REQUIRE(design.values[j][sample] == quantile(variables[j].distribution, columns[j].u_by_stratum[rows[j][r]]));
      }
    }
  }
}

TEST_CASE("columns computed on two threads, in any order, are the design computed in order") {
  // compute_column depends only on the designer's preparation: a column is the same whichever
  // thread computes it and whatever was computed before (the campaign designs lines on several
  // processes and some columns alone).
  Eigen::MatrixXd s(4, 4);
  s << 1, 0.25, 0.55, 0.3, 0.25, 1, -0.1, 0.05, 0.55, -0.1, 1, 0.7, 0.3, 0.05, 0.7, 1;
  const ImanConoverTarget target = make_iman_conover_target(s, {"k", "h", "d", "d0"}, "test");
  SamplingOptions options;
  options.samples = 20011;
  options.seed = 5;
  const LineDesign in_order = latin_hypercube_design("wild_type", wild_type_variables(), options, &target);
  REQUIRE(in_order.correlation.imposed);
  const LineDesigner designer("wild_type", wild_type_variables(), options, &target);
  std::vector<LargeVector<std::uint32_t>> ranks(4);
  std::vector<LargeVector<double>> values(4);
  std::thread second([&] {
    for (const std::size_t j : {3, 1}) designer.compute_column(j, ranks[j], values[j]);
  });
  for (const std::size_t j : {2, 0}) designer.compute_column(j, ranks[j], values[j]);
  second.join();
  for (std::size_t j = 0; j < 4; ++j) {
    CAPTURE(j);
    CHECK(ranks[j] == in_order.ranks[j]);
    CHECK(values[j] == in_order.values[j]);
  }
}
