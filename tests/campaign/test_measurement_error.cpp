// The data bootstrap of a raw line whose k comes from force curves draws each tube's k within its
// measurement uncertainty u ([force_curves] measurement_error = bootstrap, the default;
// campaign/parametric_resample.hpp add_measurement_error):
//   - a draw is value + u z, z standard normal, truncated at 0: checked by a Kolmogorov-Smirnov
//     test against that distribution; u = 0 leaves a value exactly as it was;
//   - with measurement_error = none the data interval is the plain bootstrap's, bit for bit: the
//     same as a line whose k is a column holding the same per-tube values;
//   - with measurement_error = bootstrap on noisy curves (u comparable to the tubes' spread) the
//     interval widens, and the bootstrap says the interval includes measurement error;
//   - `growthuq run` says so under its summary, for the lines it concerns.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "campaign/parametric_resample.hpp"
#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/campaign/data_uncertainty.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/forcecurves/curve_processing.hpp"
#include "growthuq/forcecurves/force_curve.hpp"
#include "growthuq/forcecurves/tube_stiffness.hpp"
#include "growthuq/synthetic/indentation_curve.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using growthuq::testing::CliOutcome;
using growthuq::testing::run_cli;
using growthuq::testing::ScratchDirectory;
using growthuq::testing::slurp;
using growthuq::testing::spit;

namespace {

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// The Kolmogorov-Smirnov statistic of `draws` against the normal (mean, sd) truncated at 0.
double ks_truncated_normal(std::vector<double> draws, double mean, double sd) {
  std::sort(draws.begin(), draws.end());
  const double below_zero = normal_cdf(-mean / sd);
  double d = 0.0;
  const double n = static_cast<double>(draws.size());
  for (std::size_t i = 0; i < draws.size(); ++i) {
    const double cdf = (normal_cdf((draws[i] - mean) / sd) - below_zero) / (1.0 - below_zero);
    d = std::max({d, static_cast<double>(i + 1) / n - cdf, cdf - static_cast<double>(i) / n});
  }
  return d;
}

}  // namespace

TEST_CASE("measurement error: value + u z, z standard normal, truncated at 0; u = 0 leaves a value as it was") {
  const std::size_t n = 4000;
  // The 1 % critical value of the one-sample KS statistic, 1.628 / sqrt(n) (Massey 1951).
  const double critical = 1.628 / std::sqrt(static_cast<double>(n));
  for (const auto& [value, u] : {std::pair{3.0, 0.3}, std::pair{0.2, 0.2}}) {
    std::vector<double> draws(n, value);
    add_measurement_error(draws, std::vector<double>(n, u), 17, "wt", "k");
    CAPTURE(value);
    CHECK(*std::min_element(draws.begin(), draws.end()) > 0.0);
    const double d = ks_truncated_normal(draws, value, u);
    MESSAGE("KS D of " << n << " draws of " << value << " within u = " << u << ": " << d << " (1 % critical " << critical << ")");
    CHECK(d < critical);
    // A normal without the truncation is rejected where the truncation matters (u = value).
    if (u == value) CHECK(ks_truncated_normal(draws, value, 1e6 * u) > critical);
  }
  std::vector<double> values{2.87, 3.1, 1.9};
  const std::vector<double> before = values;
  add_measurement_error(values, {0.0, 0.0, 0.0}, 17, "wt", "k");
  CHECK(values == before);
  // Another replicate key, other draws; the same key, the same draws.
  std::vector<double> a(5, 3.0), b(5, 3.0), c(5, 3.0);
  add_measurement_error(a, std::vector<double>(5, 0.1), 1, "wt", "k");
  add_measurement_error(b, std::vector<double>(5, 0.1), 1, "wt", "k");
  add_measurement_error(c, std::vector<double>(5, 0.1), 2, "wt", "k");
  CHECK(a == b);
  CHECK(a != c);
}

