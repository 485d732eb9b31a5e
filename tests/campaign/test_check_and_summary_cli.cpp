// growthuq check: the run's validation and plan without running (its verdict and message are
// the run's, for the same campaign and flags; nothing is written); and run --summary-only: the
// same stdout as a full run up to the per-line reports, which it leaves out.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::string small = std::string(GROWTHUQ_SOURCE_DIR) + "/tests/campaign/data/small_campaign.ini";

// `text` with "growthuq check" replaced by "growthuq run", to compare the two commands' messages.
std::string as_run(std::string text) {
  const std::string check = "growthuq check";
  for (std::size_t at = text.find(check); at != std::string::npos; at = text.find(check, at)) text.replace(at, check.size(), "growthuq run");
  return text;
}

// The message without the machine's available memory and what fits in it: they change between
// two commands while other programs run (23.9 against 23.8 GB seen on a shared machine).
std::string without_available_memory(std::string text) {
  const std::size_t from = text.find("this machine has ");
  const std::size_t to = text.find(" samples per line fit", from);
  if (from != std::string::npos && to != std::string::npos) text.replace(from, to - from, "this machine has ...");
  return text;
}

// The folder's entries, to show that check wrote nothing.
std::size_t entries(const fs::path& folder) {
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder)) ++count;
  return count;
}

}  // namespace

TEST_CASE("growthuq check prints the plan and writes nothing") {
  const ScratchDirectory scratch("check_plan");
  const CliOutcome check = run_cli("check " + small + " --out planned", scratch.root);
  REQUIRE(check.exit_code == 0);
  CHECK(check.err.empty());
  CHECK(check.out.rfind("campaign 'small' (" + small + "): 2 lines x 200 samples, seed 11, fidelity closed_form\n", 0) == 0);
  CHECK(check.out.find("outputs: p, E, eta, v\n") != std::string::npos);
  // Run order: the reference line (wild_type) first when v is an output, then file order.
  const std::size_t wild_type = check.out.find("  wild_type: distributions ");
  const std::size_t pme48 = check.out.find("  pme48: distributions ");
  REQUIRE(wild_type != std::string::npos);
  REQUIRE(pme48 != std::string::npos);
  CHECK(wild_type < pme48);
  CHECK(check.out.find("rank correlation from the forward thin-shell model") != std::string::npos);
  CHECK(check.out.find("results in planned: summary.csv, sensitivity.csv, provenance.json, samples.csv\n") != std::string::npos);
  CHECK(check.out.find("    samples k [N/m], h [nm], d [um], d0 [um], tau [s], einf [%]; ") != std::string::npos);
  CHECK(check.out.find("    models thin_shell_turgor, thin_shell_modulus, viscosity, growth\n") != std::string::npos);
  // The run's estimate (run_footprint.hpp) by hand: m = 6 inputs, o = 4 outputs, 2 lines, csv,
  // checkpoint. Memory per sample: 20 m + 4 o + 36 = 172, + 3/5 of (12 m + 8 o + 1 = 105) = 63
  // for the lines held, + 105 for samples.csv: 340 bytes; 40e6 + 2^29 + 340 x 200 = 576.9 MB.
  // Disk per sample and line: samples.csv 20 (m + o) + 30 + 9 (wild_type) = 239, checkpoint
  // 8 (o + 1) = 40; 279 x 2 lines x 200 = 0.1 MB.
  CHECK(check.out.find("estimated peak memory 576.9 MB for one process (") != std::string::npos);
  CHECK(check.out.find("), disk 0.1 MB (") != std::string::npos);
  CHECK(check.out.find("checked: nothing was sampled or written\n") != std::string::npos);
  CHECK(check.out.find("data uncertainty: none, the intervals will be Monte Carlo only (no line is given by raw data)\n") !=
        std::string::npos);
  CHECK(entries(scratch.root) == 2);  // stdout.txt and stderr.txt only: no "planned"
  // --samples changes the plan as it changes the run.
  CHECK(run_cli("check " + small + " --out planned --samples 30", scratch.root).out.find("2 lines x 30 samples") != std::string::npos);
}

