// The speed/accuracy trade: the table logic against hand-computed numbers (errors, error over
// the CI half-width, the smallest count meeting a target, the "no count meets it" case), and a
// statistical property of real runs (errors fall with n; the median's 95 % interval covers the
// reference median in most rows).
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/tradeoff.hpp"
#include "growthuq/campaign/tradeoff_run.hpp"
#include "growthuq/pool/pool.hpp"

using namespace growthuq;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

QuantitySummary summary(const std::string& line, double median, double iqr, double ci_low, double ci_high,
                        std::size_t n = 100, const std::string& quantity = "p") {
  QuantitySummary s;
  s.line = line;
  s.quantity = quantity;
  s.unit = "MPa";
  s.n = n;
  s.median = median;
  s.iqr = iqr;
  s.median_ci_low = ci_low;
  s.median_ci_high = ci_high;
  return s;
}

// Two lines, one quantity, three counts. All numbers are dyadic, so every error below is exact:
//   reference (1000): a: median 2, IQR 1, CI [1.875, 2.125];  b: median 4, IQR 2, CI [3.875, 4.125]
//   100: a: median 2.0625 (3.125 %), IQR 1.0625 (6.25 %), CI half-width 0.03125 -> ratio 2
//        b: median 3.75 (6.25 %), IQR 1.75 (12.5 %), CI half-width 0.25 -> ratio 1
//   10:  a: median 2.5 (25 %), IQR 1.5 (50 %), no CI (n = 5) -> ratio undefined
//        b: median 4, IQR 2 (both 0 %), CI [3, 5] -> ratio 0
std::vector<TradeoffRun> hand_runs() {
  return {
      {"closed_form", 10, 0.5, {summary("a", 2.5, 1.5, nan, nan, 5), summary("b", 4, 2, 3, 5)}},
      {"closed_form", 100, 1.5, {summary("a", 2.0625, 1.0625, 2.03125, 2.09375), summary("b", 3.75, 1.75, 3.5, 4.0)}},
      {"closed_form", 1000, 9.0, {summary("a", 2, 1, 1.875, 2.125), summary("b", 4, 2, 3.875, 4.125)}},
  };
}

// The report's paragraphs with their line breaks as spaces.
std::string unwrapped(std::string text) {
  for (char& c : text) {
    if (c == '\n') c = ' ';
  }
  return text;
}

}  // namespace

TEST_CASE("tradeoff rows: errors against the largest run and against the CI half-width, by hand") {
  const std::vector<TradeoffRun> runs = hand_runs();
  const std::vector<TradeoffRow> rows = tradeoff_rows(runs);
  REQUIRE(rows.size() == 6);
  const TradeoffRow& a10 = rows[0];
  CHECK(a10.samples == 10);
  CHECK(a10.seconds == 0.5);
  CHECK(a10.n == 5);
  CHECK(a10.reference_median == 2);
  CHECK(a10.reference_iqr == 1);
  CHECK(a10.median_error_pct == 25);
  CHECK(a10.iqr_error_pct == 50);
  CHECK(std::isnan(a10.median_error_over_ci_half_width));
  const TradeoffRow& b10 = rows[1];
  CHECK(b10.median_error_pct == 0);
  CHECK(b10.iqr_error_pct == 0);
  CHECK(b10.median_error_over_ci_half_width == 0);
  const TradeoffRow& a100 = rows[2];
  CHECK(a100.median_error_pct == 3.125);
  CHECK(a100.iqr_error_pct == 6.25);
  CHECK(a100.median_error_over_ci_half_width == 2);
  const TradeoffRow& b100 = rows[3];
  CHECK(b100.median_error_pct == 6.25);
  CHECK(b100.iqr_error_pct == 12.5);
  CHECK(b100.median_error_over_ci_half_width == 1);
  for (std::size_t r = 4; r < 6; ++r) {  // the reference against itself
    CHECK(rows[r].samples == 1000);
    CHECK(rows[r].median_error_pct == 0);
    CHECK(rows[r].iqr_error_pct == 0);
    CHECK(rows[r].median_error_over_ci_half_width == 0);
  }

  // Without a shell_fe run there is no finite-element reference: its four cells are empty.
  CHECK(std::isnan(a10.fe_reference_median));
  CHECK(std::isnan(a10.fe_median_error_pct));

  // tradeoff.csv: the fixed columns, shortest round-trip numbers, undefined cells empty.
  const std::string csv = tradeoff_csv_text(rows);
  CHECK(csv.starts_with("fidelity,samples,seconds,line,quantity,unit,n,median,iqr,median_ci_low,median_ci_high,"
                        "reference_median,reference_iqr,median_error_pct,iqr_error_pct,median_error_over_ci_half_width,"
                        "fe_reference_median,fe_reference_iqr,fe_median_error_pct,fe_iqr_error_pct\n"
                        "closed_form,10,0.5,a,p,MPa,5,2.5,1.5,,,2,1,25,50,,,,,\n"
                        "closed_form,10,0.5,b,p,MPa,100,4,2,3,5,4,2,0,0,0,,,,\n"
                        "closed_form,100,1.5,a,p,MPa,100,2.0625,1.0625,2.03125,2.09375,2,1,3.125,6.25,2,,,,\n"));
}

