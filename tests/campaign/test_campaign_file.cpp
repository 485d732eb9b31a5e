// Campaign files: the values read, relative paths, overrides, and one clear error per mistake.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/core/error.hpp"
#include "support/campaign_text.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::string valid =
    "[campaign]\nname = test\nseed = 7\nsamples = 300\noutputs = p, E, eta, v\noutput_dir = out/test\n"
    "[instrument]\nprobe_radius_um = 0.5\n"
    "[growth]\nyield_pressure_MPa = 0.1\nreference_line = wt\n"
    "[line wt]\ndistributions = lines/wt.ini\nrank_correlation = physics\n"
    "[line m1]\ndistributions = lines/m1.ini\nrank_correlation = lines/matrix.csv\n";

}  // namespace

TEST_CASE("a valid campaign is read with SI values and resolved paths") {
  const CampaignFolder folder("campaign", {"lines/wt.ini", "lines/m1.ini", "lines/matrix.csv", "lines/raw.ini"});
  const Campaign campaign = parse_campaign(valid, folder.path());
  CHECK(campaign.name == "test");
  CHECK(campaign.seed == 7);
  CHECK(campaign.samples == 300);
  CHECK(campaign.outputs == std::vector<std::string>{"p", "E", "eta", "v"});
  CHECK(campaign.instrument.probe_radius_m == doctest::Approx(0.5e-6).epsilon(1e-15));
  CHECK(campaign.instrument.poisson_ratio == 0.2);
  CHECK(std::isinf(campaign.instrument.sensor_stiffness_N_per_m));
  CHECK(campaign.yield_pressure == doctest::Approx(1e5).epsilon(1e-15));
  CHECK(campaign.formats.csv);
  CHECK(campaign.formats.hdf5);
  REQUIRE(campaign.lines.size() == 2);
  CHECK(campaign.lines[0].correlation == CorrelationSource::physics);
  CHECK(campaign.lines[1].correlation == CorrelationSource::file);
  CHECK(fs::equivalent(campaign.lines[1].correlation_path, folder.root / "lines/matrix.csv"));
  CHECK(fs::equivalent(campaign.lines[0].distributions_path, folder.root / "lines/wt.ini"));
}

TEST_CASE("command-line overrides") {
  const CampaignFolder folder("campaign", {"lines/wt.ini", "lines/m1.ini", "lines/matrix.csv", "lines/raw.ini"});
  Campaign campaign = parse_campaign(valid, folder.path());
  apply_overrides(campaign, {.samples = 50, .seed = 9, .output_dir = "elsewhere", .lines = "wt", .formats = "hdf5"});
  CHECK(campaign.samples == 50);
  CHECK(campaign.seed == 9);
  CHECK(campaign.output_dir == "elsewhere");
  REQUIRE(campaign.lines.size() == 1);
  CHECK(campaign.lines[0].name == "wt");
  CHECK_FALSE(campaign.formats.csv);
  CHECK(campaign.formats.hdf5);
  Campaign other = parse_campaign(valid, folder.path());
  CHECK_THROWS_WITH_AS(apply_overrides(other, {.lines = "m1"}),
                       "command line: --lines = 'm1': expected a selection that keeps the reference line 'wt' (it calibrates kappa)",
                       InputError);
  CHECK_THROWS_AS(apply_overrides(other, {.lines = "nope"}), InputError);
  CHECK_THROWS_AS(apply_overrides(other, {.formats = "xlsx"}), InputError);
}

