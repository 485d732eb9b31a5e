// Input that changed results without a word, refused at the command line (src/cli/README.md, "Input that
// changes results"): an eval column named like an input with no unit of it, a line given twice.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq::testing;
namespace fs = std::filesystem;

TEST_CASE("eval: a column named like an input with a unit not of its kind is an error, not ignored") {
  const ScratchDirectory scratch("cli_eval_columns");
  // h in seconds: the thickness was skipped, so E, hoop stress and wall stiffness were left out.
  spit(scratch.root / "tubes.csv", "k_N_per_m,d_um,d0_um,h_s\n2.87,6.56,5.35,145\n");
  const CliOutcome run = run_cli("eval --rho-um 0.5 --in tubes.csv --out r.csv", scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err == "growthuq eval: error: tubes.csv: column 'h_s' names h with no unit of length: expected one of "
                   "h_m, h_mm, h_um, h_nm (or rename the column)\n");
  CHECK(!fs::exists(scratch.root / "r.csv"));
  // With its unit the same tube gives E.
  spit(scratch.root / "tubes.csv", "k_N_per_m,d_um,d0_um,h_nm\n2.87,6.56,5.35,145\n");
  const CliOutcome good = run_cli("eval --rho-um 0.5 --in tubes.csv --out r.csv", scratch.root);
  CHECK(good.exit_code == 0);
  CHECK(slurp(scratch.root / "r.csv").find("E_MPa") != std::string::npos);
}

TEST_CASE("run: a line given twice in --lines is an error, not run twice into the same files") {
  const ScratchDirectory scratch("cli_lines_twice");
  const std::string quick = std::string(GROWTHUQ_SOURCE_DIR) + "/campaigns/quick.ini";
  const CliOutcome run = run_cli("run " + quick + " --samples 20 --quiet --out out --lines wild_type,wild_type", scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err == "growthuq run: error: command line: --lines = 'wild_type,wild_type': expected each item once "
                   "('wild_type' is listed twice)\n");
  CHECK(!fs::exists(scratch.root / "out"));
}
