// Line comparisons end to end (campaigns/README.md, "Line comparisons"): a campaign of three
// raw-data lines with a 120-replicate bootstrap run through the CLI. The printed table and
// comparisons.csv / letters.csv carry the same pairs, numbers and letters; the ratios are those
// of summary.csv's medians; a pair differs exactly when its adjusted interval excludes 1, and
// two lines share a letter exactly when they do not differ. Without a bootstrap (no raw-data
// lines, or raw-data lines with replicates = 0) one line says so and no comparison file is
// written, and a --force rerun without one removes the old files.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "growthuq/io/csv.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/shared_letter.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::string source = GROWTHUQ_SOURCE_DIR;

std::string four_digits(const std::string& csv_cell) {
  if (csv_cell.empty()) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", std::stod(csv_cell));
  return text;
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> result;
  for (std::string word; in >> word;) result.push_back(word);
  return result;
}

// The lines of `text` from the one starting with `first` up to (not including) the first empty
// line or the end.
std::vector<std::string> block(const std::string& text, const std::string& first) {
  const std::size_t start = text.find("\n" + first);
  REQUIRE(start != std::string::npos);
  std::vector<std::string> lines;
  std::istringstream in(text.substr(start + 1));
  for (std::string line; std::getline(in, line) && !line.empty();) lines.push_back(line);
  return lines;
}

}  // namespace

TEST_CASE("line comparisons: the printed table, comparisons.csv, letters.csv and summary.csv agree") {
  ScratchDirectory scratch("line_comparisons");
  const fs::path out = scratch.root / "out";
  const CliOutcome run = run_cli("run '" + source + "/tests/campaign/data/raw_comparisons.ini' --out out --quiet", scratch.root);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  INFO(run.out);

  const CsvTable pairs = read_csv((out / "comparisons.csv").string());
  CHECK(pairs.header == std::vector<std::string>{"quantity", "unit", "line_a", "line_b", "ratio", "data_ci_low",
                                                 "data_ci_high", "adjusted_ci_low", "adjusted_ci_high", "adjusted_level",
                                                 "replicates", "differs", "note"});
  REQUIRE(pairs.rows.size() == 4 * 3);  // p, E, eta, v x 3 pairs
  const CsvTable summary = read_csv((out / "summary.csv").string());
  std::map<std::pair<std::string, std::string>, double> medians;
  for (std::size_t r = 0; r < summary.rows.size(); ++r) {
    medians[{summary.rows[r][summary.column_index("line")], summary.rows[r][summary.column_index("quantity")]}] =
        std::stod(summary.rows[r][summary.column_index("median")]);
  }

  // The printed table: a title line, the header, one row per pair, then the letters.
  const std::vector<std::string> printed = block(run.out, "line comparisons (");
  REQUIRE(printed.size() >= 2 + pairs.rows.size());
  std::map<std::pair<std::string, std::string>, std::string> differs;  // {quantity, "a/b"}
  std::size_t found_different = 0;
  for (std::size_t r = 0; r < pairs.rows.size(); ++r) {
    const std::vector<std::string>& row = pairs.rows[r];
    const auto at = [&](const char* column) { return row[pairs.column_index(column)]; };
    CAPTURE(printed[2 + r]);
    const std::vector<std::string> shown = words(printed[2 + r]);
    REQUIRE(shown.size() == 12);
    CHECK(shown[0] == at("quantity"));
    CHECK(shown[1] == at("line_a"));
    CHECK(shown[2] == at("line_b"));
    CHECK(shown[3] == four_digits(at("ratio")));
    CHECK(shown[4] == "[" + four_digits(at("data_ci_low")) + ",");
    CHECK(shown[5] == four_digits(at("data_ci_high")) + "]");
    CHECK(shown[6] == "[" + four_digits(at("adjusted_ci_low")) + ",");
    CHECK(shown[7] == four_digits(at("adjusted_ci_high")) + "]");
    CHECK(shown[8] == "98.33");  // 1 - 0.05 / 3
    CHECK(std::stod(at("adjusted_level")) == doctest::Approx(1.0 - 0.05 / 3).epsilon(1e-15));
    CHECK(shown[10] == at("replicates"));
    CHECK(shown[11] == at("differs"));
    CHECK(at("replicates") == "120");

    // The ratio is that of summary.csv's medians; the adjusted interval holds the 95 % one; the
    // pair differs exactly when the adjusted interval excludes 1.
    const double ratio = std::stod(at("ratio"));
    CHECK(ratio == doctest::Approx(medians.at({at("line_a"), at("quantity")}) / medians.at({at("line_b"), at("quantity")}))
                       .epsilon(1e-14));
    const double low = std::stod(at("adjusted_ci_low")), high = std::stod(at("adjusted_ci_high"));
    CHECK(low <= std::stod(at("data_ci_low")));
    CHECK(high >= std::stod(at("data_ci_high")));
    CHECK(at("differs") == ((low > 1.0 || high < 1.0) ? "yes" : "no"));
    found_different += at("differs") == "yes" ? 1 : 0;
    differs[{at("quantity"), at("line_a") + "/" + at("line_b")}] = at("differs");
  }
  MESSAGE(found_different << " of " << pairs.rows.size() << " pairs differ");
  CHECK(found_different > 0);  // (so the letters below are more than "a" everywhere)

  // Letters: the printed table (a row per line, a column per quantity) equals letters.csv, and
  // lines share a letter exactly when their pair does not differ.
  const CsvTable letters = read_csv((out / "letters.csv").string());
  CHECK(letters.header == std::vector<std::string>{"quantity", "line", "letters"});
  REQUIRE(letters.rows.size() == 4 * 3);
  std::size_t start = 2 + pairs.rows.size();
  while (start < printed.size() && printed[start].rfind("letters (", 0) != 0) ++start;
  REQUIRE(start + 4 < printed.size());
  const std::vector<std::string> quantities = words(printed[start + 1]);
  REQUIRE(quantities == std::vector<std::string>{"line", "p", "E", "eta", "v"});
  std::map<std::pair<std::string, std::string>, std::string> shown_letters;  // {quantity, line}
  for (std::size_t l = start + 2; l < start + 5; ++l) {
    const std::vector<std::string> row = words(printed[l]);
    REQUIRE(row.size() == 5);
    for (std::size_t q = 1; q < 5; ++q) shown_letters[{quantities[q], row[0]}] = row[q];
  }
  std::map<std::pair<std::string, std::string>, std::string> csv_letters;
  for (const std::vector<std::string>& row : letters.rows) csv_letters[{row[0], row[1]}] = row[2];
  CHECK(shown_letters == csv_letters);
  for (const auto& [key, text] : differs) {
    const std::string a = key.second.substr(0, key.second.find('/')), b = key.second.substr(key.second.find('/') + 1);
    CAPTURE(key.first);
    CAPTURE(key.second);
    CHECK(share_letter(csv_letters.at({key.first, a}), csv_letters.at({key.first, b})) == (text == "no"));
  }
}

