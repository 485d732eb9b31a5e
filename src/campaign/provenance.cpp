#include "campaign/provenance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string_view>

#include "core/sha256.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"

namespace growthuq {

namespace {

// The references, once each (the sources sections of src/*/README.md hold the same).
constexpr std::string_view arnoldi_2000 =
    "Arnoldi M, Fritz M, Bäuerlein E, Radmacher M, Sackmann E, Boulbitch A (2000) Bacterial turgor pressure can be "
    "measured by atomic force microscopy. Phys Rev E 62:1034-1044; applied to pollen tubes under the cellular force "
    "microscope by Burri JT et al. (2019)";
constexpr std::string_view vogler_2013 =
    "Vogler H, Draeger C, Weber A, et al. (2013) The pollen tube: a soft shell with a hard core. Plant J 73:617-627";
constexpr const char* study =
    "the Arabidopsis pollen-tube cellular-force-microscope study whose published medians and IQRs the shipped line "
    "files restate (distributions/README.md; its finite-element driver scripts: GitHub gmunglani/Chip, 2017)";

// What the README's fidelity table measured against the finite-element inverse (README.md,
// "Fidelity"), so a report can warn of it.
constexpr std::string_view closed_form_error =
    "p -55 %, E -57 % (median; -37 to -67 %) against the finite-element inverse over an Arabidopsis-like envelope "
    "(README.md, Fidelity)";
constexpr std::string_view corrected_error =
    "within 1.46 % of the finite-element inverse on 37 held-out tubes (rms 0.6 %); no value outside the fitted "
    "range (status outside_correction; src/correction/README.md)";

// The evaluators a campaign can plan (their Evaluator::name()), what they compute, their
// references (up to two, joined with "; ") and their measured error where there is one.
struct KnownModel {
  std::string_view name, description;
  std::array<std::string_view, 2> references;
  std::string_view measured_error;
};

constexpr std::array known_models{
    KnownModel{"thin_shell_turgor",
               "turgor p from the apparent stiffness under a probe of radius rho (Arnoldi relation, closed form; "
               "src/mechanics/README.md, M2-M10)",
               {arnoldi_2000, ""}, closed_form_error},
    KnownModel{"thin_shell_modulus",
               "wall modulus E from hoop equilibrium with logarithmic strain (src/mechanics/README.md, M1)",
               {vogler_2013, ""}, closed_form_error},
    KnownModel{"thin_shell_forward",
               "forward thin shell: turgid diameter and stiffness from (p, E, h, d0) (src/mechanics/README.md)",
               {vogler_2013, arnoldi_2000}, ""},
    KnownModel{"corrected_turgor_modulus",
               "the closed form times a correction fitted to the finite-element inverse (src/correction/README.md)",
               {arnoldi_2000, vogler_2013}, corrected_error},
    KnownModel{"shell_fe_turgor_modulus",
               "finite-element shell inverse, one simulation per sample (src/fe/README.md)",
               {"Hencky H (1928) Z techn Phys 9:215 (logarithmic strain energy); the shell and its validation: "
                "src/fe/README.md",
                ""},
               ""},
    KnownModel{"viscosity",
               "wall viscosity eta = tau (1 - e_inf) E from the generalized Maxwell relaxation "
               "(src/relaxation/README.md)",
               {"Golub GH, Pereyra V (1973) The differentiation of pseudo-inverses and nonlinear least squares "
                "problems whose variables separate. SIAM J Numer Anal 10:413-432 (the fit of raw relaxation curves)",
                ""},
               ""},
    KnownModel{"growth",
               "tip growth rate v = kappa (p - p0) d^2 / (4 eta h), kappa calibrated on the reference line "
               "(src/growth/README.md)",
               {"Lockhart JA (1965) An analysis of irreversible plant cell elongation. J Theor Biol 8:264-275",
                "Ortega JKE (1985) Augmented growth equation for cell wall expansion. Plant Physiol 79:318-320"},
               ""},
};

ProvenanceModel describe_model(std::string_view name) {
  for (const KnownModel& known : known_models) {
    if (known.name != name) continue;
    std::string references;
    for (const std::string_view reference : known.references) {
      if (!reference.empty()) references += (references.empty() ? "" : "; ") + std::string(reference);
    }
    return {std::string(name), std::string(known.description), references, std::string(known.measured_error)};
  }
  return {std::string(name), "(no description)", "", ""};
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
          out += escaped;
        } else {
          out += c;  // UTF-8 passes through
        }
    }
  }
  return out + "\"";
}

