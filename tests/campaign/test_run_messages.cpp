// The messages of a campaign run (a column's statistics, a process's batch of them, a design's
// outline, an evaluated chunk, a coordinator's failure) read back exactly what was written.
#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "campaign/chunk_values.hpp"
#include "campaign/column_statistics.hpp"
#include "campaign/coordinator_failure.hpp"
#include "campaign/design_sharing.hpp"
#include "growthuq/core/error.hpp"

using namespace growthuq;

namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

ColumnStatistics example(std::size_t ranks, bool with_summary) {
  ColumnStatistics statistics;
  statistics.analysis.verdict = ColumnAnalysis::Verdict::constant;
  statistics.analysis.moments = {7, 0.1 + 0.2, 1.0 / 3.0};
  for (std::size_t i = 0; i < ranks; ++i) statistics.analysis.twice_ranks.push_back(static_cast<std::uint32_t>(4'000'000'000u - 3 * i));
  if (with_summary) {
    QuantitySummary s;
    s.n = 123456789;
    s.n_flagged = 3;
    s.median = 0.1;
    s.q1 = -0.0;
    s.q3 = 5e-324;  // subnormal
    s.iqr = std::numeric_limits<double>::max();
    s.p10 = -1.5;
    s.p90 = 2.5;
    s.mean = std::nextafter(1.0, 2.0);
    s.sd = not_a_number;  // n = 1 gives NaN
    s.median_ci_low = -std::numeric_limits<double>::infinity();
    s.median_ci_high = 1e300;
    statistics.summary = s;
  }
  return statistics;
}

void check_same(const ColumnStatistics& a, const ColumnStatistics& b) {
  CHECK(a.analysis.verdict == b.analysis.verdict);
  CHECK(a.analysis.moments.count == b.analysis.moments.count);
  CHECK(same_bits(a.analysis.moments.mean, b.analysis.moments.mean));
  CHECK(same_bits(a.analysis.moments.squared_deviations, b.analysis.moments.squared_deviations));
  CHECK(std::vector<std::uint32_t>(a.analysis.twice_ranks.begin(), a.analysis.twice_ranks.end()) ==
        std::vector<std::uint32_t>(b.analysis.twice_ranks.begin(), b.analysis.twice_ranks.end()));
  REQUIRE(a.summary.has_value() == b.summary.has_value());
  if (!a.summary) return;
  const QuantitySummary& s = *a.summary;
  const QuantitySummary& t = *b.summary;
  CHECK(s.n == t.n);
  CHECK(s.n_flagged == t.n_flagged);
  const double fields_a[] = {s.median, s.q1, s.q3, s.iqr, s.p10, s.p90, s.mean, s.sd, s.median_ci_low, s.median_ci_high};
  const double fields_b[] = {t.median, t.q1, t.q3, t.iqr, t.p10, t.p90, t.mean, t.sd, t.median_ci_low, t.median_ci_high};
  for (std::size_t f = 0; f < 10; ++f) CHECK(same_bits(fields_a[f], fields_b[f]));
}

}  // namespace

TEST_CASE("a column's statistics round-trip bit for bit, with and without summary, any number of ranks") {
  for (const std::size_t ranks : {0u, 1u, 2u, 5u, 1000u}) {
    for (const bool with_summary : {false, true}) {
      const ColumnStatistics original = example(ranks, with_summary);
      const std::vector<double> message = original.encode();
      CHECK(message.size() == 18 + (ranks + 1) / 2);  // two 32-bit ranks per double
      check_same(ColumnStatistics::decode(message), original);
    }
  }
  std::vector<double> message = example(5, true).encode();
  message.pop_back();
  CHECK_THROWS_AS(ColumnStatistics::decode(message), std::logic_error);
  CHECK_THROWS_AS(ColumnStatistics::decode(std::vector<double>(17, 0.0)), std::logic_error);
}

TEST_CASE("a batch of columns round-trips with its column numbers, in order") {
  ColumnStatisticsBatch batch;
  batch.columns.emplace_back(4, example(3, true));
  batch.columns.emplace_back(0, example(0, false));
  batch.columns.emplace_back(11, example(8, true));
  const ColumnStatisticsBatch read = ColumnStatisticsBatch::decode(batch.encode());
  REQUIRE(read.columns.size() == 3);
  for (std::size_t k = 0; k < 3; ++k) {
    CHECK(read.columns[k].first == batch.columns[k].first);
    check_same(read.columns[k].second, batch.columns[k].second);
  }
  CHECK(ColumnStatisticsBatch::decode(ColumnStatisticsBatch{}.encode()).columns.empty());
  std::vector<double> cut = batch.encode();
  cut.resize(cut.size() - 1);
  CHECK_THROWS_AS(ColumnStatisticsBatch::decode(cut), std::logic_error);
}

TEST_CASE("a design outline round-trips its target matrix and warnings, NUL bytes and all") {
  DesignOutline outline;
  outline.target_spearman.resize(3, 3);
  for (Eigen::Index a = 0; a < 3; ++a) {
    for (Eigen::Index b = 0; b < 3; ++b) outline.target_spearman(a, b) = a == b ? 1.0 : 0.1 * static_cast<double>(a + 2 * b) / 7.0;
  }
  outline.warnings = {"target repaired: nearest correlation matrix", "", std::string("with\0nul", 8)};
  const DesignOutline read = DesignOutline::decode(outline.encode());
  REQUIRE(read.target_spearman.rows() == 3);
  REQUIRE(read.target_spearman.cols() == 3);
  for (Eigen::Index a = 0; a < 3; ++a) {
    for (Eigen::Index b = 0; b < 3; ++b) CHECK(same_bits(read.target_spearman(a, b), outline.target_spearman(a, b)));
  }
  CHECK(read.warnings == outline.warnings);

  const DesignOutline empty = DesignOutline::decode(DesignOutline{}.encode());
  CHECK(empty.target_spearman.rows() == 0);
  CHECK(empty.warnings.empty());
  const std::string message = outline.encode();
  CHECK_THROWS_AS(DesignOutline::decode(message.substr(0, message.size() - 1)), std::logic_error);
  CHECK_THROWS_AS(DesignOutline::decode(message.substr(0, 4)), std::logic_error);
}

TEST_CASE("an evaluated chunk reads back each output's column and each sample's status") {
  SampleBlock block(4);
  const double p[] = {1e5, 2e5, not_a_number, 4e5};
  const double e[] = {-0.0, 5e-324, 7.0, 8.0};
  block.set_column("p", p);
  block.set_column("E", e);
  block.set_column("unused", p);
  block.flag(2, SampleStatus::burst);
  block.flag(3, SampleStatus::unstable_branch);
  const std::vector<double> packed = ChunkValues::pack(block, {"E", "p"});
  CHECK(packed.size() == ChunkValues::values_per_sample(2) * 4);
  const ChunkValues chunk(packed, 2);
  REQUIRE(chunk.samples() == 4);
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(same_bits(chunk.output(0)[i], e[i]));
    CHECK(same_bits(chunk.output(1)[i], p[i]));
    CHECK(chunk.status(i) == block.status()[i]);
  }
  CHECK_THROWS_AS(ChunkValues(std::span<const double>(packed).first(packed.size() - 1), 2), std::logic_error);
}

TEST_CASE("a coordinator's failure round-trips as an InputError or a plain error") {
  const FailureMessage input{true, "campaigns/quick.ini:14", "probe_radius_um = '-1': expected a radius > 0"};
  const std::optional<FailureMessage> read = FailureMessage::decode(input.encode());
  REQUIRE(read.has_value());
  CHECK(read->input_error);
  CHECK(read->location == input.location);
  CHECK(read->problem == input.problem);
  CHECK_THROWS_WITH_AS(read->raise(), "campaigns/quick.ini:14: probe_radius_um = '-1': expected a radius > 0", InputError);

  const FailureMessage other{false, "", std::string("disk full\0 and more", 18)};
  const std::optional<FailureMessage> read_other = FailureMessage::decode(other.encode());
  REQUIRE(read_other.has_value());
  CHECK_FALSE(read_other->input_error);
  CHECK(read_other->location.empty());
  CHECK(read_other->problem == other.problem);
  CHECK_THROWS_AS(read_other->raise(), std::runtime_error);
  CHECK_FALSE(FailureMessage::decode("").has_value());
}