TEST_CASE("tradeoff rows: a zero reference has no relative error; each fidelity has its own reference") {
  const std::vector<TradeoffRun> runs{
      {"closed_form", 10, 1, {summary("a", 0, 0.5, 0, 0.25, 100, "v"), summary("b", 0.25, 1, 0, 0.5, 100, "v")}},
      {"corrected", 10, 50, {summary("a", 3, 1, 2, 4)}},
      {"corrected", 40, 200, {summary("a", 2, 1, 1.5, 2.5)}},
      {"closed_form", 100, 8, {summary("a", 0, 0.5, 0, 0.125, 100, "v"), summary("b", 0, 1, 0, 0.125, 100, "v")}},
  };
  const std::vector<TradeoffRow> rows = tradeoff_rows(runs);
  REQUIRE(rows.size() == 6);
  CHECK(rows[0].median_error_pct == 0);               // 0 against 0: equal
  CHECK(rows[0].median_error_over_ci_half_width == 0);
  CHECK(std::isnan(rows[1].median_error_pct));         // 0.25 against 0: undefined
  CHECK(rows[1].median_error_over_ci_half_width == 1);  // 0.25 / 0.25 is still defined
  CHECK(rows[2].reference_median == 2);                 // corrected against the largest corrected run
  CHECK(rows[2].median_error_pct == 50);
  CHECK(rows[2].median_error_over_ci_half_width == 1);

  // An undefined error never meets a target, and it is the worst of its count.
  const TradeoffVerdict verdict = judge_tradeoff(rows, "closed_form", 50);
  REQUIRE(verdict.counts.size() == 2);
  CHECK_FALSE(verdict.counts[0].meets_target);
  CHECK(std::isnan(verdict.counts[0].median_error_pct.value));
  CHECK(verdict.counts[0].median_error_pct.line == "b");
  CHECK_FALSE(verdict.smallest_meeting_target.has_value());
  CHECK(verdict.remaining_statistic == "median");
  CHECK(verdict.estimated_samples_needed == 0);
  // The reference's medians are 0: its relative CI half-width is undefined, hence not precise.
  CHECK(std::isnan(verdict.reference_ci_half_width_pct.value));
  CHECK_FALSE(verdict.reference_precise_enough);
  CHECK_THROWS_AS(judge_tradeoff(rows, "other", 1), std::invalid_argument);
}

