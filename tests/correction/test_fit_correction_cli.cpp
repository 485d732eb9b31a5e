// `growthuq fit-correction` end to end: from the shipped training data it writes exactly the
// shipped correction (the text the engine compiles in), reports the held-out and the
// cross-validation errors, refuses to overwrite without --force, and names a malformed file.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_run.hpp"
#include "support/text_file.hpp"

using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path directory = fs::temp_directory_path() / ("growthuq_test_fit_correction_" + name);
  fs::remove_all(directory);
  fs::create_directories(directory);
  return directory;
}

const std::string source_dir = GROWTHUQ_SOURCE_DIR;

}  // namespace

TEST_CASE("fit-correction refits the shipped correction byte for byte and reports its errors") {
  const fs::path directory = scratch("refit");
  const CliOutcome outcome =
      run_cli("fit-correction --training '" + source_dir + "/src/correction/training.csv' --curves '" + source_dir +
                  "/src/correction/training_curves.csv' --out fit.inc --errors errors.csv",
              directory);
  INFO(outcome.err);
  REQUIRE(outcome.exit_code == 0);
  CHECK(slurp(directory / "fit.inc") == slurp(fs::path(source_dir) / "src/correction/shipped_correction.inc"));
  CHECK(outcome.out.find("held out: ") != std::string::npos);
  CHECK(outcome.out.find("cross-validation (5 folds") != std::string::npos);
  // One errors row per training tube and window inside the fitted envelope, with a value or a status.
  const std::string errors = slurp(directory / "errors.csv");
  CHECK(errors.rfind("index,window_low_uN,window_top_uN,held_out,lambda,", 0) == 0);
  CHECK(errors.find(",nan") == std::string::npos);

  const CliOutcome again = run_cli("fit-correction --training '" + source_dir + "/src/correction/training.csv' --curves '" +
                                       source_dir + "/src/correction/training_curves.csv' --out fit.inc",
                                   directory);
  CHECK(again.exit_code != 0);
  CHECK(again.err.find("fit.inc") != std::string::npos);
  CHECK(again.err.find("--force") != std::string::npos);
}

TEST_CASE("fit-correction names the file, line and column of a malformed training row") {
  const fs::path directory = scratch("bad");
  std::ofstream(directory / "bad.csv") << "index,p_MPa,E_MPa,h_nm,d0_um,rho_um,k_N_per_m,d_um,status,newton_iterations,seconds\n"
                                       << "0,0.4,40,180,5.3,0.4,2.5,6.2,ok,100,20\n"
                                       << "1,0.4,-40,180,5.3,0.4,2.5,6.2,ok,100,20\n";
  std::ofstream(directory / "curves.csv") << "index,delta_um,F_uN\n0,0,0\n0,1,3\n";
  const CliOutcome outcome = run_cli("fit-correction --training bad.csv --curves curves.csv --out fit.inc", directory);
  CHECK(outcome.exit_code != 0);
  CHECK(outcome.err.find("bad.csv") != std::string::npos);
  CHECK(outcome.err.find("E_MPa") != std::string::npos);
  CHECK(outcome.err.find("'-40'") != std::string::npos);
  CHECK_FALSE(fs::exists(directory / "fit.inc"));
}
