// A campaign presents no infinite value as a result: a line file whose law would draw inf is
// refused at its section, and a line whose values are too large for their statistics in double
// precision (an sd that overflows) fails the run naming the line, quantity and statistic; in
// both cases the run leaves no output directory and no result file behind.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::string campaign_text =
    "[campaign]\nname = finite\nseed = 1\nsamples = 50\noutputs = p, E\noutput_dir = out\nformats = csv, hdf5\n\n"
    "[instrument]\nprobe_radius_um = 0.5\npoisson_ratio = 0.2\n\n[line thin]\ndistributions = line.ini\n";

// k, d, d0 as published for the wild type; h as given.
std::string line_text(const std::string& k_law, const std::string& h_law) {
  return "[line]\nname = thin\n\n[k]\n" + k_law + "unit = N/m\nsource = illustrative\nnote = test\n\n" +
         "[d]\nlaw = lognormal\nmedian = 6.56\niqr = 1.19\nunit = um\nsource = illustrative\nnote = test\n\n" +
         "[d0]\nlaw = lognormal\nmedian = 5.35\niqr = 0.5\nunit = um\nsource = illustrative\nnote = test\n\n" +
         "[h]\n" + h_law + "unit = nm\nsource = illustrative\nnote = test\n";
}

const std::string k_published = "law = lognormal\nmedian = 2.87\niqr = 0.83\n";
const std::string h_published = "law = lognormal\nmedian = 145\niqr = 31\n";

}  // namespace

TEST_CASE("a campaign line whose law would draw inf is refused before anything is written") {
  const ScratchDirectory scratch("campaign_sigma");
  spit(scratch.root / "campaign.ini", campaign_text);
  spit(scratch.root / "line.ini", line_text("law = lognormal\nmu = 1\nsigma = 100\n", h_published));
  const CliOutcome run = run_cli("run campaign.ini --quiet", scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err.find("line.ini:4: [k] law lognormal(mu=1, sigma=100; ") != std::string::npos);
  CHECK(run.err.find(" in N/m: its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is inf: expected a law whose values are finite") !=
        std::string::npos);
  CHECK_FALSE(fs::exists(scratch.root / "out"));
}

TEST_CASE("values too large for their statistics fail the run: no sd = inf, no empty sd cell") {
  // h = e^-438 nm = 1e-190 nm, a representable law, puts E near 1e194 MPa: finite values
  // whose squares overflow double precision, so their sd would be inf.
  const ScratchDirectory scratch("campaign_overflow");
  spit(scratch.root / "campaign.ini", campaign_text);
  spit(scratch.root / "line.ini", line_text(k_published, "law = lognormal\nmu = -438\nsigma = 0.2\n"));
  const CliOutcome run = run_cli("run campaign.ini --quiet", scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err.rfind("growthuq run: error: campaign.ini: line 'thin', E: sd = inf: expected a finite statistic of ", 0) == 0);
  CHECK(run.err.find("values; they are too large for double precision (median ") != std::string::npos);
  CHECK(run.err.find(" MPa): check the line's laws or data\n") != std::string::npos);
  CHECK_FALSE(fs::exists(scratch.root / "out"));

  // The same campaign with an ordinary thickness runs.
  spit(scratch.root / "line.ini", line_text(k_published, h_published));
  const CliOutcome ordinary = run_cli("run campaign.ini --quiet", scratch.root);
  INFO(ordinary.err);
  CHECK(ordinary.exit_code == 0);
  CHECK(fs::exists(scratch.root / "out" / "results.h5"));
}
