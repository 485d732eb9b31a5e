// [probe_radius]: a law of the probe radius, drawn per sample (campaigns/README.md, "An unknown
// probe radius"). Each sample's turgor is checked against the Arnoldi relation written out here
// with that sample's rho (Eqs. M2-M10, src/mechanics/README.md; Bessel functions from the
// standard library), and the campaign's refusals name the file, the line and what is expected.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/campaign/prepared_campaign.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/fidelity/fidelity.hpp"
#include "growthuq/pool/pool.hpp"
#include "campaign/provenance.hpp"
#include "support/campaign_text.hpp"
#include "support/scratch_directory.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

constexpr const char* made_up = "source = illustrative\nnote = a tube made up for this test\n";

// One line of turgor only, k, d and d0 on narrow uniform laws under the physics rank correlation
// (drawn at one radius: the law's median); `instrument` is the text of the
// campaign's probe radius ([instrument] and, or, [probe_radius]).
std::string campaign_text(const fs::path& folder, const std::string& instrument) {
  std::ofstream(folder / "tube.ini") << "[line]\nname = tube\n[k]\nlaw = uniform\nlower = 1.5\nupper = 2.5\nunit = N/m\n"
                                     << made_up << "[d]\nlaw = uniform\nlower = 6.4\nupper = 6.6\nunit = um\n" << made_up
                                     << "[d0]\nlaw = uniform\nlower = 5.3\nupper = 5.4\nunit = um\n" << made_up;
  return "[campaign]\nname = rho\nseed = 5\nsamples = 200\noutputs = p\noutput_dir = " + (folder / "results").string() +
         "\nformats = csv\n" + instrument + "[line tube]\ndistributions = tube.ini\nrank_correlation = physics\n";
}

constexpr const char* law_text =
    "[instrument]\npoisson_ratio = 0.2\n"
    "[probe_radius]\nlaw = uniform\nlower = 0.25\nupper = 1.7\nunit = um\nsource = the range the study's driver admits\n";

// Every column of each finished line, in its unit, keyed by quantity.
class ColumnObserver final : public RunObserver {
 public:
  void line_started(const PreparedLine&, std::size_t) override {}
  void chunk_done(ChunkRange) override {}
  void line_done(const LineResult& result, const std::vector<std::string>&) override {
    for (const ResultColumn& column : result.columns) {
      columns[column.quantity] = std::vector<double>(column.values.begin(), column.values.end());
      to_si[column.quantity] = column.unit->to_si;
    }
  }
  std::map<std::string, std::vector<double>> columns;
  std::map<std::string, double> to_si;
};

ColumnObserver run_columns(const Campaign& campaign) {
  const PreparedCampaign prepared(campaign);
  ColumnObserver observer;
  const std::unique_ptr<Pool> pool = make_serial_pool();
  run_campaign_lines(prepared, *pool, observer);
  return observer;
}

// The closed form's turgor (Eqs. M1-M10) in SI, written out: q = (1 - nu^2) ln(d/d0),
// alpha = d sqrt(3 q / (16 (1 - q))), phi = x K1(x) / K0(x) at x = rho / alpha,
// p = 4 k / (3 pi d phi).
double arnoldi_turgor(double k, double d, double d0, double rho, double nu) {
  const double q = (1.0 - nu * nu) * std::log(d / d0);
  const double alpha = d * std::sqrt(3.0 * q / (16.0 * (1.0 - q)));
  const double x = rho / alpha;
  const double phi = x * std::cyl_bessel_k(1.0, x) / std::cyl_bessel_k(0.0, x);
  return 4.0 * k / (3.0 * std::numbers::pi * d * phi);
}

}  // namespace

