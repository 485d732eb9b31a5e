// A run's provenance: what a reader needs to say how the results were made (the engine's
// version, the campaign file and its SHA-256, seed, sample counts, the instrument, each line's
// fidelity and source, the data-interval settings, the models used with their literature
// references). Written into results.h5 (/provenance) and as provenance.json beside the CSVs;
// `growthuq report` builds its methods paragraph from it.
//
// Only what decides the results goes in, so reruns stay byte-identical: no date (the files'
// modification times say when) and no process count (results do not depend on it:
// tests/campaign/identical_across_processes.cmake).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/io/results_h5.hpp"

namespace growthuq {

inline constexpr const char* provenance_json_name = "provenance.json";

struct ProvenanceLine {
  std::string name;
  std::string fidelity;  // closed_form, corrected, shell_fe
  std::string source;    // "distributions FILE" or "raw FILE" (paths as resolved by the campaign)
  std::string correlation;  // none, file, physics
  std::vector<std::string> illustrative;  // variables of a line file whose law is illustrative, not measured
};

// A model or method a run used: its name in the engine (an evaluator's name, or a method's),
// what it does, its literature reference and, where measured, its known error.
struct ProvenanceModel {
  std::string name, description, reference, measured_error;
};

// The audit of the campaign's fast fidelity (campaign_audit.hpp), when one ran: per audited line
// and output, the bias measured in this run (mean of high - fast over the pairs) with its 95 %
// interval.
struct ProvenanceAuditRow {
  std::string line, fidelity, quantity, unit;  // fidelity: the line's fast one; unit: of the bias
  std::uint64_t pairs = 0;                     // samples both fidelities gave a value for
  double bias = 0, bias_ci_low = 0, bias_ci_high = 0;  // NaN (JSON null) with fewer than 3 pairs
};

struct ProvenanceAudit {
  std::uint64_t samples_per_line = 0;  // 0: no audit ran
  std::string high_fidelity, mesh;     // shell_fe and its [shell_fe] mesh
  std::vector<ProvenanceAuditRow> rows;
};

struct RunProvenance {
  std::string engine_version, campaign_name, campaign_path, campaign_sha256;
  std::uint64_t seed = 0;
  std::uint64_t samples_per_line = 0;
  std::vector<std::string> outputs;
  double probe_radius_um = 0, poisson_ratio = 0, sensor_stiffness_N_per_m = 0, yield_pressure_MPa = 0;
  std::string probe_radius_law;                // "uniform(lower=0.25, upper=1.7) um" when drawn per sample;
                                               // probe_radius_um is then its median. Empty otherwise.
  std::string reference_line;                  // empty when kappa is not calibrated
  std::uint64_t data_interval_replicates = 0;  // the bootstrap's; 0: no data intervals
  std::uint64_t data_interval_samples = 0;     // samples per line and replicate (0 without)
  std::vector<ProvenanceLine> lines;           // the campaign's order
  std::vector<ProvenanceModel> models;         // sampling first, then the evaluators in run order
  ProvenanceAudit audit;                       // filled in by the audit itself (campaign_audit.cpp)
};

RunProvenance run_provenance(const PreparedCampaign& campaign);

// provenance.json: one object, keys in a fixed order, two-space indentation, numbers that read
// back to the same double; the key "audit" only when an audit ran.
std::string provenance_json(const RunProvenance& provenance);

// /provenance: scalar attributes on the group; /provenance/lines/<line> and
// /provenance/models/<model> groups with their fields as string attributes; when an audit ran,
// /provenance/audit (samples_per_line, high_fidelity, mesh) and /provenance/audit/<line>/<quantity>
// (fidelity, unit, pairs, bias, bias_ci_low, bias_ci_high).
void write_provenance(ResultsH5Writer& h5, const RunProvenance& provenance);

}  // namespace growthuq
