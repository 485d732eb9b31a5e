// `growthuq run` end to end through the built CLI: the files it writes, their columns, summary
// numbers recomputed from samples.csv, kappa calibration, a turgor-only campaign without wall
// thickness, and the errors a user meets (bad campaign, existing output directory).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/pool/pool.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::string data_dir = std::string(GROWTHUQ_SOURCE_DIR) + "/tests/campaign/data";

std::size_t count_lines(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

// Type-7 quantile (numpy's default), written out here independently of the engine's.
double quantile7(const std::vector<double>& sorted, double p) {
  const double h = static_cast<double>(sorted.size() - 1) * p;
  const auto low = static_cast<std::size_t>(std::floor(h));
  const std::size_t high = std::min(low + 1, sorted.size() - 1);
  return sorted[low] + (h - static_cast<double>(low)) * (sorted[high] - sorted[low]);
}

// 1-based rank `lower` of the distribution-free 95 % interval [X(l), X(n+1-l)] of the median:
// the largest l with 1 - 2 P(B <= l - 1) >= 0.95, B ~ binomial(n, 1/2) (Conover 1999, 3.2).
std::size_t median_ci_lower_rank(std::size_t n) {
  std::size_t lower = 1;
  double below = 0;  // P(B <= l - 1)
  for (std::size_t l = 1; l <= n / 2; ++l) {
    below += std::exp(std::lgamma(static_cast<double>(n) + 1) - std::lgamma(static_cast<double>(l)) -
                      std::lgamma(static_cast<double>(n - l + 2)) - static_cast<double>(n) * std::log(2.0));
    if (1 - 2 * below >= 0.95) lower = l;
    else break;
  }
  return lower;
}

double relative_difference(double a, double b) { return a == b ? 0.0 : std::abs(a - b) / std::max(std::abs(a), std::abs(b)); }

}  // namespace

