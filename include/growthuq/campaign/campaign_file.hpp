// A campaign: which plant lines to sample, how many samples, which outputs, the instrument,
// the growth parameters and where results go. Read from an INI file (format in
// campaigns/README.md), validated completely before any work starts; command-line flags then
// override some keys.
//
// The file is read with the engine's INI reader rather than Boost.Program_options'
// parse_config_file because every error must name the line it comes from, which
// Boost.Program_options does not keep.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "growthuq/distributions/line_file.hpp"
#include "growthuq/fe/indentation.hpp"
#include "growthuq/mechanics/mechanical_correlation.hpp"
#include "growthuq/mechanics/instrument.hpp"
#include "growthuq/fidelity/fidelity.hpp"
#include "growthuq/sampling/latin_hypercube.hpp"

namespace growthuq {

// How a line's target rank correlation is obtained.
enum class CorrelationSource {
  none,     // independent variables
  file,     // a matrix CSV (header row of names, then the matrix)
  physics,  // derived from the forward thin-shell model (Eq. (M16), src/mechanics/README.md)
};

struct CampaignLine {
  std::string name;                // from the section header [line NAME]
  std::string distributions_path;  // resolved against the campaign file's folder; empty with raw_path
  std::string raw_path;            // raw = FILE (rawdata/raw_line_file.hpp): distributions fitted
                                   // from raw data; exactly one of the two paths is set
  CorrelationSource correlation = CorrelationSource::none;
  std::string correlation_path;    // when correlation == file, resolved like distributions_path
  std::optional<Fidelity> fidelity;  // the line's own fidelity = ...; the campaign's otherwise
  long line = 0;                   // line of the section header, for messages
};

// [data_uncertainty]: a parametric bootstrap over tubes for lines given by raw data
// (campaign/data_uncertainty.hpp). On by default when a line is given by raw data, with
// default_data_replicates replicates; replicates = 0 switches it off. A campaign without a
// raw-data line has none (replicates 0).
struct DataUncertaintySettings {
  // Chosen in campaigns/README.md ("Data uncertainty", "Why 200 replicates"): an end of the
  // interval moves by about 5 % of its width between two bootstraps, for about 1.5 times the
  // CPU of campaigns/from_raw.ini itself (tools/bench/data-uncertainty-replicates).
  static constexpr std::size_t default_replicates = 200;
  // Samples per line and replicate when `samples` is not given: the campaign's, at most this
  // many (the replicates' Monte Carlo error is then small next to the data's, and a campaign of
  // 1e6 samples does not run its bootstrap at 1e6 samples a replicate).
  static constexpr std::size_t default_samples_cap = 1000;

  std::size_t replicates = 0;         // refitted lines per raw line; 0: no bootstrap
  bool replicates_given = false;      // stated in the file (else the default, or 0 without raw data)
  std::size_t samples = 0;            // Latin hypercube samples per line and replicate; 0: the default
};

// [audit]: how far the fast fidelity (closed_form, corrected) is from shell_fe, from the first
// `samples` samples of each line run through both (growthuq/campaign/campaign_audit.hpp). Off without the
// section or with samples = 0.
struct AuditSettings {
  // Chosen in campaigns/README.md ("Audit"): 20 pairs bound the bias to about +-0.5 of the
  // spread of the differences (95 %) and leave the control variate 18 degrees of freedom.
  static constexpr std::size_t default_samples = 20;

  std::size_t samples = 0;  // finite-element samples per line; 0: no audit
  long line = 0;            // of the samples key (or the section), for messages
};

struct OutputFormats {
  bool csv = true;
  bool hdf5 = true;
};

struct Campaign {
  std::string path;  // the campaign file as given
  std::string text;  // its full text, stored with the results
  std::string name;
  std::uint64_t seed = 0;
  std::size_t samples = 0;            // per line
  std::vector<std::string> outputs;   // quantity names: any of p, E, eta, v and intermediates
  StratumPosition stratum_position = StratumPosition::random;
  std::size_t chunk_size = 4096;      // samples per unit of work handed to a process (analytic lines)
  Fidelity fidelity = Fidelity::closed_form;
  ShellFeOptions shell_fe;            // [shell_fe]: the finite-element model's options
  std::size_t shell_fe_chunk_size = 1;  // [shell_fe] chunk_size: samples per unit of work of shell_fe lines
  Instrument instrument;     // probe radius (required), Poisson ratio, sensor stiffness
  // [probe_radius]: a law of rho [its unit] where the study does not know it, sampled per sample
  // into the column "rho" of every line (instrument.probe_radius_per_sample); nothing otherwise.
  std::optional<LineVariable> probe_radius_law;
  double yield_pressure = 0.0;        // p0 [Pa]
  std::string reference_line;         // calibrates kappa; required when v is an output
  MechanicalDrawOptions physics_correlation;  // p, E ranges and draw count for `physics` lines
  std::string output_dir;             // relative to the current directory
  OutputFormats formats;
  DataUncertaintySettings data_uncertainty;
  AuditSettings audit;
  std::vector<CampaignLine> lines;    // in file order

  // What a campaign file cannot say wrong once its keys are read, checked again for a campaign
  // built or changed in code (run_campaign calls it): at least one line, no line twice, samples
  // from 1 to 4294967295, known outputs, an output directory, and the reference line when v is
  // an output. The first problem as an InputError naming `path` (its line where there is one),
  // as the campaign reader's messages do; the files the lines name are checked when the
  // campaign is prepared (PreparedCampaign).
  void validate() const;

  const CampaignLine* find_line(std::string_view name) const;
  Fidelity fidelity_of(const CampaignLine& line) const { return line.fidelity.value_or(fidelity); }
};

// Reads and validates a campaign file: unknown sections or keys, missing required keys, bad
// values, missing distribution or matrix files — each an InputError naming file, line, key,
// value and what was expected.
Campaign read_campaign(const std::string& path);

// Parses campaign text; `path` locates relative files and appears in messages.
Campaign parse_campaign(const std::string& text, const std::string& path);

// Command-line overrides (`growthuq run --samples ... --seed ... --out ... --lines a,b
// --formats csv,hdf5`); unset fields leave the file's values. Validated like the file.
struct CampaignOverrides {
  std::optional<std::size_t> samples{};
  std::optional<std::uint64_t> seed{};
  std::optional<std::string> output_dir{};
  std::optional<std::string> lines{};    // comma-separated subset of the file's lines
  std::optional<std::string> formats{};  // "csv", "hdf5" or "csv,hdf5"
  std::optional<std::string> fidelity{};  // every line's fidelity (lines' own included)
};

// --lines leaving no raw-data line also leaves no default bootstrap (a stated replicates stays).
void apply_overrides(Campaign& campaign, const CampaignOverrides& overrides);

// Whether a line of the campaign is given by raw data (raw = FILE).
bool has_raw_data_line(const Campaign& campaign);

// The Latin hypercube samples per line and replicate of the data-uncertainty bootstrap:
// [data_uncertainty] samples, else the campaign's samples capped at
// DataUncertaintySettings::default_samples_cap.
std::size_t data_uncertainty_samples(const Campaign& campaign);

// "csv,hdf5" -> formats; InputError naming `location` and `key` otherwise.
OutputFormats parse_formats(std::string_view text, std::string_view location, std::string_view key);

}  // namespace growthuq