TEST_CASE("tradeoff verdict: worst errors per count, the smallest count meeting a target, and none") {
  const std::vector<TradeoffRow> rows = tradeoff_rows(hand_runs());

  const TradeoffVerdict tight = judge_tradeoff(rows, "closed_form", 10);
  REQUIRE(tight.counts.size() == 3);
  CHECK(tight.reference_samples == 1000);
  const TradeoffCount& at100 = tight.counts[1];
  CHECK(at100.samples == 100);
  CHECK(at100.seconds == 1.5);
  CHECK(at100.median_error_pct.value == 6.25);
  CHECK(at100.median_error_pct.line == "b");
  CHECK(at100.iqr_error_pct.value == 12.5);
  CHECK(at100.iqr_error_pct.line == "b");
  CHECK(at100.median_error_over_ci_half_width.value == 2);
  CHECK(at100.median_error_over_ci_half_width.line == "a");
  CHECK(std::isnan(tight.counts[0].median_error_over_ci_half_width.value));  // a at 10 has no CI
  CHECK(tight.counts[0].median_error_pct.value == 25);
  // 10 %: the IQR of b at 100 (12.5 %) fails, so no count meets it. 1/sqrt(n) scaling:
  // 100 x (12.5 / 10)^2 = 156.25 samples, rounded up to 200.
  CHECK_FALSE(tight.smallest_meeting_target.has_value());
  CHECK(tight.remaining_statistic == "IQR");
  CHECK(tight.remaining_error_pct.value == 12.5);
  CHECK(tight.remaining_error_pct.line == "b");
  CHECK(tight.estimated_samples_needed == 200);
  // The reference's worst CI half-width: a, 0.125 / 2 = 6.25 % (b: 0.125 / 4 = 3.125 %), more
  // than a quarter of 10 %.
  CHECK(tight.reference_ci_half_width_pct.value == 6.25);
  CHECK(tight.reference_ci_half_width_pct.line == "a");
  CHECK_FALSE(tight.reference_precise_enough);

  const TradeoffVerdict middle = judge_tradeoff(rows, "closed_form", 15);
  CHECK(middle.smallest_meeting_target == std::optional<std::size_t>(100));  // 10 fails (25 %, 50 %)
  CHECK_FALSE(middle.counts[0].meets_target);
  CHECK(middle.counts[1].meets_target);
  CHECK_FALSE(middle.reference_precise_enough);  // 6.25 > 15 / 4

  const TradeoffVerdict loose = judge_tradeoff(rows, "closed_form", 60);
  CHECK(loose.smallest_meeting_target == std::optional<std::size_t>(10));
  CHECK(loose.reference_precise_enough);  // 6.25 <= 60 / 4

  // The limit is strict: an error equal to the target does not meet it.
  CHECK(judge_tradeoff(rows, "closed_form", 12.5).smallest_meeting_target == std::nullopt);

  // A small count that passes by chance while a larger one fails is not offered.
  const std::vector<TradeoffRun> lucky{
      {"closed_form", 10, 1, {summary("a", 1.015625, 1, 0.5, 1.5)}},
      {"closed_form", 100, 2, {summary("a", 1.0625, 1, 0.75, 1.25)}},
      {"closed_form", 1000, 3, {summary("a", 1, 1, 0.9375, 1.0625)}},
  };
  const TradeoffVerdict by_chance = judge_tradeoff(tradeoff_rows(lucky), "closed_form", 5);
  CHECK(by_chance.counts[0].meets_target);
  CHECK_FALSE(by_chance.counts[1].meets_target);
  CHECK_FALSE(by_chance.smallest_meeting_target.has_value());
  CHECK(by_chance.remaining_error_pct.value == 6.25);
  CHECK(by_chance.estimated_samples_needed == 200);  // 100 x 1.25^2 = 156.25

  // The report names the answer; its numbers are those above.
  const std::string report = unwrapped(format_tradeoff_report(middle));
  CHECK(report.find("target 15 %: 100 samples per line.") != std::string::npos);
  CHECK(report.find("12.5 % (b p)") != std::string::npos);
  CHECK(unwrapped(format_tradeoff_report(tight)).find("about 200 samples per line") != std::string::npos);
}

TEST_CASE("tradeoff of a real campaign: errors fall with n and the median's 95 % interval covers the reference") {
  // campaigns/quick.ini: five lines x its outputs (p, E, eta, v, v_exp). Counts up to 1e5 (the
  // reference).
  const Campaign campaign = read_campaign(std::string(GROWTHUQ_SOURCE_DIR) + "/campaigns/quick.ini");
  const std::size_t rows_per_run = campaign.lines.size() * campaign.outputs.size();
  const std::vector<std::size_t> counts{100, 1000, 10000, 100000};
  const std::unique_ptr<Pool> pool = make_serial_pool();
  std::ostringstream log;
  const std::vector<TradeoffRun> runs = run_tradeoff(campaign, counts, *pool, ProgressMode::none, log);
  CHECK(log.str().empty());  // no progress, no design warnings at these counts
  REQUIRE(runs.size() == counts.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    CHECK(runs[i].fidelity == "closed_form");
    CHECK(runs[i].samples == counts[i]);
    CHECK(runs[i].seconds > 0);
    REQUIRE(runs[i].summaries.size() == rows_per_run);
  }
  const std::vector<TradeoffRow> rows = tradeoff_rows(runs);
  const TradeoffVerdict verdict = judge_tradeoff(rows, "closed_form", 1);
  // The worst median and IQR errors fall from 100 to 1e4 samples (not necessarily at every
  // step: each count is an independent design).
  CHECK(verdict.counts[2].median_error_pct.value < verdict.counts[0].median_error_pct.value);
  CHECK(verdict.counts[2].iqr_error_pct.value < verdict.counts[0].iqr_error_pct.value);

  // The distribution-free interval has coverage >= 95 % for independent samples, and a Latin
  // hypercube estimates a median at least as well as independent sampling, so the interval should
  // contain the true median in about 95 % or more of the rows; the 1e5 run's median stands in for
  // the truth, and it is itself off by about a third of a 1e4 run's half-width. 80 % leaves room
  // for both and for the rows not being independent (the quantities of one line share samples).
  std::size_t covered = 0, total = 0;
  for (const TradeoffRow& row : rows) {
    if (row.samples > 10000) continue;
    ++total;
    if (row.median_ci_low <= row.reference_median && row.reference_median <= row.median_ci_high) ++covered;
  }
  REQUIRE(total == 3 * rows_per_run);
  const double coverage = static_cast<double>(covered) / static_cast<double>(total);
  MESSAGE("95 % intervals of the median containing the 1e5-sample median: " << covered << " of " << total);
  CHECK(coverage >= 0.8);
}