TEST_CASE("a small campaign end to end: files, columns, summaries from samples.csv, kappa") {
  const ScratchDirectory scratch("run_small");
  const fs::path out = scratch.root / "results";
  const CliOutcome run = run_cli("run " + data_dir + "/small_campaign.ini --out " + out.string() + " --formats csv,hdf5", scratch.root);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(fs::is_regular_file(out / "samples.csv"));
  CHECK(fs::is_regular_file(out / "summary.csv"));
  CHECK(fs::is_regular_file(out / "results.h5"));
  CHECK_FALSE(fs::exists(out / "samples.csv.partial"));
  // stderr is a file here: one progress line per plant line, reference line first.
  CHECK(run.err.starts_with("wild_type: 200 samples in "));
  CHECK(run.err.find("\npme48: 200 samples in ") != std::string::npos);
  CHECK(run.out.find("kappa = ") != std::string::npos);

  const std::string samples_text = slurp(out / "samples.csv");
  const std::string summary_text = slurp(out / "summary.csv");
  CHECK(samples_text.find("nan") == std::string::npos);
  CHECK(summary_text.find("nan") == std::string::npos);

  const CsvTable samples = read_csv((out / "samples.csv").string());
  CHECK(samples.header == std::vector<std::string>{"line", "sample", "k_N_per_m", "h_nm", "d_um", "d0_um", "tau_s", "einf_pct",
                                                   "p_MPa", "E_MPa", "eta_MPa_s", "v_um_per_s", "status"});
  REQUIRE(samples.rows.size() == 400);
  CHECK(samples.rows.front()[0] == "wild_type");  // the reference line runs first
  CHECK(samples.rows.back()[0] == "pme48");
  CHECK(samples.rows[199][1] == "199");

  // Per line and quantity: the values that count, those computed: every output of an ok sample,
  // and of a no_growth sample p, E and eta (computed before the growth model flagged it) and v = 0.
  const std::vector<std::string> quantities{"p", "E", "eta", "v"};
  std::map<std::string, std::map<std::string, std::vector<double>>> counted;
  std::map<std::string, std::size_t> flagged_v;
  std::map<std::string, std::size_t> no_growth;
  std::vector<double> wild_type_growing_v;
  for (std::size_t r = 0; r < samples.rows.size(); ++r) {
    const auto& row = samples.rows[r];
    const std::string& line = row[0];
    const std::string& status = row[12];
    const auto cell = [&](std::size_t c) { return std::stod(row[c]); };
    // Every row's outputs follow from the same row's inputs (chunks were placed where they
    // belong): eta = tau (1 - e_inf) E [Eq. (G1)] and v / (p d^2 / (4 eta h)) = kappa
    // [sec. 6], the same for every growing tube.
    if (status == "ok") {
      const double eta = cell(6) * (1 - cell(7) / 100) * cell(9);  // s x MPa = MPa s
      CHECK(relative_difference(cell(10), eta) < 1e-13);
      counted[line]["v"].push_back(cell(11));
      if (line == "wild_type") wild_type_growing_v.push_back(cell(11));
      for (std::size_t q = 0; q < 3; ++q) counted[line][quantities[q]].push_back(cell(8 + q));
    } else if (status == "no_growth") {
      CHECK(row[11] == "0");
      CHECK(cell(8) <= 0.15);
      CHECK(relative_difference(cell(10), cell(6) * (1 - cell(7) / 100) * cell(9)) < 1e-13);
      counted[line]["v"].push_back(0.0);
      for (std::size_t q = 0; q < 3; ++q) counted[line][quantities[q]].push_back(cell(8 + q));
      ++no_growth[line];
    } else {
      CHECK(row[11].empty());
      ++flagged_v[line];
    }
  }
  CHECK(no_growth["wild_type"] + no_growth["pme48"] > 0);  // the yield pressure is exercised

  // kappa = v / (4^-1 (p - p0) d^2 / (eta h)) in consistent units, one value for both lines.
  std::vector<double> kappas;
  for (const auto& row : samples.rows) {
    if (row[12] != "ok") continue;
    const double p = (std::stod(row[8]) - 0.15) * 1e6, d = std::stod(row[4]) * 1e-6, h = std::stod(row[3]) * 1e-9;
    const double eta = std::stod(row[10]) * 1e6, v = std::stod(row[11]) * 1e-6;
    kappas.push_back(v / (p * d * d / (4 * eta * h)));
  }
  REQUIRE_FALSE(kappas.empty());
  for (const double kappa : kappas) CHECK(relative_difference(kappa, kappas.front()) < 1e-12);
  // The reference line's predicted median growth rate (growing tubes) equals the median of its
  // v_exp law, 0.028 um/s in distributions/wild_type.ini; a few ulps of rounding allowed.
  std::sort(wild_type_growing_v.begin(), wild_type_growing_v.end());
  CHECK(relative_difference(quantile7(wild_type_growing_v, 0.5), 0.028) < 1e-12);

  const CsvTable summary = read_csv((out / "summary.csv").string());
  CHECK(summary.header == std::vector<std::string>{"line", "quantity", "unit", "n", "n_flagged", "median", "q1", "q3", "iqr",
                                                   "p10", "p90", "mean", "sd", "median_ci_low", "median_ci_high",
                                                   "data_ci_low", "data_ci_high"});
  // No line is given by raw data: no bootstrap, empty data intervals, and the report says that
  // its intervals are Monte Carlo only.
  CHECK(run.out.find("note: the intervals are Monte Carlo only (no line is given by raw data") != std::string::npos);
  CHECK(run.out.find("data 95 % interval") == std::string::npos);
  // kappa's Monte Carlo error (Eq. (G5b), src/growth/README.md), recomputed from samples.csv: the
  // reference line's growing rates give P and its order-statistic 95 % CI [P_lo, P_hi] (kappa
  // scales them all alike, so the ratios are kappa's relative interval).
  const std::size_t growing = wild_type_growing_v.size();
  const std::size_t kappa_rank = median_ci_lower_rank(growing);
  const double reference_median = quantile7(wild_type_growing_v, 0.5);
  const double kappa_below = std::log(wild_type_growing_v[growing - kappa_rank] / reference_median);  // ln(P_hi / P)
  const double kappa_above = std::log(reference_median / wild_type_growing_v[kappa_rank - 1]);        // ln(P / P_lo)
  REQUIRE(kappa_below > 0.005);  // large enough to show in the widened interval
  REQUIRE(kappa_above > 0.005);
  REQUIRE(summary.rows.size() == 8);
  for (std::size_t r = 0; r < summary.rows.size(); ++r) {
    const auto& row = summary.rows[r];
    const std::string line = row[0];
    const std::string quantity = row[1];
    INFO(line << " " << quantity);
    CHECK(line == (r < 4 ? "wild_type" : "pme48"));
    CHECK(quantity == quantities[r % 4]);
    std::vector<double> values = counted[line][quantity];
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    REQUIRE(n > 10);
    CHECK(std::stoul(row[3]) == n);
    CHECK(std::stoul(row[4]) == 200 - n);
    // Same order statistics, same interpolation: agreement to rounding (the CSV holds
    // shortest round-trip doubles, so only the arithmetic order can differ).
    const auto column = [&](std::size_t c) { return std::stod(row[c]); };
    CHECK(relative_difference(column(5), quantile7(values, 0.5)) < 1e-14);
    CHECK(relative_difference(column(6), quantile7(values, 0.25)) < 1e-14);
    CHECK(relative_difference(column(7), quantile7(values, 0.75)) < 1e-14);
    CHECK(relative_difference(column(8), quantile7(values, 0.75) - quantile7(values, 0.25)) < 1e-12);
    CHECK(relative_difference(column(9), quantile7(values, 0.1)) < 1e-14);
    CHECK(relative_difference(column(10), quantile7(values, 0.9)) < 1e-14);
    double mean = 0;
    for (const double value : values) mean += value / static_cast<double>(n);
    double squares = 0;
    for (const double value : values) squares += (value - mean) * (value - mean);
    CHECK(relative_difference(column(11), mean) < 1e-12);
    CHECK(relative_difference(column(12), std::sqrt(squares / static_cast<double>(n - 1))) < 1e-10);
    const std::size_t lower = median_ci_lower_rank(n);
    CHECK(row[15].empty());
    CHECK(row[16].empty());
    if (line == "pme48" && quantity == "v") {
      // Another line's v: its own order-statistic interval widened by kappa's, in quadrature on the log scale.
      const double median = quantile7(values, 0.5);
      CHECK(relative_difference(column(13), median * std::exp(-std::hypot(std::log(median / values[lower - 1]), kappa_below))) < 1e-12);
      CHECK(relative_difference(column(14), median * std::exp(std::hypot(std::log(values[n - lower] / median), kappa_above))) < 1e-12);
      CHECK(column(13) < values[lower - 1]);
      CHECK(column(14) > values[n - lower]);
      continue;
    }
    CHECK(column(13) == values[lower - 1]);
    CHECK(column(14) == values[n - lower]);
  }
}