// JSON has no infinity: an ideal sensor (infinite stiffness) is written as null.
std::string number(double value) { return std::isfinite(value) ? format_double(value) : "null"; }

// A list as one HDF5 string attribute: "p, E, eta".
std::string comma_separated(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

std::string source_of(const CampaignLine& line) {
  return line.raw_path.empty() ? "distributions " + line.distributions_path : "raw " + line.raw_path;
}

std::string_view correlation_name(CorrelationSource source) {
  switch (source) {
    case CorrelationSource::none: return "none";
    case CorrelationSource::file: return "file";
    case CorrelationSource::physics: return "physics";
  }
  return "none";
}

}  // namespace

RunProvenance run_provenance(const PreparedCampaign& prepared) {
  const Campaign& campaign = prepared.campaign();
  RunProvenance provenance;
  provenance.engine_version = GROWTHUQ_VERSION;
  provenance.campaign_name = campaign.name;
  provenance.campaign_path = campaign.path;
  provenance.campaign_sha256 = sha256_hex(campaign.text);
  provenance.seed = campaign.seed;
  provenance.samples_per_line = campaign.samples;
  provenance.outputs = campaign.outputs;
  provenance.probe_radius_um = to_um(campaign.instrument.probe_radius_m);
  if (const std::optional<LineVariable>& law = campaign.probe_radius_law) {
    provenance.probe_radius_law = describe(law->distribution) + " " + std::string(law->unit->symbol);
  }
  provenance.poisson_ratio = campaign.instrument.poisson_ratio;
  provenance.sensor_stiffness_N_per_m = campaign.instrument.sensor_stiffness_N_per_m;
  provenance.yield_pressure_MPa = campaign.yield_pressure * unit_factor::per_MPa;
  if (prepared.calibrates_kappa()) provenance.reference_line = campaign.reference_line;
  provenance.data_interval_replicates = campaign.data_uncertainty.replicates;
  if (campaign.data_uncertainty.replicates > 0) provenance.data_interval_samples = data_uncertainty_samples(campaign);
  bool correlated = false, published = false;
  for (const CampaignLine& line : campaign.lines) {
    ProvenanceLine stated{line.name, std::string(to_string(campaign.fidelity_of(line))), source_of(line),
                          std::string(correlation_name(line.correlation)), {}};
    correlated = correlated || line.correlation != CorrelationSource::none;
    const auto prepared_line = std::find_if(prepared.lines().begin(), prepared.lines().end(),
                                            [&](const PreparedLine& p) { return p.campaign_line.name == line.name; });
    if (line.raw_path.empty() && prepared_line != prepared.lines().end()) {
      for (const LineVariable& variable : prepared_line->distributions.variables) {
        if (variable.source == "illustrative") stated.illustrative.push_back(variable.name);
        published = published || variable.source.starts_with("published");
      }
    }
    provenance.lines.push_back(std::move(stated));
  }
  provenance.models.push_back({"latin_hypercube", "Latin hypercube sampling, one point per stratum of every input",
                               "McKay MD, Beckman RJ, Conover WJ (1979) A comparison of three methods for selecting "
                               "values of input variables in the analysis of output from a computer code. "
                               "Technometrics 21:239-245",
                               ""});
  if (correlated) {
    provenance.models.push_back({"iman_conover", "target rank correlation imposed by reordering the strata",
                                 "Iman RL, Conover WJ (1982) A distribution-free approach to inducing rank correlation "
                                 "among input variables. Commun Stat Simul Comput B11:311-334",
                                 ""});
  }
  if (provenance.data_interval_replicates > 0) {
    provenance.models.push_back({"parametric_bootstrap", "data 95 % intervals: the raw-data lines refitted to tubes "
                                                         "redrawn from their fitted laws (campaigns/README.md, Data "
                                                         "uncertainty)",
                                 "", ""});
  }
  for (const PreparedLine& line : prepared.lines()) {
    for (const Evaluator* model : line.plan) {
      const auto known = std::find_if(provenance.models.begin(), provenance.models.end(),
                                      [&](const ProvenanceModel& m) { return m.name == model->name(); });
      if (known == provenance.models.end()) provenance.models.push_back(describe_model(model->name()));
    }
  }
  // Line files whose laws restate the published table say so in each law's source.
  if (published) provenance.models.push_back({"published_data", "the published medians and IQRs of line files", study, ""});
  return provenance;
}