TEST_CASE("each mistake is one error naming file and line") {
  const CampaignFolder folder("campaign", {"lines/wt.ini", "lines/m1.ini", "lines/matrix.csv", "lines/raw.ini"});
  const std::string file = folder.path();
  const auto error_of = [&](const std::string& text) { return parse_error(text, file); };
  CHECK(error_of(replaced(valid, "seed = 7", "seed = -7")) == file + ":3: seed = '-7': expected a whole number from 0 to 18446744073709551615");
  CHECK(error_of(replaced(valid, "samples = 300", "samples = 0")) == file + ":4: samples = '0': expected a whole number from 1 to 4294967295");
  CHECK(error_of(replaced(valid, "outputs = p, E, eta, v", "outputs = p, turgor")).starts_with(file + ":5: outputs = 'turgor': expected quantities among k, h"));
  CHECK(error_of(replaced(valid, "probe_radius_um = 0.5", "probe_radius_um = -1")) == file + ":8: probe_radius_um = '-1': expected a probe radius in um, > 0 and at most 1000");
  // The instrument keys take exactly the values and give the messages of --rho-um, --nu, --k-sys
  // (mechanics/instrument.hpp): nu = 0.5 and 0.7 were accepted here before, like any nu in [0, 1).
  for (const char* nu : {"0.5", "0.7", "-0.1", "nan"}) {
    CHECK(error_of(replaced(valid, "probe_radius_um = 0.5", "probe_radius_um = 0.5\npoisson_ratio = " + std::string(nu))) ==
          file + ":9: poisson_ratio = '" + nu + "': expected a Poisson ratio in [0, 0.5)");
  }
  CHECK(error_of(replaced(valid, "probe_radius_um = 0.5", "probe_radius_um = 0.5\nsensor_stiffness_N_per_m = 0")) ==
        file + ":9: sensor_stiffness_N_per_m = '0': expected a sensor stiffness in N/m, a number > 0 or inf (an ideal sensor)");
  CHECK(error_of(replaced(valid, "probe_radius_um = 0.5", "probe_radius = 0.5")) ==
        file + ":8: unknown key 'probe_radius' in [instrument] (allowed: probe_radius_um, poisson_ratio, sensor_stiffness_N_per_m)");
  CHECK(error_of(replaced(valid, "probe_radius_um = 0.5", "poisson_ratio = 0.2")) ==
        file + ": [instrument] probe_radius_um is required (it dominates turgor), or a [probe_radius] section with a law of "
               "it where the study does not know it");
  CHECK(error_of(replaced(valid, "yield_pressure_MPa = 0.1", "yield_presure_MPa = 0.1")) == file + ":10: unknown key 'yield_presure_MPa' in [growth] (allowed: yield_pressure_MPa, reference_line)");
  CHECK(error_of(replaced(valid, "lines/m1.ini", "lines/missing.ini")).starts_with(file + ":16: distributions = 'lines/missing.ini': expected an existing file"));
  CHECK(error_of(replaced(valid, "reference_line = wt", "reference_line = col0")) == file + ": [growth] reference_line = 'col0': expected one of the campaign's lines");
  CHECK(error_of(replaced(valid, "[line m1]", "[line  wt]")) == file + ":15: line 'wt' repeats");
  // [sensitivity] (src/campaign/sensitivity_settings.hpp): one message naming file:line, key, value, expectation.
  CHECK(error_of(valid + "[sensitivity]\nmethod = jansen\n") == file + ":19: method = 'jansen': expected first_order, shapley or sobol");
  CHECK(error_of(valid + "[sensitivity]\nmethod = shapley\ninner = 1\n").starts_with(file + ":20: inner = '1': expected "));
  CHECK(error_of(valid + "[sensitivity]\nouter_draws = 5\n") == file + ":19: unknown key 'outer_draws' in [sensitivity] (allowed: method, outer, inner, permutations, variance_samples, sobol_samples)");
  CHECK(error_of(replaced(valid, "[growth]", "[grow]")) == file + ":9: unknown section [grow] (expected [campaign], [instrument], [probe_radius], [growth], [physics_correlation], [data_uncertainty], [shell_fe], [audit], [sensitivity] or [line NAME])");
  CHECK(error_of(replaced(valid, "reference_line = wt\n", "")) == file + ": output v needs [growth] reference_line: the line whose experimental growth rate calibrates kappa");
  CHECK(error_of(replaced(valid, "[instrument]\nprobe_radius_um = 0.5\n", "")) == file + ": no [instrument] section: probe_radius_um is required (it dominates turgor)");
  CHECK(error_of(valid + "[physics_correlation]\np_MPa = 0.8:0.1\n") == file + ":19: p_MPa = '0.8:0.1': expected a range 'low:high' with 0 < low < high");
  CHECK(error_of(replaced(valid, "output_dir = out/test", "output_dir = out/test\nformats = pdf")) == file + ":7: formats = 'pdf': expected csv, hdf5 or csv,hdf5");
}