TEST_CASE("a turgor-only campaign runs on a line without thickness or relaxation data") {
  const ScratchDirectory scratch("run_turgor");
  const fs::path out = scratch.root / "results";
  const CliOutcome run = run_cli("run " + data_dir + "/turgor_campaign.ini --quiet --out " + out.string(), scratch.root);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.empty());  // --quiet: no progress
  const CsvTable samples = read_csv((out / "samples.csv").string());
  CHECK(samples.header == std::vector<std::string>{"line", "sample", "k_N_per_m", "d_um", "d0_um", "p_MPa", "status"});
  CHECK(samples.rows.size() == 150);
  CHECK_FALSE(fs::exists(out / "results.h5"));  // formats = csv
  const CsvTable summary = read_csv((out / "summary.csv").string());
  REQUIRE(summary.rows.size() == 1);
  CHECK(summary.rows[0][1] == "p");
  CHECK(summary.rows[0][2] == "MPa");

  // The library plans one model, samples three variables and keeps their physics correlation.
  Campaign campaign = read_campaign(data_dir + "/turgor_campaign.ini");
  const PreparedCampaign prepared(std::move(campaign));
  REQUIRE(prepared.lines().size() == 1);
  const PreparedLine& line = prepared.lines()[0];
  CHECK(line.plan.size() == 1);
  CHECK(line.plan[0]->name() == "thin_shell_turgor");
  REQUIRE(line.correlation.has_value());
  CHECK(line.correlation->names == std::vector<std::string>{"k", "d", "d0"});
  CHECK_FALSE(prepared.calibrates_kappa());
}