std::string provenance_json(const RunProvenance& p) {
  std::ostringstream out;
  out << "{\n"
      << "  \"growthuq_version\": " << quoted(p.engine_version) << ",\n"
      << "  \"campaign_name\": " << quoted(p.campaign_name) << ",\n"
      << "  \"campaign_path\": " << quoted(p.campaign_path) << ",\n"
      << "  \"campaign_sha256\": " << quoted(p.campaign_sha256) << ",\n"
      << "  \"seed\": " << p.seed << ",\n"
      << "  \"samples_per_line\": " << p.samples_per_line << ",\n"
      << "  \"outputs\": [";
  for (std::size_t i = 0; i < p.outputs.size(); ++i) out << (i ? ", " : "") << quoted(p.outputs[i]);
  out << "],\n"
      << "  \"probe_radius_um\": " << number(p.probe_radius_um) << ",\n"
      << "  \"probe_radius_law\": " << quoted(p.probe_radius_law) << ",\n"
      << "  \"poisson_ratio\": " << number(p.poisson_ratio) << ",\n"
      << "  \"sensor_stiffness_N_per_m\": " << number(p.sensor_stiffness_N_per_m) << ",\n"
      << "  \"yield_pressure_MPa\": " << number(p.yield_pressure_MPa) << ",\n"
      << "  \"reference_line\": " << quoted(p.reference_line) << ",\n"
      << "  \"data_interval_replicates\": " << p.data_interval_replicates << ",\n"
      << "  \"data_interval_samples\": " << p.data_interval_samples << ",\n"
      << "  \"lines\": [";
  for (std::size_t i = 0; i < p.lines.size(); ++i) {
    const ProvenanceLine& line = p.lines[i];
    out << (i ? "," : "") << "\n    {\"name\": " << quoted(line.name) << ", \"fidelity\": " << quoted(line.fidelity)
        << ", \"source\": " << quoted(line.source) << ", \"correlation\": " << quoted(line.correlation)
        << ", \"illustrative\": [";
    for (std::size_t v = 0; v < line.illustrative.size(); ++v) out << (v ? ", " : "") << quoted(line.illustrative[v]);
    out << "]}";
  }
  out << "\n  ],\n  \"models\": [";
  for (std::size_t i = 0; i < p.models.size(); ++i) {
    const ProvenanceModel& model = p.models[i];
    out << (i ? "," : "") << "\n    {\"name\": " << quoted(model.name) << ", \"description\": " << quoted(model.description)
        << ", \"reference\": " << quoted(model.reference) << ", \"measured_error\": " << quoted(model.measured_error)
        << "}";
  }
  out << "\n  ]";
  if (p.audit.samples_per_line > 0) {
    const ProvenanceAudit& audit = p.audit;
    out << ",\n  \"audit\": {\"samples_per_line\": " << audit.samples_per_line << ", \"high_fidelity\": " << quoted(audit.high_fidelity)
        << ", \"mesh\": " << quoted(audit.mesh) << ", \"rows\": [";
    for (std::size_t i = 0; i < audit.rows.size(); ++i) {
      const ProvenanceAuditRow& row = audit.rows[i];
      out << (i ? "," : "") << "\n    {\"line\": " << quoted(row.line) << ", \"fidelity\": " << quoted(row.fidelity)
          << ", \"quantity\": " << quoted(row.quantity) << ", \"unit\": " << quoted(row.unit) << ", \"pairs\": " << row.pairs
          << ", \"bias\": " << number(row.bias) << ", \"bias_ci_low\": " << number(row.bias_ci_low)
          << ", \"bias_ci_high\": " << number(row.bias_ci_high) << "}";
    }
    out << "\n  ]}";
  }
  out << "\n}\n";
  return out.str();
}

