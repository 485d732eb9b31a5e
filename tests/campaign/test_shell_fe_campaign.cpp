// A campaign at fidelity shell_fe, for real (tests/campaign/data/fidelity_campaign.ini: one line
// of finite-element samples on the coarse mesh, one analytic): each sample's p and E are those
// of `growthuq eval --fidelity shell_fe` for the same tube; a run killed between
// finite-element samples keeps the finished ones and `--resume` finishes it byte-identical to
// an uninterrupted run. (The same campaign under mpirun: test_fidelity_campaign_mpi_2.)
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "campaign/chunk_log.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

// A copy of the campaign whose line paths point at the shipped line files.
fs::path campaign_copy(const fs::path& root) {
  const std::string source = std::string(GROWTHUQ_SOURCE_DIR);
  std::string text = slurp(source + "/tests/campaign/data/fidelity_campaign.ini");
  for (std::size_t at; (at = text.find("../../../distributions/")) != std::string::npos;) {
    text.replace(at, 23, source + "/distributions/");
  }
  spit(root / "fidelities.ini", text);
  return root / "fidelities.ini";
}


std::size_t records_in(const fs::path& log) {
  std::error_code error;
  if (!fs::exists(log, error)) return 0;
  return scan_chunk_log(log.string()).records.size();
}

}  // namespace

TEST_CASE("shell_fe campaign: samples equal eval's inverse; killed between samples, --resume finishes it identically") {
  ScratchDirectory scratch("shell_fe_campaign");
  const fs::path campaign = campaign_copy(scratch.root);
  const std::vector<std::string> arguments{"run", campaign.string(), "--formats", "csv", "--quiet", "--out", "out"};

  fs::create_directories(scratch.root / "reference");
  const CliOutcome reference = run_in(scratch.root / "reference", cli(arguments));
  REQUIRE_MESSAGE(reference.exit_code == 0, reference.err);
  const std::string samples = slurp(scratch.root / "reference" / "out" / "samples.csv");
  const std::vector<std::string> rows = split_text(samples, '\n');
  REQUIRE(rows.size() >= 2);
  CHECK(rows[0] == "line,sample,k_N_per_m,h_nm,d_um,d0_um,p_MPa,E_MPa,status");

  // The first finite-element sample with a value, through `growthuq eval --fidelity shell_fe`
  // (the same inverse, called by a different front end, from the tube as samples.csv prints
  // it): the same p and E within the inverse's own tolerance (its root in E and the inflation's
  // refinement stop at 1e-4 relative, src/fe/README.md: an input one rounding away may stop one
  // iteration apart).
  bool compared = false;
  for (std::size_t r = 1; r < rows.size() && !compared; ++r) {
    const std::vector<std::string> cells = split_text(rows[r], ',');
    if (cells.size() != 9 || cells[0] != "wild_type" || cells[8] != "ok") continue;
    const CliOutcome eval = run_in(scratch.root, cli({"eval", "--fidelity", "shell_fe", "--mesh", "coarse", "--rho-um", "0.5",
                                                      "--k", cells[2], "--h-nm", cells[3], "--d-um", cells[4], "--d0-um", cells[5]}));
    REQUIRE_MESSAGE(eval.exit_code == 0, eval.err);
    CHECK(printed_value(eval.out, "p") == doctest::Approx(std::stod(cells[6])).epsilon(5e-4));
    CHECK(printed_value(eval.out, "E") == doctest::Approx(std::stod(cells[7])).epsilon(5e-4));
    compared = true;
  }
  CHECK(compared);

  // Killed once two finite-element samples are in the checkpoint: at most the one in flight is lost.
  const fs::path work = scratch.root / "killed";
  fs::create_directories(work);
  const pid_t pid = start(cli(arguments), work);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
  while (records_in(work / "out" / "checkpoint" / "chunks.bin") < 2) {
    int status = 0;
    REQUIRE_MESSAGE(waitpid(pid, &status, WNOHANG) == 0, "the run ended before it could be killed");
    REQUIRE_MESSAGE(std::chrono::steady_clock::now() < deadline, "no two samples in the checkpoint after 300 s");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(pid, SIGKILL);
  wait_for(pid);
  CHECK(records_in(work / "out" / "checkpoint" / "chunks.bin") >= 2);
  CHECK_FALSE(fs::exists(work / "out" / "samples.csv"));

  const CliOutcome resumed = run_in(work, cli({"run", "--resume", "out", "--quiet"}));
  REQUIRE_MESSAGE(resumed.exit_code == 0, resumed.err);
  CHECK(resumed.out == reference.out);
  CHECK(slurp(work / "out" / "samples.csv") == samples);
  CHECK(slurp(work / "out" / "summary.csv") == slurp(scratch.root / "reference" / "out" / "summary.csv"));
}