TEST_CASE("a bad campaign is one line on stderr and exit code 2, before any output exists") {
  const ScratchDirectory scratch("run_bad");
  const fs::path campaign = scratch.root / "bad.ini";
  std::string text = slurp(data_dir + "/small_campaign.ini");
  text.replace(text.find("samples = 200"), 13, "samples = many");
  text.replace(text.find("../../../distributions"), 22, std::string(GROWTHUQ_SOURCE_DIR) + "/distributions");
  text.replace(text.find("../../../distributions"), 22, std::string(GROWTHUQ_SOURCE_DIR) + "/distributions");
  std::ofstream(campaign) << text;
  const fs::path out = scratch.root / "results";
  CliOutcome run = run_cli("run " + campaign.string() + " --out " + out.string(), scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err == "growthuq run: error: " + campaign.string() + ":6: samples = 'many': expected a whole number from 1 to 4294967295\n");
  CHECK_FALSE(fs::exists(out));

  run = run_cli("run " + data_dir + "/small_campaign.ini --samples 0 --out " + out.string(), scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(count_lines(run.err) == 1);
  CHECK(run.err.find("--samples = '0'") != std::string::npos);

  run = run_cli("run " + data_dir + "/small_campaign.ini --lines pme48 --out " + out.string(), scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(count_lines(run.err) == 1);
  CHECK(run.err.find("keeps the reference line 'wild_type'") != std::string::npos);

  // A reference line whose models lack inputs is named with what it lacks.
  std::string lacking = slurp(data_dir + "/small_campaign.ini");
  lacking.replace(lacking.find("reference_line = wild_type"), 26, "reference_line = turgor_line");
  lacking += "[line turgor_line]\ndistributions = " + data_dir + "/turgor_line.ini\n";
  for (int i = 0; i < 2; ++i) lacking.replace(lacking.find("../../../distributions"), 22, std::string(GROWTHUQ_SOURCE_DIR) + "/distributions");
  std::ofstream(campaign) << lacking;
  run = run_cli("run " + campaign.string() + " --out " + out.string(), scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(count_lines(run.err) == 1);
  CHECK(run.err.find(campaign.string() + ":30: line 'turgor_line'") != std::string::npos);

  // The reference line must have an experimental growth rate: its median calibrates kappa.
  const std::string wild_type = slurp(std::string(GROWTHUQ_SOURCE_DIR) + "/distributions/wild_type.ini");
  const fs::path no_v_exp = scratch.root / "no_v_exp.ini";
  std::ofstream(no_v_exp) << wild_type.substr(0, wild_type.find("[v_exp]"));
  std::string reference = slurp(data_dir + "/small_campaign.ini");
  reference.replace(reference.find("../../../distributions/wild_type.ini"), 36, no_v_exp.string());
  reference.replace(reference.find("../../../distributions"), 22, std::string(GROWTHUQ_SOURCE_DIR) + "/distributions");
  std::ofstream(campaign) << reference;
  run = run_cli("run " + campaign.string() + " --out " + out.string(), scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err == "growthuq run: error: " + campaign.string() + ": [growth] reference_line = 'wild_type': expected a line whose "
                   "distribution file (" + no_v_exp.string() + ") has a [v_exp] section: its median calibrates kappa\n");
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("a run that cannot calibrate kappa stops with one error and leaves no output directory") {
  const ScratchDirectory scratch("run_kappa");
  // A yield pressure of 5 MPa is above every sampled turgor: no reference tube grows.
  std::string text = slurp(data_dir + "/small_campaign.ini");
  text.replace(text.find("yield_pressure_MPa = 0.15"), 25, "yield_pressure_MPa = 5");
  for (int i = 0; i < 2; ++i) text.replace(text.find("../../../distributions"), 22, std::string(GROWTHUQ_SOURCE_DIR) + "/distributions");
  const fs::path campaign = scratch.root / "kappa.ini";
  std::ofstream(campaign) << text;
  const fs::path out = scratch.root / "results";
  const CliOutcome run = run_cli("run " + campaign.string() + " --quiet --formats csv,hdf5 --out " + out.string(), scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err.starts_with("growthuq run: error: reference line 'wild_type': predicted median growth rate (kappa = 1) = 'nan'"));
  CHECK(count_lines(run.err) == 1);
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("an existing output directory is refused without --force and replaced with it") {
  const ScratchDirectory scratch("run_exists");
  const fs::path out = scratch.root / "results";
  fs::create_directories(out);
  std::ofstream(out / "results.h5") << "stale";
  CliOutcome run = run_cli("run " + data_dir + "/turgor_campaign.ini --quiet --out " + out.string(), scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err == "growthuq run: error: " + out.string() +
                       ": output directory already exists; choose another (--out DIR) or pass --force to replace its results\n");
  CHECK_FALSE(fs::exists(out / "summary.csv"));
  run = run_cli("run " + data_dir + "/turgor_campaign.ini --quiet --force --out " + out.string(), scratch.root);
  CHECK(run.exit_code == 0);
  CHECK(fs::is_regular_file(out / "summary.csv"));
  CHECK_FALSE(fs::exists(out / "results.h5"));  // a stale result of a format not written is removed
}

TEST_CASE("physics correlation seeds differ per line and follow the documented scheme") {
  CHECK(physics_correlation_seed(11, "wild_type") != physics_correlation_seed(11, "pme48"));
  CHECK(physics_correlation_seed(11, "wild_type") != physics_correlation_seed(12, "wild_type"));
}

TEST_CASE("the statistics the processes compute column by column equal those of the whole result in one place") {
  // run_campaign_lines shares the statistics out by column (inputs ranked by their design
  // strata, outputs sorted, summaries from the same sort); line_statistics computes them from
  // the assembled LineResult alone (summarize_quantity, analyze_line). The small campaign has
  // no_growth samples (v = 0, p, E and eta computed), so their summaries take summarize_quantity's own path.
  Campaign campaign = read_campaign(data_dir + "/small_campaign.ini");
  campaign.samples = 3000;
  const PreparedCampaign prepared(std::move(campaign));

  struct Checker final : RunObserver {
    const std::vector<std::string>* outputs = nullptr;
    int lines = 0;
    void line_started(const PreparedLine&, std::size_t) override {}
    void chunk_done(ChunkRange) override {}
    void line_done(const LineResult&, const std::vector<std::string>&) override { FAIL("line_analyzed is what the run calls"); }
    void line_analyzed(LineResult&& result, LineStatistics&& statistics, const std::vector<std::string>&) override {
      ++lines;
      const LineStatistics expected = line_statistics(result, *outputs);
      REQUIRE(statistics.summaries.size() == expected.summaries.size());
      const auto same = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
      for (std::size_t s = 0; s < expected.summaries.size(); ++s) {
        const QuantitySummary& got = statistics.summaries[s];
        const QuantitySummary& want = expected.summaries[s];
        CAPTURE(want.quantity);
        CHECK(got.line == want.line);
        CHECK(got.quantity == want.quantity);
        CHECK(got.unit == want.unit);
        CHECK(got.n == want.n);
        CHECK(got.n_flagged == want.n_flagged);
        for (const auto member : {&QuantitySummary::median, &QuantitySummary::q1, &QuantitySummary::q3, &QuantitySummary::iqr,
                                  &QuantitySummary::p10, &QuantitySummary::p90, &QuantitySummary::mean, &QuantitySummary::sd,
                                  &QuantitySummary::median_ci_low, &QuantitySummary::median_ci_high}) {
          // Another line's v interval holds kappa's Monte Carlo error as well (Eq. (G5b)).
          const bool widened = want.quantity == "v" && want.line != "wild_type" &&
                               (member == &QuantitySummary::median_ci_low || member == &QuantitySummary::median_ci_high);
          if (widened) continue;
          CHECK(same(got.*member, want.*member));
        }
        if (want.quantity == "v" && want.line != "wild_type") {
          CHECK(got.median_ci_low < want.median_ci_low);
          CHECK(got.median_ci_high > want.median_ci_high);
        }
      }
      const LineAnalysis& got = statistics.analysis;
      const LineAnalysis& want = expected.analysis;
      CHECK(got.inputs == want.inputs);
      CHECK(got.outputs == want.outputs);
      CHECK(got.notes == want.notes);
      CHECK(got.samples_used == want.samples_used);
      CHECK(got.input_output_spearman == want.input_output_spearman);
      CHECK(got.explained_variance_ratio == want.explained_variance_ratio);
      CHECK(got.loadings == want.loadings);
    }
  } checker;
  checker.outputs = &prepared.campaign().outputs;
  const std::unique_ptr<Pool> pool = make_serial_pool();
  run_campaign_lines(prepared, *pool, checker);
  CHECK(checker.lines == 2);
}

TEST_CASE("another line's Monte Carlo CI of v holds kappa's error as the spread over seeds does") {
  // The independent reference: 150 seeds, each a new campaign (new samples of both lines, so a
  // new kappa). Over them, pme48's median v = kappa Q spreads as ln kappa and ln Q together; the
  // delta method of Eq. (G5b) assumes the two independent, so their variances add. The order-
  // statistic CI assumes independent samples and is conservative for a Latin hypercube (its
  // strata pin the median better), so a CI is judged by its ratio to the spread of what it
  // measures: the line's own CI is that much wider than the spread of ln Q, and the widened
  // CI must be at least as wide, relative to the spread of ln v; the own CI alone falls short of it.
  std::string text = slurp(fs::path(data_dir) / "small_campaign.ini");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
  };
  replace("samples = 200", "samples = 400");
  replace("yield_pressure_MPa = 0.15", "yield_pressure_MPa = 0");  // every tube grows: v > 0, logs defined
  replace("rank_correlation = physics", "rank_correlation = none");
  replace("rank_correlation = physics", "rank_correlation = none");

  struct Medians final : RunObserver {
    QuantitySummary widened;
    QuantitySummary own;  // the line's own order-statistic interval, without kappa's error
    void line_started(const PreparedLine&, std::size_t) override {}
    void chunk_done(ChunkRange) override {}
    void line_done(const LineResult&, const std::vector<std::string>&) override {}
    void line_analyzed(LineResult&& result, LineStatistics&& statistics, const std::vector<std::string>&) override {
      if (result.name != "pme48") return;
      for (const QuantitySummary& summary : statistics.summaries) {
        if (summary.quantity == "v") widened = summary;
      }
      own = line_statistics(result, {"v"}).summaries.front();
    }
  };
  const std::unique_ptr<Pool> pool = make_serial_pool();
  std::vector<double> log_v, log_kappa, log_q;
  double widened_sd = 0, own_sd = 0;  // means over seeds of the implied standard deviations (log half-width / 1.96)
  const int seeds = 150;
  for (int seed = 1; seed <= seeds; ++seed) {
    std::string seeded = text;
    seeded.replace(seeded.find("seed = 11"), 9, "seed = " + std::to_string(seed));
    const PreparedCampaign prepared(parse_campaign(seeded, data_dir + "/seed_spread.ini"));
    Medians medians;
    const RunOutcome outcome = run_campaign_lines(prepared, *pool, medians);
    REQUIRE(medians.widened.median > 0);
    REQUIRE(medians.widened.median == medians.own.median);
    log_v.push_back(std::log(medians.widened.median));
    log_kappa.push_back(std::log(outcome.kappa));
    log_q.push_back(log_v.back() - log_kappa.back());
    widened_sd += std::log(medians.widened.median_ci_high / medians.widened.median_ci_low) / (2 * 1.96) / seeds;
    own_sd += std::log(medians.own.median_ci_high / medians.own.median_ci_low) / (2 * 1.96) / seeds;
  }
  const auto sd_of = [&](const std::vector<double>& x) {
    double mean = 0, squares = 0;
    for (const double value : x) mean += value / seeds;
    for (const double value : x) squares += (value - mean) * (value - mean);
    return std::sqrt(squares / (seeds - 1));
  };
  const double sd_v = sd_of(log_v), sd_kappa = sd_of(log_kappa), sd_q = sd_of(log_q);
  MESSAGE("over " << seeds << " seeds: sd of ln v " << sd_v << ", of ln kappa " << sd_kappa << ", of ln Q " << sd_q
                  << "; implied by the CI: with kappa's error " << widened_sd << ", the line's own " << own_sd);
  // Independent errors: the variances add (the sample variances of 150 draws are within about
  // 25 % of the true ones).
  CHECK(sd_v * sd_v / (sd_q * sd_q + sd_kappa * sd_kappa) > 0.75);
  CHECK(sd_v * sd_v / (sd_q * sd_q + sd_kappa * sd_kappa) < 1.33);
  CHECK(sd_kappa > 0.3 * sd_q);  // kappa's error is not negligible here
  // The widened CI is as conservative for ln v as the own CI is for ln Q; the own CI is not.
  const double own_margin = own_sd / sd_q;
  CHECK(widened_sd / sd_v > 0.95 * own_margin);
  CHECK(own_sd / sd_v < 0.9 * own_margin);
}