namespace {

// Twelve tubes of two curves each, true k 2.90-3.01 N/m, with force noise `noise_uN`; their d, d0
// and h. Writes curves.csv, sheet.csv and tubes.csv into `folder` and returns the per-tube k as
// the campaign computes it (Eq. (C10)).
std::vector<TubeStiffness> write_curves(const std::filesystem::path& folder, double noise_uN) {
  std::vector<ForceCurve> curves;
  std::string tubes = "tube,d_um,d0_um,h_nm\n";
  for (int t = 0; t < 12; ++t) {
    IndentationTruth truth;
    truth.stiffness = 2.9 + 0.01 * t;
    truth.sensor_stiffness = 100.0;
    truth.approach_samples = 300;
    truth.noise = noise_uN * 1e-6;
    truth.end = truth.contact + 6e-6 / truth.stiffness;
    const std::string tube = "T" + std::to_string(t);
    for (int r = 1; r <= 2; ++r) {
      curves.push_back(simulate_indentation_curve(truth, static_cast<std::uint64_t>(10 * t + r), tube + "r" + std::to_string(r), tube, r));
    }
    tubes += tube + "," + std::to_string(6.3 + 0.05 * t) + "," + std::to_string(5.2 + 0.03 * t) + "," + std::to_string(140 + t) + "\n";
  }
  spit(folder / "curves.csv", force_curves_csv(curves));
  spit(folder / "sheet.csv", curve_sheet_csv(curves));
  spit(folder / "tubes.csv", tubes);
  std::vector<CurveResult> results;
  for (const ForceCurve& curve : read_force_curves((folder / "curves.csv").string(), (folder / "sheet.csv").string())) {
    results.push_back(process_force_curve(curve, CurveProcessingOptions{}));
  }
  return tube_stiffness(results);
}

std::string measured(const std::string& variable, const std::string& file, const std::string& unit) {
  return "\n[measurement " + variable + "]\nfile = " + file + "\ncolumn = " + variable + "_" + unit + "\nunit = " + unit + "\n";
}

// raw.ini with d, d0, h and then k: from the force curves with `force_curves_keys`, or (empty
// keys and `k_column`) from a column of k.csv.
std::string raw_ini(const std::string& force_curves_keys, bool k_column) {
  std::string raw = "[line]\nname = curved\n" + measured("d", "tubes.csv", "um") + measured("d0", "tubes.csv", "um") +
                    measured("h", "tubes.csv", "nm");
  if (k_column) return raw + "\n[measurement k]\nfile = k.csv\ncolumn = k_N_per_m\nunit = N/m\n";
  return raw + "\n[force_curves]\ncurves = curves.csv\nsheet = sheet.csv\n" + force_curves_keys;
}

DataUncertainty bootstrap_of(const std::filesystem::path& folder, const std::string& raw_name) {
  const std::string text = "[campaign]\nname = curved\nseed = 3\nsamples = 200\noutputs = k\noutput_dir = out\nformats = csv\n"
                           "[instrument]\nprobe_radius_um = 0.5\n[line curved]\nraw = " + raw_name +
                           "\nrank_correlation = none\n[data_uncertainty]\nreplicates = 200\nsamples = 400\n";
  const PreparedCampaign prepared(parse_campaign(text, (folder / ("campaign_" + raw_name)).string()));
  const DataUncertaintyResult result = estimate_data_uncertainty(prepared);
  REQUIRE(result.rows.size() == 1);
  return result.rows.front();
}

}  // namespace

TEST_CASE("measurement error in the data bootstrap: none is the plain bootstrap bit for bit; bootstrap widens the interval and says so") {
  const ScratchDirectory folder("measurement_error");
  // Noise 0.15 uN on tubes of nearly one k: each tube's u is most of the tubes' spread.
  const std::vector<TubeStiffness> tubes = write_curves(folder.root, 0.15);
  std::string k = "tube,k_N_per_m\n";
  double u_mean = 0.0;
  std::vector<double> values;
  for (const TubeStiffness& tube : tubes) {
    REQUIRE(tube.ok == 2);
    k += tube.tube + "," + format_double(tube.stiffness) + "\n";
    u_mean += tube.uncertainty / static_cast<double>(tubes.size());
    values.push_back(tube.stiffness);
  }
  spit(folder.root / "k.csv", k);
  spit(folder.root / "none.ini", raw_ini("measurement_error = none\n", false));
  spit(folder.root / "bootstrap.ini", raw_ini("", false));  // the default
  spit(folder.root / "column.ini", raw_ini("", true));

  const DataUncertainty none = bootstrap_of(folder.root, "none.ini");
  const DataUncertainty column = bootstrap_of(folder.root, "column.ini");
  const DataUncertainty with_error = bootstrap_of(folder.root, "bootstrap.ini");
  CHECK_FALSE(none.measurement_error);
  CHECK(with_error.measurement_error);
  // none: the k column's bootstrap exactly.
  CHECK(none.replicate_medians == column.replicate_medians);
  CHECK(none.low == column.low);
  CHECK(none.high == column.high);

  double mean = 0.0, spread = 0.0;
  for (const double value : values) mean += value / static_cast<double>(values.size());
  for (const double value : values) spread += (value - mean) * (value - mean) / static_cast<double>(values.size() - 1);
  spread = std::sqrt(spread);
  MESSAGE("tubes' k spread " << spread << " N/m, mean u " << u_mean << " N/m; k data interval width: none "
                             << none.high - none.low << ", bootstrap " << with_error.high - with_error.low << " N/m; sd of the "
                             << "replicate medians " << none.sd << " and " << with_error.sd << " (ratio "
                             << with_error.sd / none.sd << ", expected about " << std::sqrt(1.0 + u_mean * u_mean / (spread * spread))
                             << ")");
  // A replicate's k values scatter by sqrt(s^2 + u^2) instead of s, so the replicate medians' sd
  // grows by about sqrt(1 + u^2 / s^2), here about 1.3 (the sd of 200 replicates has a relative
  // standard error of 5 %; the replicates' Monte Carlo error, 400 samples, is small beside it).
  CHECK(u_mean > 0.5 * spread);
  CHECK(with_error.sd > none.sd * 1.12);
  CHECK(with_error.high - with_error.low > none.high - none.low);
}

