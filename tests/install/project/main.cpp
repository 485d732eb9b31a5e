// A program using the installed library: the thin-shell turgor inverse, a lognormal law and a
// small campaign run through run_campaign, each checked against values computed here
// independently. Exit 0 when all agree.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/run_campaign.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/distributions/lognormal.hpp"
#include "growthuq/mechanics/thin_shell.hpp"
#include "growthuq/pool/pool.hpp"

namespace {

// A campaign of one line, 101 samples of the turgor p: k uniform on [1.5, 2.5] N/m, d and d0
// within 1e-6 um of 10 and 9.3 um, so that p = c k with c the thin-shell factor of the tube
// above (relative spread of c below 1e-6). Latin hypercube strata put exactly one sample of k
// in each of the 101 equal slices of [1.5, 2.5]; the sample median is the 51st, in the middle
// slice [1.5 + 50/101, 1.5 + 51/101] N/m, so its p lies in c times that slice. The files go to
// `directory` (emptied). Returns the number of failed checks.
int check_campaign(double c, const std::filesystem::path& directory) {
  namespace fs = std::filesystem;
  fs::remove_all(directory);
  fs::create_directories(directory);
  const std::string made_up = "source = illustrative\nnote = a tube made up for this check\n";
  std::ofstream(directory / "tube.ini") << "[line]\nname = tube\n[k]\nlaw = uniform\nlower = 1.5\nupper = 2.5\nunit = N/m\n" +
                                               made_up + "[d]\nlaw = uniform\nlower = 9.999999\nupper = 10.000001\nunit = um\n" +
                                               made_up + "[d0]\nlaw = uniform\nlower = 9.299999\nupper = 9.300001\nunit = um\n" +
                                               made_up;
  const std::string text = "[campaign]\nname = outside\nseed = 7\nsamples = 101\noutputs = p\noutput_dir = " +
                           (directory / "results").string() +
                           "\nformats = csv\n[instrument]\nprobe_radius_um = 0.5\npoisson_ratio = 0.2\n"
                           "[line tube]\ndistributions = tube.ini\nrank_correlation = none\n";
  const growthuq::Campaign campaign = growthuq::parse_campaign(text, (directory / "outside.ini").string());
  const auto pool = growthuq::make_serial_pool();
  const growthuq::RunSummary summary = growthuq::run_campaign(campaign, *pool, growthuq::RunOptions{});
  std::printf("run_campaign: %s\n", summary.brief_report().c_str());
  int failures = 0;
  if (!summary.completed || summary.summaries.size() != 1 || !fs::exists(directory / "results" / "summary.csv")) return 1;
  const growthuq::QuantitySummary& p = summary.summaries.front();
  const double low = c * (1.5 + 50.0 / 101) * (1 - 1e-5) * 1e-6, high = c * (1.5 + 51.0 / 101) * (1 + 1e-5) * 1e-6;
  std::printf("campaign median p %.17g MPa, expected within [%.17g, %.17g] MPa; n %zu, flagged %zu\n", p.median, low, high,
              p.n, p.n_flagged);
  if (p.quantity != "p" || p.unit != "MPa" || p.n != 101 || p.n_flagged != 0 || !(p.median >= low && p.median <= high)) {
    ++failures;
  }
  // The results are never replaced unasked: a second run into the same directory is refused.
  try {
    growthuq::run_campaign(campaign, *pool, growthuq::RunOptions{});
    std::printf("a second run replaced the results without being asked\n");
    ++failures;
  } catch (const growthuq::InputError& error) {
    std::printf("second run refused: %s\n", error.what());
  }
  return failures;
}

}  // namespace

// argv[1]: the folder for the campaign's files (default: one in the system's temporary folder).
int main(int argc, char** argv) {
  int failures = 0;

  // Turgor of a tube of stiffness k = 2 N/m, d = 10 um, d0 = 9.3 um under a 0.5 um probe,
  // nu = 0.2, ideal sensor. Reference: the closed form the header states,
  //   lambda = d/d0, q = (1 - nu^2) ln lambda, alpha = d sqrt(3q / (16 (1 - q))),
  //   phi = x K1(x) / K0(x) with x = rho / alpha, p = 4 k / (3 pi d phi),
  // with the Bessel functions of the C++ standard library (the engine uses GSL's). The two
  // Bessel implementations agree to about 1e-14 relative here; 1e-10 leaves room for either and
  // still catches any wrong term (a unit or factor error is of order 1).
  const double k = 2.0, d = 10e-6, d0 = 9.3e-6, rho = 0.5e-6, nu = 0.2;
  growthuq::Instrument instrument;
  instrument.probe_radius_m = rho;
  instrument.poisson_ratio = nu;
  const growthuq::TurgorResult turgor = growthuq::invert_turgor(k, d, d0, instrument);

  const double q = (1 - nu * nu) * std::log(d / d0);
  const double alpha = d * std::sqrt(3 * q / (16 * (1 - q)));
  const double x = rho / alpha;
  const double phi = x * std::cyl_bessel_k(1.0, x) / std::cyl_bessel_k(0.0, x);
  const double p_reference = 4 * k / (3 * std::numbers::pi * d * phi);
  const double p_error = std::abs(turgor.p - p_reference) / p_reference;
  std::printf("turgor: %.17g Pa, reference %.17g Pa, relative difference %.2g\n", turgor.p, p_reference, p_error);
  if (turgor.status != growthuq::SampleStatus::ok || !(p_error < 1e-10)) ++failures;

  // A lognormal given by median 4 and IQR 3: its quartiles must be 3 apart and its median 4;
  // quantiles are accurate to a few ulp, so 1e-12 relative is ample.
  const auto law = growthuq::Lognormal::from_median_iqr(4.0, 3.0);
  const double iqr = growthuq::quantile(law, 0.75) - growthuq::quantile(law, 0.25);
  const double median = growthuq::quantile(law, 0.5);
  std::printf("lognormal: median %.17g, IQR %.17g\n", median, iqr);
  if (!(std::abs(median - 4.0) < 4e-12 && std::abs(iqr - 3.0) < 3e-12)) ++failures;

  // The campaign's p per unit k, from the reference above (p_reference is for k = 2 N/m).
  try {
    failures += check_campaign(p_reference / k, argc > 1 ? std::filesystem::path(argv[1])
                                                     : std::filesystem::temp_directory_path() / "growthuq_outside_campaign");
  } catch (const std::exception& error) {
    std::printf("run_campaign failed: %s\n", error.what());
    ++failures;
  }

  return failures == 0 ? 0 : 1;
}
