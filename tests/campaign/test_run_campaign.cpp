// The library's front door: Campaign::validate on campaigns built in code, and run_campaign /
// resume_campaign with their RunSummary, in process (the CLI's `growthuq run` is tested as a
// command elsewhere).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/run_campaign.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/pool/pool.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

// One line of turgor only: k uniform on [1.5, 2.5] N/m, d and d0 uniform on narrow ranges.
Campaign small_campaign(const fs::path& folder, std::size_t samples) {
  const std::string made_up = "source = illustrative\nnote = a tube made up for this test\n";
  std::ofstream(folder / "tube.ini") << "[line]\nname = tube\n[k]\nlaw = uniform\nlower = 1.5\nupper = 2.5\nunit = N/m\n" +
                                            made_up + "[d]\nlaw = uniform\nlower = 9.9\nupper = 10.1\nunit = um\n" + made_up +
                                            "[d0]\nlaw = uniform\nlower = 9.2\nupper = 9.4\nunit = um\n" + made_up;
  const std::string text = "[campaign]\nname = small\nseed = 11\nsamples = " + std::to_string(samples) +
                           "\noutputs = p\nchunk_size = 16\noutput_dir = " + (folder / "results").string() +
                           "\nformats = csv\n[instrument]\nprobe_radius_um = 0.5\n"
                           "[line tube]\ndistributions = tube.ini\nrank_correlation = none\n";
  return parse_campaign(text, (folder / "small.ini").string());
}

std::string problem_of(const Campaign& campaign) {
  try {
    campaign.validate();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("Campaign::validate names the first problem of a campaign changed in code") {
  const ScratchDirectory scratch("validate_campaign");
  const Campaign valid = small_campaign(scratch.root, 40);
  const std::string path = (scratch.root / "small.ini").string();
  CHECK(problem_of(valid).empty());

  Campaign twice = valid;
  twice.lines.push_back(twice.lines.front());
  CHECK(problem_of(twice) == path + ":" + std::to_string(valid.lines.front().line) + ": line 'tube' repeats");

  Campaign no_samples = valid;
  no_samples.samples = 0;
  CHECK(problem_of(no_samples) == path + ": samples = '0': expected a whole number from 1 to 4294967295");

  Campaign unknown = valid;
  unknown.outputs = {"p", "turgor"};
  CHECK(problem_of(unknown).starts_with(path + ": outputs = 'turgor': expected quantities among "));

  Campaign growth = valid;
  growth.outputs = {"p", "v"};
  CHECK(problem_of(growth) == path + ": output v needs [growth] reference_line: the line whose experimental growth rate "
                                     "calibrates kappa");
  growth.reference_line = "mutant";
  CHECK(problem_of(growth) == path + ": [growth] reference_line = 'mutant': expected one of the campaign's lines");

  Campaign nowhere = valid;
  nowhere.output_dir.clear();
  CHECK(problem_of(nowhere).starts_with(path + ": output_dir = '': expected "));
  Campaign no_lines = valid;
  no_lines.lines.clear();
  CHECK(problem_of(no_lines) == path + ": no [line NAME] section: a campaign needs at least one plant line");

  // run_campaign validates before anything is written.
  const auto pool = make_serial_pool();
  CHECK_THROWS_AS(run_campaign(no_samples, *pool, RunOptions{}), InputError);
  CHECK_FALSE(fs::exists(scratch.root / "results"));
}

TEST_CASE("run_campaign returns the summary.csv rows and reports them; an existing output is replaced only when asked") {
  const ScratchDirectory scratch("run_campaign");
  const Campaign campaign = small_campaign(scratch.root, 200);
  const auto pool = make_serial_pool();
  RunOptions options;
  options.overrides.samples = 101;  // applied before the run, as --samples
  const RunSummary summary = run_campaign(campaign, *pool, options);
  REQUIRE(summary.completed);
  CHECK(summary.lines == 1);
  CHECK(summary.samples_per_line == 101);
  CHECK_FALSE(summary.calibrated);
  REQUIRE(summary.summaries.size() == 1);
  const QuantitySummary& p = summary.summaries.front();
  CHECK(p.line == "tube");
  CHECK(p.quantity == "p");
  CHECK(p.n + p.n_flagged == 101);
  // The summary is summary.csv's row: its median is the file's.
  const std::string csv = slurp(scratch.root / "results" / "summary.csv");
  CHECK(csv.find("tube,p,MPa,") != std::string::npos);
  CHECK(summary.brief_report().starts_with("campaign 'small': 1 line x 101 samples run in "));
  CHECK(summary.brief_report().ends_with(", results in " + (scratch.root / "results").string()));
  CHECK(summary.brief_report().find('\n') == std::string::npos);
  const std::string full = summary.full_report();
  CHECK(full.starts_with(summary.brief_report() + "\n"));
  CHECK(full.find("  tube  p [MPa]  ") != std::string::npos);
  CHECK(full.find("time of this process [s]: design ") != std::string::npos);

  // Results are never replaced unasked; with Overwrite::allow they are, identically.
  CHECK_THROWS_AS(run_campaign(campaign, *pool, options), InputError);
  options.overwrite = Overwrite::allow;
  const RunSummary again = run_campaign(campaign, *pool, options);
  REQUIRE(again.completed);
  CHECK(slurp(scratch.root / "results" / "summary.csv") == csv);
}

TEST_CASE("a run stopped by its pool says so in its summary, and resume_campaign finishes it as one run") {
  const ScratchDirectory scratch("run_campaign_stop");
  const Campaign campaign = small_campaign(scratch.root, 160);
  const auto pool = make_serial_pool();
  const RunSummary whole = run_campaign(campaign, *pool, RunOptions{});
  REQUIRE(whole.completed);
  const std::string csv = slurp(scratch.root / "results" / "summary.csv");
  fs::remove_all(scratch.root / "results");

  // The pool asks to stop (reason 15, as SIGTERM would): no result file, the checkpoint kept.
  pool->stop_when([] { return 15; });
  const RunSummary stopped = run_campaign(campaign, *pool, RunOptions{});
  pool->stop_when({});
  CHECK_FALSE(stopped.completed);
  CHECK(stopped.stop_reason == 15);
  CHECK(stopped.stop_message.find("growthuq run --resume " + (scratch.root / "results").string()) != std::string::npos);
  CHECK(stopped.brief_report() == stopped.stop_message);
  CHECK_FALSE(fs::exists(scratch.root / "results" / "summary.csv"));

  RunOptions changed;
  changed.overrides.seed = 12;
  CHECK_THROWS_AS(resume_campaign((scratch.root / "results").string(), *pool, changed), InputError);
  const RunSummary resumed = resume_campaign((scratch.root / "results").string(), *pool, RunOptions{});
  REQUIRE(resumed.completed);
  CHECK(resumed.resumed);
  CHECK(slurp(scratch.root / "results" / "summary.csv") == csv);
}
