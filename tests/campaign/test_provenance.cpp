// The run's provenance (campaign/provenance.hpp) against the campaign file it comes from: the
// values stated there, the models the outputs need, and a JSON text without anything that
// varies between reruns.
#include <doctest/doctest.h>

#include <limits>
#include <string>
#include <vector>

#include "campaign/provenance.hpp"
#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/campaign_run.hpp"

using namespace growthuq;

namespace {

const std::string data_dir = GROWTHUQ_SOURCE_DIR "/tests/campaign/data";

bool has_model(const RunProvenance& provenance, const std::string& name) {
  for (const ProvenanceModel& model : provenance.models) {
    if (model.name == name) return true;
  }
  return false;
}

ProvenanceModel model_named(const RunProvenance& provenance, const std::string& name) {
  for (const ProvenanceModel& model : provenance.models) {
    if (model.name == name) return model;
  }
  FAIL("no model " << name);
  return {};
}

}  // namespace

TEST_CASE("provenance states the campaign's settings and the models its outputs need") {
  // small_campaign.ini: seed 11, 200 samples, probe 0.5 um, nu 0.2, p0 0.15 MPa, reference
  // wild_type, two physics-correlated lines at the default fidelity, outputs p, E, eta, v.
  const PreparedCampaign prepared(read_campaign(data_dir + "/small_campaign.ini"));
  const RunProvenance provenance = run_provenance(prepared);
  CHECK(provenance.engine_version == GROWTHUQ_VERSION);
  CHECK(provenance.campaign_name == "small");
  CHECK(provenance.campaign_sha256.size() == 64);
  CHECK(provenance.seed == 11);
  CHECK(provenance.samples_per_line == 200);
  CHECK(provenance.probe_radius_um == doctest::Approx(0.5).epsilon(1e-15));
  CHECK(provenance.poisson_ratio == 0.2);
  CHECK(provenance.yield_pressure_MPa == doctest::Approx(0.15).epsilon(1e-15));
  CHECK(provenance.reference_line == "wild_type");
  CHECK(provenance.data_interval_replicates == 0);  // no raw-data line
  REQUIRE(provenance.lines.size() == 2);
  CHECK(provenance.lines[0].name == "pme48");
  CHECK(provenance.lines[0].fidelity == "closed_form");
  CHECK(provenance.lines[0].correlation == "physics");
  CHECK(provenance.lines[1].source.find("distributions/wild_type.ini") != std::string::npos);
  CHECK(has_model(provenance, "iman_conover"));
  CHECK(model_named(provenance, "thin_shell_turgor").reference.find("Arnoldi") != std::string::npos);
  CHECK(model_named(provenance, "thin_shell_turgor").measured_error.find("-55 %") != std::string::npos);
  CHECK(model_named(provenance, "growth").reference.find("Lockhart") != std::string::npos);
  CHECK(has_model(provenance, "viscosity"));
  CHECK_FALSE(has_model(provenance, "parametric_bootstrap"));
}

TEST_CASE("provenance names the illustrative laws of line files and cites the study only for published ones") {
  // campaigns/quick.ini: the shipped line files; xeg113.ini fills the published table's gaps
  // for k, h and d with illustrative laws (source = illustrative), wild_type.ini has none.
  const PreparedCampaign shipped(read_campaign(GROWTHUQ_SOURCE_DIR "/campaigns/quick.ini"));
  const RunProvenance quick = run_provenance(shipped);
  for (const ProvenanceLine& line : quick.lines) {
    CAPTURE(line.name);
    if (line.name == "xeg113") CHECK(line.illustrative == std::vector<std::string>{"k", "h", "d"});
    if (line.name == "wild_type") CHECK(line.illustrative.empty());
  }
  CHECK(has_model(quick, "published_data"));
  // raw_comparisons.ini: every line given by raw data: no published law, no line file.
  const PreparedCampaign raw(read_campaign(data_dir + "/raw_comparisons.ini"));
  const RunProvenance from_raw = run_provenance(raw);
  CHECK_FALSE(has_model(from_raw, "published_data"));
  CHECK(has_model(from_raw, "parametric_bootstrap"));
  CHECK(from_raw.data_interval_replicates == 120);
  CHECK(from_raw.data_interval_samples == 200);
  CHECK(from_raw.lines[0].source.starts_with("raw "));
}

TEST_CASE("provenance of a turgor-only campaign names no growth model and no reference line") {
  const PreparedCampaign prepared(read_campaign(data_dir + "/turgor_campaign.ini"));
  const RunProvenance provenance = run_provenance(prepared);
  CHECK_FALSE(has_model(provenance, "growth"));
  CHECK(provenance.reference_line.empty());
}

TEST_CASE("provenance.json escapes text and writes an ideal sensor as null") {
  RunProvenance provenance;
  provenance.campaign_name = "a \"quoted\"\\name\n";
  provenance.sensor_stiffness_N_per_m = std::numeric_limits<double>::infinity();
  provenance.probe_radius_um = 0.25;
  const std::string json = provenance_json(provenance);
  CHECK(json.find(R"("campaign_name": "a \"quoted\"\\name\n")") != std::string::npos);
  CHECK(json.find(R"("sensor_stiffness_N_per_m": null)") != std::string::npos);
  CHECK(json.find(R"("probe_radius_um": 0.25)") != std::string::npos);
}

TEST_CASE("provenance.json holds an audit's measured bias only when one ran, null where none was estimated") {
  RunProvenance provenance;
  CHECK(provenance_json(provenance).find("\"audit\"") == std::string::npos);
  provenance.audit.samples_per_line = 20;
  provenance.audit.high_fidelity = "shell_fe";
  provenance.audit.mesh = "coarse";
  const double none = std::numeric_limits<double>::quiet_NaN();
  provenance.audit.rows = {{"wild_type", "closed_form", "p", "MPa", 19, 0.359, 0.295, 0.423},
                           {"pme48", "corrected", "E", "MPa", 2, none, none, none}};
  const std::string json = provenance_json(provenance);
  CHECK(json.find(R"("audit": {"samples_per_line": 20, "high_fidelity": "shell_fe", "mesh": "coarse", "rows": [)") !=
        std::string::npos);
  CHECK(json.find(R"({"line": "wild_type", "fidelity": "closed_form", "quantity": "p", "unit": "MPa", "pairs": 19, )"
                  R"("bias": 0.359, "bias_ci_low": 0.295, "bias_ci_high": 0.423})") != std::string::npos);
  CHECK(json.find(R"("pairs": 2, "bias": null, "bias_ci_low": null, "bias_ci_high": null})") != std::string::npos);
  CHECK(json.substr(json.size() - 5) == "]}\n}\n");  // the last key, and the object closed
}