TEST_CASE("line comparisons: without a bootstrap one line says why, and a --force rerun removes old comparison files") {
  ScratchDirectory scratch("line_comparisons_none");
  const fs::path out = scratch.root / "out";
  REQUIRE(run_cli("run '" + source + "/tests/campaign/data/raw_comparisons.ini' --out out --quiet", scratch.root).exit_code == 0);
  REQUIRE(fs::exists(out / "comparisons.csv"));
  REQUIRE(fs::exists(out / "letters.csv"));

  // Two lines given by line files: no data interval, so no comparison; the old files go.
  const CliOutcome run = run_cli("run '" + source + "/tests/campaign/data/small_campaign.ini' --out out --force --quiet", scratch.root);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(run.out.find("\nline comparisons: not made: they need the data interval of a [data_uncertainty] bootstrap over "
                     "raw-data lines, which this run has not (the Monte Carlo interval shrinks with the sample count and "
                     "would tell any lines apart)\n") != std::string::npos);
  CHECK(run.out.find("line comparisons (") == std::string::npos);
  CHECK_FALSE(fs::exists(out / "comparisons.csv"));
  CHECK_FALSE(fs::exists(out / "letters.csv"));

  // Raw-data lines with the bootstrap switched off (replicates = 0): the same line, no files.
  std::string text = slurp(source + "/tests/campaign/data/raw_comparisons.ini");
  text = text.substr(0, text.find("[data_uncertainty]")) + "[data_uncertainty]\nreplicates = 0\n\n" +
         text.substr(text.find("[line wild_type]"));
  for (std::size_t at = text.find("../../../distributions"); at != std::string::npos; at = text.find("../../../distributions")) {
    text.replace(at, std::string("../../../distributions").size(), source + "/distributions");
  }
  spit(scratch.root / "no_bootstrap.ini", text);
  const CliOutcome raw = run_cli("run no_bootstrap.ini --out raw --samples 100 --quiet", scratch.root);
  INFO(raw.err);
  REQUIRE(raw.exit_code == 0);
  CHECK(raw.out.find("\nline comparisons: not made: they need the data interval of a [data_uncertainty] bootstrap") !=
        std::string::npos);
  CHECK_FALSE(fs::exists(scratch.root / "raw" / "comparisons.csv"));
  CHECK_FALSE(fs::exists(scratch.root / "raw" / "letters.csv"));

  // One raw-data line and one from a line file: the bootstrap redraws only one.
  const CliOutcome mixed = run_cli("run '" + source + "/tests/campaign/data/raw_campaign.ini' --out mixed --quiet", scratch.root);
  REQUIRE(mixed.exit_code == 0);
  CHECK(mixed.out.find("\nline comparisons: not made: they need two lines or more given by raw data (only their laws "
                       "are all redrawn; pme48 from line files)\n") != std::string::npos);
  CHECK_FALSE(fs::exists(scratch.root / "mixed" / "comparisons.csv"));
}
