// `growthuq tradeoff --fe-samples-list` through the built CLI: closed_form at 20 and 40 samples
// and shell_fe at 2 (seconds each on the coarse mesh) on a one-line campaign. The table holds
// the rows of both fidelities with the fe_ columns filled against the shell_fe run, and the
// printed cheapest run is the one the table itself designates.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "growthuq/io/csv.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::string campaign_path = std::string(GROWTHUQ_SOURCE_DIR) + "/tests/campaign/data/tradeoff_fidelity.ini";

// Columns of tradeoff.csv.
constexpr std::size_t fidelity = 0, samples = 1, seconds = 2, quantity = 4, median = 7, iqr = 8, fe_reference_median = 16,
                      fe_reference_iqr = 17, fe_median_error_pct = 18, fe_iqr_error_pct = 19;

std::string unwrapped(std::string text) {
  for (char& c : text) {
    if (c == '\n') c = ' ';
  }
  return text;
}

}  // namespace

TEST_CASE("growthuq tradeoff --fe-samples-list: both fidelities' rows, the fe_ columns and the cheapest run") {
  const ScratchDirectory scratch("tradeoff_fidelity");
  const fs::path csv = scratch.root / "trade.csv";
  const std::string target = "100%";
  const CliOutcome run = run_cli("tradeoff " + campaign_path + " --samples-list 20,40 --fe-samples-list 2 --target " +
                                     target + " --out " + csv.string(),
                                 scratch.root);
  INFO(run.err);
  INFO(run.out);
  REQUIRE(run.exit_code == 0);
  // The time of the finite-element runs is said before they start; progress per run.
  CHECK(run.err.find("growthuq tradeoff: time: fidelity shell_fe, 2 finite-element samples x about 4 s") !=
        std::string::npos);
  CHECK(run.err.find("tradeoff: closed_form, 40 samples per line\n") != std::string::npos);
  CHECK(run.err.find("tradeoff: shell_fe, 2 samples per line\n") != std::string::npos);

  const CsvTable table = read_csv(csv.string());
  REQUIRE(table.header.size() == 20);
  CHECK(table.header[fe_iqr_error_pct] == "fe_iqr_error_pct");
  REQUIRE(table.rows.size() == 3 * 2);  // (closed_form 20, 40; shell_fe 2) x (p, E) of one line

  // The shell_fe run's medians and IQRs per quantity: the finite-element reference.
  std::map<std::string, std::pair<double, double>> fe_reference;
  std::map<std::pair<std::string, std::string>, std::size_t> rows_of_run;
  for (const auto& row : table.rows) {
    ++rows_of_run[{row[fidelity], row[samples]}];
    if (row[fidelity] == "shell_fe") fe_reference[row[quantity]] = {std::stod(row[median]), std::stod(row[iqr])};
  }
  CHECK(rows_of_run == std::map<std::pair<std::string, std::string>, std::size_t>{
                           {{"closed_form", "20"}, 2}, {{"closed_form", "40"}, 2}, {{"shell_fe", "2"}, 2}});
  REQUIRE(fe_reference.size() == 2);

  // Every row's fe_ cells, recomputed from the table; and the run the sentence must name: the
  // least seconds among the non-reference runs whose every fe error is below the target.
  std::map<std::pair<std::string, std::string>, bool> meets;
  std::map<std::pair<std::string, std::string>, double> seconds_of_run;
  std::map<std::pair<std::string, std::string>, double> largest_error;  // of its median and IQR errors
  for (const auto& row : table.rows) {
    INFO(row[fidelity] << " " << row[samples] << " " << row[quantity]);
    const auto [reference_median, reference_iqr] = fe_reference.at(row[quantity]);
    CHECK(std::stod(row[fe_reference_median]) == reference_median);
    CHECK(std::stod(row[fe_reference_iqr]) == reference_iqr);
    const double median_error = 100 * std::abs(std::stod(row[median]) - reference_median) / std::abs(reference_median);
    const double iqr_error = 100 * std::abs(std::stod(row[iqr]) - reference_iqr) / std::abs(reference_iqr);
    CHECK(std::stod(row[fe_median_error_pct]) == doctest::Approx(median_error).epsilon(1e-12));
    CHECK(std::stod(row[fe_iqr_error_pct]) == doctest::Approx(iqr_error).epsilon(1e-12));
    if (row[fidelity] == "shell_fe") {
      CHECK(row[fe_median_error_pct] == "0");
      continue;
    }
    const std::pair<std::string, std::string> key{row[fidelity], row[samples]};
    seconds_of_run[key] = std::stod(row[seconds]);
    const bool below = median_error < 100 && iqr_error < 100;
    meets[key] = meets.contains(key) ? meets[key] && below : below;
    largest_error[key] = std::max({largest_error[key], median_error, iqr_error});
  }
  std::optional<std::pair<std::string, std::string>> cheapest, closest;
  for (const auto& [key, ok] : meets) {
    if (ok && (!cheapest || seconds_of_run[key] < seconds_of_run[*cheapest])) cheapest = key;
    if (!closest || largest_error[key] < largest_error[*closest]) closest = key;
  }

  const std::string out = unwrapped(run.out);
  CHECK(out.find("trade-off of campaign 'trade_fidelities' (closed_form): 1 lines x 2 quantities") != std::string::npos);
  CHECK(out.find("every run against the finite-element model (the 2-sample shell_fe run):") != std::string::npos);
  CHECK(out.find("against the 2-sample shell_fe reference, target 100 %: ") != std::string::npos);
  if (cheapest) {
    MESSAGE("cheapest within 100 %: " << cheapest->first << " at " << cheapest->second);
    CHECK(out.find("the cheapest run is " + cheapest->first + " at " + cheapest->second + " samples per line") !=
          std::string::npos);
  } else {
    CHECK(out.find("no run has every median and IQR within it. Closest is " + closest->first + " at " +
                   closest->second + " samples per line") != std::string::npos);
  }
  CHECK(out.find("table: " + csv.string() + " (6 rows)") != std::string::npos);
}