TEST_CASE("growthuq check states the data-uncertainty bootstrap a raw-data campaign runs by default, and its cost") {
  // tests/campaign/data/raw_campaign.ini states 20 replicates x 200 samples; without the section
  // its raw-data line gets the default, 200 replicates x min(300, 1000) samples.
  const ScratchDirectory scratch("check_bootstrap");
  const std::string raw = std::string(GROWTHUQ_SOURCE_DIR) + "/tests/campaign/data/raw_campaign.ini";
  const CliOutcome stated = run_cli("check " + raw + " --out planned", scratch.root);
  REQUIRE(stated.exit_code == 0);
  // The curve fits (seconds) are no silent wait: their progress on stderr, as the run gives it;
  // --quiet silences it.
  // (find, not starts_with: on a loaded machine a slower step may print its progress first)
  CHECK(stated.err.find("fitting relaxation curves of line wild_type: 22 curves in ") != std::string::npos);
  CHECK(run_cli("check " + raw + " --out planned --quiet", scratch.root).err.empty());
  // 20 x 200 = 4000 samples per line, 4000 / 300 = 13.3 times the run's.
  CHECK(stated.out.find("data uncertainty: a bootstrap of 20 replicates x 200 samples per line (each refits the raw-data laws): "
                        "4000 more samples per line, 13.3 times the run's own ([data_uncertainty] replicates = 0 switches it off)\n") !=
        std::string::npos);
  // One raw-data line: the bootstrap's table, but no line comparisons (they need two).
  CHECK(stated.out.find("results in planned: summary.csv, sensitivity.csv, provenance.json, samples.csv, results.h5, data_uncertainty.csv\n") != std::string::npos);
  const CliOutcome three = run_cli("check " + std::string(GROWTHUQ_SOURCE_DIR) + "/tests/campaign/data/raw_comparisons.ini --out planned",
                                   scratch.root);
  REQUIRE(three.exit_code == 0);
  CHECK(three.out.find(", data_uncertainty.csv, comparisons.csv, letters.csv\n") != std::string::npos);
  std::string text = slurp(raw);
  const std::string section = "[data_uncertainty]\nreplicates = 20\nsamples = 200\n";
  REQUIRE(text.find(section) != std::string::npos);
  text.replace(text.find(section), section.size(), "");
  // Its relative paths made absolute, so the copy can live in the scratch folder.
  for (std::size_t at = text.find("../../../"); at != std::string::npos; at = text.find("../../../", at)) {
    text.replace(at, 9, std::string(GROWTHUQ_SOURCE_DIR) + "/");
  }
  spit(scratch.root / "by_default.ini", text);
  const CliOutcome defaulted = run_cli("check by_default.ini --out planned", scratch.root);
  REQUIRE(defaulted.exit_code == 0);
  CHECK(defaulted.out.find("data uncertainty: a bootstrap of 200 replicates x 300 samples per line (each refits the raw-data laws): "
                           "60000 more samples per line, 200 times the run's own") != std::string::npos);
}

TEST_CASE("growthuq check fails where the run fails, with the run's message, and writes nothing") {
  const ScratchDirectory scratch("check_errors");
  fs::create_directories(scratch.root / "exists");
  spit(scratch.root / "broken.ini", "[campaign]\nname = b\nseed = 1\nsamples = 10\noutputs = p\noutput_dir = o\n"
                                     "[instrument]\nprobe_radius_um = 0.5\n[line a]\ndistributions = missing.ini\n");
  for (const std::string& flags : {small + " --out exists", small + " --out fresh --samples 0", small + " --out fresh --lines nope",
                                  small + " --out fresh --samples 4000000000", std::string("broken.ini")}) {
    CAPTURE(flags);
    const CliOutcome check = run_cli("check " + flags, scratch.root);
    const CliOutcome run = run_cli("run --quiet " + flags, scratch.root);
    CHECK(check.exit_code == 2);
    CHECK(run.exit_code == 2);
    CHECK(without_available_memory(as_run(check.err)) == without_available_memory(run.err));
    CHECK(check.out.empty());
    CHECK_FALSE(fs::exists(scratch.root / "fresh"));
  }
  // --force accepts an existing output directory, as it does for the run.
  CHECK(run_cli("check " + small + " --out exists --force", scratch.root).exit_code == 0);
}

TEST_CASE("run --summary-only prints the full run's stdout up to the per-line reports") {
  const ScratchDirectory scratch("summary_only");
  const CliOutcome full = run_cli("run " + small + " --out full --quiet --samples 60", scratch.root);
  const CliOutcome brief = run_cli("run " + small + " --out brief --quiet --samples 60 --summary-only", scratch.root);
  REQUIRE(full.exit_code == 0);
  REQUIRE(brief.exit_code == 0);
  const std::size_t reports = full.out.find("\nline wild_type: input rank correlation");
  REQUIRE(reports != std::string::npos);
  // The header names the output directory, which differs.
  const auto after_header = [](const std::string& text) { return text.substr(text.find('\n')); };
  CHECK(after_header(brief.out) == after_header(full.out.substr(0, reports)) + "\n(per-line reports not printed: --summary-only)\n");
  // The result files are the same.
  CHECK(slurp(scratch.root / "brief" / "summary.csv") == slurp(scratch.root / "full" / "summary.csv"));
  CHECK(slurp(scratch.root / "brief" / "samples.csv") == slurp(scratch.root / "full" / "samples.csv"));
}