TEST_CASE("a line comes from exactly one of a line file and raw data; the data bootstrap's section") {
  const CampaignFolder folder("campaign", {"lines/wt.ini", "lines/m1.ini", "lines/matrix.csv", "lines/raw.ini"});
  const std::string file = folder.path();
  const std::string raw = replaced(valid, "[line m1]\ndistributions = lines/m1.ini", "[line m1]\nraw = lines/raw.ini");
  const Campaign campaign = parse_campaign(raw + "[data_uncertainty]\nreplicates = 200\nsamples = 500\n", file);
  REQUIRE(campaign.lines.size() == 2);
  CHECK(campaign.lines[1].distributions_path.empty());
  CHECK(fs::equivalent(campaign.lines[1].raw_path, folder.root / "lines/raw.ini"));
  CHECK(campaign.lines[0].raw_path.empty());
  CHECK(campaign.data_uncertainty.replicates == 200);
  CHECK(campaign.data_uncertainty.samples == 500);
  // Without the section a campaign with a raw-data line gets the default bootstrap, one without
  // none; --lines leaving no raw-data line drops the default but keeps a stated count.
  const Campaign defaulted = parse_campaign(raw, file);
  CHECK(defaulted.data_uncertainty.replicates == DataUncertaintySettings::default_replicates);
  CHECK(DataUncertaintySettings::default_replicates == 200);
  CHECK(data_uncertainty_samples(defaulted) == 300);  // the campaign's 300 samples (below the cap of 1000)
  CHECK(parse_campaign(valid, file).data_uncertainty.replicates == 0);
  CHECK(parse_campaign(raw + "[data_uncertainty]\nreplicates = 0\n", file).data_uncertainty.replicates == 0);
  Campaign large = defaulted;
  apply_overrides(large, {.samples = 50000});
  CHECK(data_uncertainty_samples(large) == 1000);
  CHECK(data_uncertainty_samples(campaign) == 500);
  Campaign distributions_only = defaulted;
  apply_overrides(distributions_only, {.lines = "wt"});
  CHECK(distributions_only.data_uncertainty.replicates == 0);
  Campaign stated = parse_campaign(raw + "[data_uncertainty]\nreplicates = 30\n", file);
  apply_overrides(stated, {.lines = "wt"});
  CHECK(stated.data_uncertainty.replicates == 30);

  const auto error_of = [&](const std::string& text) { return parse_error(text, file); };
  CHECK(error_of(replaced(raw, "raw = lines/raw.ini", "raw = lines/raw.ini\ndistributions = lines/m1.ini")) ==
        file + ":15: [line m1] needs exactly one of 'distributions = <line file>' and 'raw = <raw data file>' (both are given)");
  CHECK(error_of(replaced(raw, "raw = lines/raw.ini\n", "")) ==
        file + ":15: [line m1] needs exactly one of 'distributions = <line file>' and 'raw = <raw data file>'");
  CHECK(error_of(replaced(raw, "lines/raw.ini", "lines/none.ini")).starts_with(file + ":16: raw = 'lines/none.ini': expected an existing file"));
  // Without raw data the section is read: line files may state tubes, and whether one does is
  // checked when they are read (test_stated_tubes.cpp).
  CHECK(parse_campaign(valid + "[data_uncertainty]\nreplicates = 10\n", file).data_uncertainty.replicates == 10);
  const Campaign samples_only = parse_campaign(raw + "[data_uncertainty]\nsamples = 10\n", file);
  CHECK(samples_only.data_uncertainty.replicates == DataUncertaintySettings::default_replicates);
  CHECK(data_uncertainty_samples(samples_only) == 10);
  CHECK(error_of(raw + "[data_uncertainty]\nreplicates = 10\nsamples = 5\n") ==
        file + ":20: samples = '5': expected a whole number from 10 to 10000000");
}

TEST_CASE("a list item given twice and an empty required value are errors, not silently doubled or empty") {
  const CampaignFolder folder("campaign", {"lines/wt.ini", "lines/m1.ini", "lines/matrix.csv", "lines/raw.ini"});
  const std::string file = folder.path();
  const auto error_of = [&](const std::string& text) { return parse_error(text, file); };
  // outputs = p, p would give two summary rows of p.
  CHECK(error_of(replaced(valid, "outputs = p, E, eta, v", "outputs = p, E, p")) ==
        file + ":5: outputs = 'p, E, p': expected each item once ('p' is listed twice)");
  CHECK(error_of(replaced(valid, "output_dir = out/test", "output_dir = out/test\nformats = csv, csv")) ==
        file + ":7: formats = 'csv, csv': expected each item once ('csv' is listed twice)");
  // name = (empty) made a nameless campaign, output_dir = (empty) the current folder.
  CHECK(error_of(replaced(valid, "name = test", "name =")) == file + ":2: name = '': expected a value (it is required)");
  CHECK(error_of(replaced(valid, "output_dir = out/test", "output_dir = ")) ==
        file + ":6: output_dir = '': expected a value (it is required)");
  // --lines wt,wt ran the line twice into the same files.
  Campaign campaign = parse_campaign(valid, file);
  CHECK_THROWS_WITH_AS(apply_overrides(campaign, {.lines = "wt, m1,wt"}),
                       "command line: --lines = 'wt, m1,wt': expected each item once ('wt' is listed twice)", InputError);
  // The same list without the repeat is taken as given.
  apply_overrides(campaign, {.lines = "wt, m1"});
  CHECK(campaign.lines.size() == 2);
}
