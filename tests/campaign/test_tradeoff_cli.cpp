// `growthuq tradeoff` through the built CLI: the CSV's columns and rows, its summaries checked
// against `growthuq run` at the same sample counts, the default location, refusal to overwrite,
// and bad options (test_tradeoff_fidelity_cli.cpp runs the finite-element axis).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "growthuq/io/csv.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::string campaign_path = std::string(GROWTHUQ_SOURCE_DIR) + "/tests/campaign/data/small_campaign.ini";

// summary.csv of `growthuq run --samples N`, by (line, quantity).
std::map<std::pair<std::string, std::string>, std::vector<std::string>> run_summary(const fs::path& directory, int samples) {
  const fs::path out = directory / ("run_" + std::to_string(samples));
  const CliOutcome run = run_cli("run " + campaign_path + " --quiet --formats csv --samples " +
                                                   std::to_string(samples) + " --out " + out.string(), directory);
  REQUIRE(run.exit_code == 0);
  const CsvTable summary = read_csv((out / "summary.csv").string());
  std::map<std::pair<std::string, std::string>, std::vector<std::string>> rows;
  for (const auto& row : summary.rows) rows[{row[0], row[1]}] = row;
  return rows;
}

}  // namespace

TEST_CASE("growthuq tradeoff writes one row per count x line x quantity, the summaries of growthuq run") {
  const ScratchDirectory scratch("tradeoff_table");
  const fs::path csv = scratch.root / "trade.csv";
  const CliOutcome tradeoff =
      run_cli("tradeoff " + campaign_path + " --samples-list 50,200,1000 --quiet --out " + csv.string(), scratch.root);
  INFO(tradeoff.err);
  REQUIRE(tradeoff.exit_code == 0);
  CHECK(tradeoff.err.empty());  // --quiet
  CHECK(tradeoff.out.find("errors against the 1000-sample run") != std::string::npos);
  CHECK(tradeoff.out.find("target 1 %:") != std::string::npos);
  CHECK(tradeoff.out.find("table: " + csv.string() + " (24 rows)") != std::string::npos);

  const CsvTable table = read_csv(csv.string());
  CHECK(table.header == std::vector<std::string>{"fidelity", "samples", "seconds", "line", "quantity", "unit", "n", "median",
                                                 "iqr", "median_ci_low", "median_ci_high", "reference_median",
                                                 "reference_iqr", "median_error_pct", "iqr_error_pct",
                                                 "median_error_over_ci_half_width", "fe_reference_median",
                                                 "fe_reference_iqr", "fe_median_error_pct", "fe_iqr_error_pct"});
  REQUIRE(table.rows.size() == 3 * 2 * 4);  // counts x lines (wild_type, pme48) x quantities (p, E, eta, v)
  std::map<std::string, std::set<std::string>> seconds_of_count;
  for (const auto& row : table.rows) {
    CHECK(row[0] == "closed_form");  // the campaign's fidelity, the default of --fidelities
    CHECK(std::stod(row[2]) > 0);
    for (std::size_t fe_cell = 16; fe_cell < 20; ++fe_cell) CHECK(row[fe_cell].empty());  // no shell_fe run
    seconds_of_count[row[1]].insert(row[2]);
  }
  CHECK(seconds_of_count.size() == 3);
  for (const auto& [count, seconds] : seconds_of_count) CHECK(seconds.size() == 1);  // one time per count

  // The summaries at a count are those `growthuq run --samples N` writes (same campaign, seed,
  // designs), cell for cell; the reference columns are the 1000-sample run's.
  const auto at_200 = run_summary(scratch.root, 200);
  const auto at_1000 = run_summary(scratch.root, 1000);
  for (const auto& row : table.rows) {
    INFO(row[1] << " " << row[3] << " " << row[4]);
    const auto& reference = at_1000.at({row[3], row[4]});
    CHECK(row[11] == reference[5]);  // reference_median = summary.csv median
    CHECK(row[12] == reference[8]);  // reference_iqr = summary.csv iqr
    if (row[1] == "1000") {
      CHECK(row[13] == "0");
      CHECK(row[14] == "0");
    }
    if (row[1] != "200") continue;
    const auto& same = at_200.at({row[3], row[4]});
    CHECK(row[5] == same[2]);   // unit
    CHECK(row[6] == same[3]);   // n
    CHECK(row[7] == same[5]);   // median
    CHECK(row[8] == same[8]);   // iqr
    CHECK(row[9] == same[13]);  // median_ci_low
    CHECK(row[10] == same[14]);
    const double median = std::stod(row[7]), reference_median = std::stod(row[11]);
    if (reference_median != 0) {
      CHECK(std::stod(row[13]) == doctest::Approx(100 * std::abs(median - reference_median) / std::abs(reference_median)).epsilon(1e-12));
    }
  }
}