TEST_CASE("a law of the probe radius is one more input: each sample's turgor is the Arnoldi relation at its own rho") {
  const ScratchDirectory scratch("probe_radius_law");
  const Campaign campaign = parse_campaign(campaign_text(scratch.root, law_text), (scratch.root / "c.ini").string());
  REQUIRE(campaign.probe_radius_law.has_value());
  CHECK(campaign.instrument.probe_radius_per_sample);
  CHECK(campaign.instrument.probe_radius_m == doctest::Approx(0.975e-6).epsilon(1e-12));  // the law's median

  // The run's provenance states the law beside its median.
  const RunProvenance provenance = run_provenance(PreparedCampaign(campaign));
  CHECK(provenance.probe_radius_um == doctest::Approx(0.975).epsilon(1e-12));
  CHECK(provenance.probe_radius_law.starts_with("uniform("));
  CHECK(provenance.probe_radius_law.ends_with(") um"));
  CHECK(provenance_json(provenance).find("\"probe_radius_law\": \"uniform(") != std::string::npos);

  const ColumnObserver run = run_columns(campaign);
  REQUIRE(run.columns.contains("rho"));
  const std::vector<double>& rho = run.columns.at("rho");
  REQUIRE(rho.size() == 200);
  // Latin hypercube strata of uniform(0.25, 1.7): one draw per 1/200 of the range.
  std::vector<double> sorted = rho;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    CHECK(sorted[i] >= 0.25 + 1.45 * static_cast<double>(i) / 200.0);
    CHECK(sorted[i] <= 0.25 + 1.45 * static_cast<double>(i + 1) / 200.0);
  }
  const auto si = [&](const std::string& quantity, std::size_t i) { return run.columns.at(quantity)[i] * run.to_si.at(quantity); };
  std::size_t checked = 0;
  for (std::size_t i = 0; i < rho.size(); ++i) {
    const double expected = arnoldi_turgor(si("k", i), si("d", i), si("d0", i), si("rho", i), 0.2);
    CHECK(si("p", i) == doctest::Approx(expected).epsilon(1e-9));
    ++checked;
  }
  CHECK(checked == 200);

  // The tubes' columns are those of the same campaign at one radius: the law's column comes last
  // and its stream is its own (line_design.hpp).
  const Campaign fixed = parse_campaign(campaign_text(scratch.root, "[instrument]\nprobe_radius_um = 0.975\n"),
                                        (scratch.root / "c.ini").string());
  const ColumnObserver one_radius = run_columns(fixed);
  CHECK_FALSE(one_radius.columns.contains("rho"));
  for (const char* quantity : {"k", "d", "d0"}) CHECK(one_radius.columns.at(quantity) == run.columns.at(quantity));
}

TEST_CASE("every fidelity's turgor model reads rho per sample when the campaign gives a law of it") {
  Instrument instrument;
  instrument.probe_radius_m = 0.5e-6;
  for (const Fidelity fidelity : {Fidelity::closed_form, Fidelity::corrected, Fidelity::shell_fe}) {
    for (const bool per_sample : {false, true}) {
      instrument.probe_radius_per_sample = per_sample;
      const auto models = turgor_modulus_models(fidelity, instrument, ShellFeOptions{}, "test");
      bool reads_rho = false;
      for (const auto& model : models) {
        for (const std::string& read : model->reads()) reads_rho = reads_rho || read == "rho";
      }
      const std::string name(to_string(fidelity));
      CAPTURE(name);
      CHECK(reads_rho == per_sample);
    }
  }
}

TEST_CASE("the probe radius is given once, as a value or a law whose every draw is a radius") {
  const CampaignFolder folder("probe_radius_refusals", {"tube.ini"});
  const std::string file = folder.path();
  const std::string with_law = campaign_text(folder.root, law_text);
  // Line numbers in with_law: [instrument] at 8, [probe_radius] at 10.
  CHECK(parse_error(replaced(with_law, "poisson_ratio = 0.2\n", "probe_radius_um = 0.5\n"), file) ==
        file + ":10: [probe_radius] and [instrument] probe_radius_um both give the probe radius: expected one of them "
               "(the law for an unknown radius, the key for a known one)");
  CHECK(parse_error(replaced(with_law, "[probe_radius]\nlaw = uniform\nlower = 0.25\nupper = 1.7\nunit = um\n"
                                       "source = the range the study's driver admits\n", ""), file) ==
        file + ": [instrument] probe_radius_um is required (it dominates turgor), or a [probe_radius] section with a "
               "law of it where the study does not know it");
  CHECK(parse_error(replaced(with_law, "law = uniform\nlower = 0.25\nupper = 1.7\nunit = um\n",
                             "law = lognormal\nmedian = 0.7\niqr = 0.3\nunit = um\ntubes = 12\n"),
                    file) ==
        file + ":15: tubes = '12': expected no tubes key: a law of the probe radius is no fit to tubes, and stays fixed "
               "in the data bootstrap");
  const std::string negative = parse_error(
      replaced(with_law, "law = uniform\nlower = 0.25\nupper = 1.7\n", "law = normal\nmean = 0.5\nsd = 0.2\n"), file);
  CHECK(negative.starts_with(file + ":10: [probe_radius] law normal("));
  CHECK(negative.find("expected a law whose every drawn radius is a probe radius in um, > 0 and at most 1000") !=
        std::string::npos);
  CHECK(parse_error(replaced(with_law, "unit = um\n", "unit = N/m\n"), file).starts_with(file + ":14: "));
}
