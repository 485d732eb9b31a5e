// [audit] as `growthuq check` sees it (tests/campaign/data/audit_campaign.ini): the plan states the
// audit's finite-element samples and their time; a count that is negative, 1 or 2, above the
// campaign's samples, or an audit of a campaign whose every line is at shell_fe gets one line
// naming the file, line and key, and exit status 2; samples = 0 is no audit.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

// The test campaign with `from` replaced by `to`, checked in `scratch`.
CliOutcome check_with(const ScratchDirectory& scratch, const std::string& from, const std::string& to) {
  const std::string source = std::string(GROWTHUQ_SOURCE_DIR);
  std::string text = slurp(source + "/tests/campaign/data/audit_campaign.ini");
  text.replace(text.find("../../../distributions/"), 23, source + "/distributions/");
  text.replace(text.find(from), from.size(), to);
  spit(scratch.root / "audited.ini", text);
  return run_in(scratch.root, cli({"check", "audited.ini", "--quiet"}));
}

bool one_line(const std::string& text) { return !text.empty() && text.find('\n') == text.size() - 1; }

}  // namespace

TEST_CASE("campaign audit: check states its samples and time; bad counts and a shell_fe campaign get one line") {
  ScratchDirectory scratch("campaign_audit_input");
  const CliOutcome plan = check_with(scratch, "samples = 4", "samples = 4");
  REQUIRE_MESSAGE(plan.exit_code == 0, plan.err);
  CHECK(plan.out.find("audit: the first 4 samples of 1 line(s) through shell_fe too (mesh coarse): 4 finite-element samples") !=
        std::string::npos);
  // A closed-form campaign's time is the audit's alone.
  CHECK(plan.out.find("time: fidelity shell_fe, 4 finite-element samples x about") != std::string::npos);
  CHECK(plan.out.find("4 of the samples are the audit's") != std::string::npos);
  CHECK(plan.out.find(", audit.csv") != std::string::npos);
  CHECK_FALSE(fs::exists(scratch.root / "audit_out"));

  const CliOutcome off = check_with(scratch, "samples = 4", "samples = 0");
  REQUIRE_MESSAGE(off.exit_code == 0, off.err);
  CHECK(off.out.find("audit: none") != std::string::npos);
  CHECK(off.out.find("audit's") == std::string::npos);

  struct Case {
    std::string from, to, message;
  };
  const Case cases[] = {
      {"samples = 4", "samples = -1", "audited.ini:19: samples = '-1': expected a whole number from 0 to"},
      {"samples = 4", "samples = 2", "audited.ini:19: samples = '2': expected 0 (no audit) or at least 3"},
      {"samples = 4", "samples = 13", "audited.ini:19: [audit] samples = 13: expected at most the campaign's 12 samples per line"},
      {"formats = csv", "formats = csv\nfidelity = shell_fe", "every line runs at fidelity shell_fe"},
  };
  for (const Case& bad : cases) {
    CAPTURE(bad.to);
    const CliOutcome outcome = check_with(scratch, bad.from, bad.to);
    CHECK(outcome.exit_code == 2);
    CHECK(one_line(outcome.err));
    CHECK_MESSAGE(outcome.err.find(bad.message) != std::string::npos, outcome.err);
  }
}