TEST_CASE("measurement error: the bootstrap's sources say the interval includes it; a bad value is refused at its line") {
  const ScratchDirectory folder("measurement_error_sources");
  write_curves(folder.root, 0.01);
  spit(folder.root / "raw.ini", raw_ini("", false));
  const std::string text = "[campaign]\nname = curved\nseed = 3\nsamples = 100\noutputs = p\noutput_dir = out\nformats = csv\n"
                           "[instrument]\nprobe_radius_um = 0.5\n[line curved]\nraw = raw.ini\nrank_correlation = none\n"
                           "[data_uncertainty]\nreplicates = 20\nsamples = 100\n";
  const PreparedCampaign prepared(parse_campaign(text, (folder.root / "c.ini").string()));
  const std::vector<std::string> sources = data_uncertainty_sources(prepared);
  REQUIRE(sources.size() == 1);
  INFO(sources[0]);
  CHECK(sources[0].find("k (n = 12, each drawn within its tube's measurement uncertainty: the interval includes measurement "
                        "error)") != std::string::npos);

  spit(folder.root / "bad.ini", raw_ini("measurement_error = yes\n", false));
  const std::string bad = "[campaign]\nname = curved\nseed = 3\nsamples = 100\noutputs = p\noutput_dir = out\nformats = csv\n"
                          "[instrument]\nprobe_radius_um = 0.5\n[line curved]\nraw = bad.ini\nrank_correlation = none\n";
  try {
    const PreparedCampaign refused(parse_campaign(bad, (folder.root / "c2.ini").string()));
    FAIL("a bad measurement_error was taken");
  } catch (const InputError& error) {
    const std::string message = error.what();
    CHECK(message.find("bad.ini:") != std::string::npos);
    CHECK(message.find("measurement_error") != std::string::npos);
    CHECK(message.find("'yes'") != std::string::npos);
    CHECK(message.find("bootstrap or none") != std::string::npos);
  }
}

TEST_CASE("the line under the summary names the lines whose data intervals include the force curves' measurement error") {
  // Two copies of the shipped wild type's raw data: k from its force curves with measurement_error
  // = bootstrap (the default) and = none. Only the first line's interval includes the error.
  const ScratchDirectory scratch("summary_measurement_error");
  const std::string folder = std::string(GROWTHUQ_SOURCE_DIR) + "/distributions/example_raw/wild_type/";
  const std::string shipped = slurp(folder + "raw.ini");
  for (const std::string name : {"with_error", "without_error"}) {
    std::string text;
    std::istringstream lines(shipped);
    for (std::string line; std::getline(lines, line);) {
      // The tables named by absolute paths, so the copy can live in the scratch folder.
      for (const std::string key : {"file = ", "curves = ", "sheet = ", "meta = "}) {
        if (line.rfind(key, 0) == 0) line = key + folder + line.substr(key.size());
      }
      if (line == "name = wild_type") line = "name = " + name;
      text += line + "\n";
      if (line == "[force_curves]" && name == std::string("without_error")) text += "measurement_error = none\n";
    }
    spit(scratch.root / (name + std::string(".ini")), text);
  }
  spit(scratch.root / "campaign.ini",
       "[campaign]\nname = measured\nseed = 5\nsamples = 60\noutputs = p, E\noutput_dir = out\nformats = csv\n"
       "[instrument]\nprobe_radius_um = 0.5\n[data_uncertainty]\nreplicates = 4\nsamples = 60\n"
       "[line with_error]\nraw = with_error.ini\n[line without_error]\nraw = without_error.ini\n");
  const CliOutcome run = run_cli("run campaign.ini --quiet --summary-only", scratch.root);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(run.out.find("\ndata 95 % interval: a parametric bootstrap over the tubes of the raw-data lines, 4 replicates x 60 samples per "
                     "line (campaigns/README.md, \"Data uncertainty\"), for with_error including each tube's measurement error of k "
                     "from its force curves; Monte Carlo 95 % CI: the error of this run's 60 samples alone\n") != std::string::npos);
  // data_uncertainty.csv says the same per row.
  const std::string table = slurp(scratch.root / "out" / "data_uncertainty.csv");
  CHECK(table.find("\nwith_error,p,") != std::string::npos);
  std::istringstream rows(table);
  std::string row;
  std::getline(rows, row);
  std::size_t included = 0, none = 0;
  while (std::getline(rows, row)) {
    const bool with_error = row.rfind("with_error,", 0) == 0;
    CHECK(row.ends_with(with_error ? ",included" : ",none"));
    ++(with_error ? included : none);
  }
  CHECK(included == 2);
  CHECK(none == 2);
}