TEST_CASE("growthuq tradeoff: default table location, progress, refusal to overwrite, --force") {
  const ScratchDirectory scratch("tradeoff_overwrite");
  // output_dir = small_out in the campaign, relative to the current directory; created.
  const fs::path csv = scratch.root / "small_out" / "tradeoff.csv";
  CliOutcome run = run_cli("tradeoff " + campaign_path + " --samples-list 20,60 --target 50%", scratch.root);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  REQUIRE(fs::is_regular_file(csv));
  CHECK(run.err.starts_with("tradeoff: closed_form, 20 samples per line\nwild_type: 20 samples in "));
  CHECK(run.err.find("tradeoff: closed_form, 60 samples per line\n") != std::string::npos);
  const std::string first = slurp(csv);

  run = run_cli("tradeoff " + campaign_path + " --samples-list 20,60 --quiet --seed 12", scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err == "growthuq tradeoff: error: small_out/tradeoff.csv: already exists; choose another output or pass --force to overwrite\n");
  CHECK(slurp(csv) == first);

  run = run_cli("tradeoff " + campaign_path + " --samples-list 20,60 --quiet --seed 12 --force", scratch.root);
  CHECK(run.exit_code == 0);
  CHECK(slurp(csv) != first);  // another seed, other designs
  CHECK_FALSE(fs::exists(scratch.root / "small_out" / "tradeoff.csv.partial"));
}

TEST_CASE("growthuq tradeoff: bad options are one line and exit code 2, before any output") {
  const ScratchDirectory scratch("tradeoff_bad");
  const std::string start = "tradeoff " + campaign_path + " --quiet ";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--target 0", "--target = '0': expected a percentage above 0 and at most 100, e.g. 1%"},
      {"--target abc", "--target = 'abc': expected a percentage above 0 and at most 100, e.g. 1%"},
      {"--target=-1%", "--target = '-1%': expected a percentage above 0 and at most 100, e.g. 1%"},
      {"--samples-list 1000,100", "--samples-list = '1000,100': expected at least two increasing sample counts"},
      {"--samples-list 100", "--samples-list = '100': expected at least two increasing sample counts"},
      {"--samples-list 100,100", "--samples-list = '100,100': expected at least two increasing sample counts"},
      {"--samples-list 1,100", "--samples-list = '1': expected a whole number from 2 to 4294967295"},
      {"--samples-list 100,,1000", "--samples-list = '': expected a whole number from 2 to 4294967295"},
      {"--lines pme48", "keeps the reference line 'wild_type'"},
      {"--fidelities shell_fe", "--fidelities = 'shell_fe': expected closed_form or corrected; finite-element runs take "
                                "their own sample counts: --fe-samples-list (e.g. --fe-samples-list 10,50)"},
      {"--fidelities closed_form,fem", "--fidelities = 'closed_form,fem': expected closed_form or corrected, "
                                       "comma-separated, each once"},
      {"--fidelities closed_form,thin_shell", "--fidelities = 'closed_form,thin_shell': expected closed_form or "
                                              "corrected, comma-separated, each once"},
      {"--fidelities closed_form,", "--fidelities = 'closed_form,': expected closed_form or corrected, "
                                     "comma-separated, each once"},
      {"--fe-samples-list 50,10", "--fe-samples-list = '50,10': expected one or more increasing sample counts for the "
                                  "shell_fe runs, the largest being the finite-element reference (e.g. 10,50,150)"},
      {"--fe-samples-list 1", "--fe-samples-list = '1': expected a whole number from 2 to 4294967295"},
  };
  for (const auto& [options, message] : cases) {
    INFO(options);
    const CliOutcome run = run_cli(start + options, scratch.root);
    CHECK(run.exit_code == 2);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
    CHECK(run.err.starts_with("growthuq tradeoff: error: "));
    CHECK(run.err.find(message) != std::string::npos);
    CHECK(run.out.empty());
  }
  CHECK_FALSE(fs::exists(scratch.root / "small_out"));
}
