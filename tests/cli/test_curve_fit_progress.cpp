// relax and fit-line fit relaxation curves for seconds: their progress goes to stderr (never into
// the report or the result on stdout) and --quiet silences it. Stderr is no terminal here, so the
// progress prints lines; whatever the load, the last one names every curve and the time taken.
#include <doctest/doctest.h>

#include <cstdio>
#include <string>

#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"

using namespace growthuq::testing;

namespace {

const std::string raw = std::string(GROWTHUQ_SOURCE_DIR) + "/distributions/example_raw/wild_type";

// The curve count the report states, "growthuq relax: N curve(s) from ...".
std::size_t reported_curves(const std::string& report) {
  std::size_t count = 0;
  REQUIRE(std::sscanf(report.c_str(), "growthuq relax: %zu curve(s)", &count) == 1);
  return count;
}

}  // namespace

TEST_CASE("relax: the curve fits' progress on stderr, none with --quiet, the report unchanged") {
  const ScratchDirectory scratch("relax_progress");
  const std::string relax = "relax " + raw + "/relaxation_curves.csv --meta " + raw + "/relaxation_meta.csv --out ";
  const CliOutcome shown = run_cli(relax + "fits.csv", scratch.root);
  REQUIRE(shown.exit_code == 0);
  const std::size_t curves = reported_curves(shown.out);
  CHECK(curves > 1);
  CHECK(shown.err.find("fitting relaxation curves: " + std::to_string(curves) + " curves in ") != std::string::npos);
  CHECK(shown.out.find("fitting relaxation curves") == std::string::npos);

  const CliOutcome quiet = run_cli(relax + "quiet.csv --quiet", scratch.root);
  REQUIRE(quiet.exit_code == 0);
  CHECK(quiet.err.empty());
  // The same report but for the file it names.
  std::string expected = shown.out;
  expected.replace(expected.rfind("fits.csv"), 8, "quiet.csv");
  CHECK(quiet.out == expected);

  const CliOutcome help = run_cli("relax --help", scratch.root);
  CHECK(help.out.find("--quiet") != std::string::npos);
  CHECK(help.out.find("progress goes to stderr") != std::string::npos);
}

TEST_CASE("fit-line: the curve fits' progress on stderr, none with --quiet") {
  const ScratchDirectory scratch("fit_line_progress");
  const CliOutcome shown = run_cli("fit-line " + raw + "/raw.ini", scratch.root);
  REQUIRE(shown.exit_code == 0);
  CHECK(shown.err.find("fitting relaxation curves: ") != std::string::npos);
  CHECK(shown.err.find(" curves in ") != std::string::npos);
  CHECK(shown.out.find("fitting relaxation curves") == std::string::npos);
  const CliOutcome quiet = run_cli("fit-line " + raw + "/raw.ini --quiet", scratch.root);
  REQUIRE(quiet.exit_code == 0);
  CHECK(quiet.err.empty());
  CHECK(quiet.out == shown.out);
}