void write_provenance(ResultsH5Writer& h5, const RunProvenance& p) {
  const std::string group = "provenance";
  h5.write_attribute(group, "growthuq_version", p.engine_version);
  h5.write_attribute(group, "campaign_name", p.campaign_name);
  h5.write_attribute(group, "campaign_path", p.campaign_path);
  h5.write_attribute(group, "campaign_sha256", p.campaign_sha256);
  h5.write_attribute(group, "seed", p.seed);
  h5.write_attribute(group, "samples_per_line", p.samples_per_line);
  h5.write_attribute(group, "outputs", comma_separated(p.outputs));
  h5.write_attribute(group, "probe_radius_um", p.probe_radius_um);
  h5.write_attribute(group, "probe_radius_law", p.probe_radius_law);
  h5.write_attribute(group, "poisson_ratio", p.poisson_ratio);
  h5.write_attribute(group, "sensor_stiffness_N_per_m", p.sensor_stiffness_N_per_m);
  h5.write_attribute(group, "yield_pressure_MPa", p.yield_pressure_MPa);
  h5.write_attribute(group, "reference_line", p.reference_line);
  h5.write_attribute(group, "data_interval_replicates", p.data_interval_replicates);
  h5.write_attribute(group, "data_interval_samples", p.data_interval_samples);
  for (const ProvenanceLine& line : p.lines) {
    const std::string path = group + "/lines/" + line.name;
    h5.write_attribute(path, "fidelity", line.fidelity);
    h5.write_attribute(path, "source", line.source);
    h5.write_attribute(path, "correlation", line.correlation);
    h5.write_attribute(path, "illustrative", comma_separated(line.illustrative));
  }
  for (const ProvenanceModel& model : p.models) {
    const std::string path = group + "/models/" + model.name;
    h5.write_attribute(path, "description", model.description);
    h5.write_attribute(path, "reference", model.reference);
    h5.write_attribute(path, "measured_error", model.measured_error);
  }
  if (p.audit.samples_per_line == 0) return;
  const std::string audit = group + "/audit";
  h5.write_attribute(audit, "samples_per_line", p.audit.samples_per_line);
  h5.write_attribute(audit, "high_fidelity", p.audit.high_fidelity);
  h5.write_attribute(audit, "mesh", p.audit.mesh);
  for (const ProvenanceAuditRow& row : p.audit.rows) {
    const std::string path = audit + "/" + row.line + "/" + row.quantity;
    h5.write_attribute(path, "fidelity", row.fidelity);
    h5.write_attribute(path, "unit", row.unit);
    h5.write_attribute(path, "pairs", row.pairs);
    h5.write_attribute(path, "bias", row.bias);
    h5.write_attribute(path, "bias_ci_low", row.bias_ci_low);
    h5.write_attribute(path, "bias_ci_high", row.bias_ci_high);
  }
}

}  // namespace growthuq
