#include "growthuq/campaign/campaign_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/distributions/distribution.hpp"
#include "growthuq/distributions/sampled_range.hpp"
#include "growthuq/mechanics/probe_radius_column.hpp"
#include "campaign/sensitivity_settings.hpp"
#include "distributions/law_section.hpp"
#include "io/ini.hpp"
#include "growthuq/io/read_text_file.hpp"

namespace growthuq {
namespace {

namespace fs = std::filesystem;

// The items of a comma-separated list (outputs, formats, --lines). An item listed twice is
// refused: a line given twice would be run twice into the same files, an output twice would
// give two summary rows of one quantity.
std::vector<std::string> split_list(std::string_view text, std::string_view location, std::string_view key) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view item = trim(text.substr(start, comma - start));
    if (!item.empty() && std::find(items.begin(), items.end(), item) != items.end()) {
      throw_bad_value(location, key, text, "each item once ('" + std::string(item) + "' is listed twice)");
    }
    if (!item.empty()) items.emplace_back(item);
    start = comma + 1;
  }
  return items;
}

// Reads the keys of one section, remembering which were used so that any other key is an
// error ("unknown key") rather than silently ignored.
class SectionReader {
 public:
  SectionReader(const IniDocument& document, const IniSection& section)
      : document_(document), section_(section) {}

  const IniEntry* optional(std::string_view key) {
    used_.emplace_back(key);
    return section_.find(key);
  }

  // An empty value is as good as none: `name =` would make a nameless campaign, `output_dir =`
  // the current folder.
  const IniEntry& required(std::string_view key) {
    if (const IniEntry* entry = optional(key)) {
      if (entry->value.empty()) throw_bad_value(location(*entry), entry->key, entry->value, "a value (it is required)");
      return *entry;
    }
    throw InputError(document_.location(section_.line),
                     "[" + section_.name + "] lacks the required key '" + std::string(key) + "'");
  }

  std::string location(const IniEntry& entry) const { return document_.location(entry.line); }

  double number(const IniEntry& entry, double minimum, double maximum, std::string_view expected) const {
    const double value = parse_double(entry.value, location(entry), entry.key);
    if (!(value >= minimum && value <= maximum)) throw_bad_value(location(entry), entry.key, entry.value, expected);
    return value;
  }

  void reject_unknown_keys(std::string_view allowed) const {
    for (const IniEntry& entry : section_.entries) {
      if (std::find(used_.begin(), used_.end(), entry.key) == used_.end()) {
        throw InputError(location(entry), "unknown key '" + entry.key + "' in [" + section_.name +
                                              "] (allowed: " + std::string(allowed) + ")");
      }
    }
  }

 private:
  const IniDocument& document_;
  const IniSection& section_;
  std::vector<std::string> used_;
};

// "lo:hi" in `unit_to_si` units -> DrawRange in SI.
DrawRange parse_range(const SectionReader& reader, const IniEntry& entry, double unit_to_si) {
  const std::size_t colon = entry.value.find(':');
  const auto low = colon == std::string::npos ? std::nullopt : try_parse_double(entry.value.substr(0, colon));
  const auto high = colon == std::string::npos ? std::nullopt : try_parse_double(entry.value.substr(colon + 1));
  if (!low || !high || !(*low > 0.0) || !(*high > *low)) {
    throw_bad_value(reader.location(entry), entry.key, entry.value, "a range 'low:high' with 0 < low < high");
  }
  return {*low * unit_to_si, *high * unit_to_si};
}

std::string resolve(const std::string& campaign_path, const std::string& relative) {
  const fs::path path(relative);
  if (path.is_absolute()) return path.string();
  return (fs::path(campaign_path).parent_path() / path).lexically_normal().string();
}

void require_readable_file(const SectionReader& reader, const IniEntry& entry, const std::string& path) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) {
    throw_bad_value(reader.location(entry), entry.key, entry.value,
                    "an existing file (looked for " + path + ", relative paths start at the campaign file's folder)");
  }
}

void read_campaign_section(const IniDocument& document, const IniSection& section, Campaign& campaign) {
  SectionReader reader(document, section);
  campaign.name = reader.required("name").value;
  const IniEntry& seed = reader.required("seed");
  campaign.seed = parse_count(seed.value, reader.location(seed), seed.key);
  const IniEntry& samples = reader.required("samples");
  campaign.samples = parse_count(samples.value, reader.location(samples), samples.key, 1, 4294967295ULL);
  const IniEntry& outputs = reader.required("outputs");
  campaign.outputs = split_list(outputs.value, reader.location(outputs), outputs.key);
  if (campaign.outputs.empty()) throw_bad_value(reader.location(outputs), outputs.key, outputs.value, "a list such as 'p, E, eta, v'");
  for (const std::string& output : campaign.outputs) {
    if (find_quantity(output) == nullptr) {
      std::string known;
      for (const Quantity& quantity : known_quantities()) known += (known.empty() ? "" : ", ") + std::string(quantity.name);
      throw_bad_value(reader.location(outputs), outputs.key, output, "quantities among " + known);
    }
  }
  campaign.output_dir = reader.required("output_dir").value;
  if (const IniEntry* formats = reader.optional("formats")) {
    campaign.formats = parse_formats(formats->value, reader.location(*formats), formats->key);
  }
  if (const IniEntry* chunk = reader.optional("chunk_size")) {
    campaign.chunk_size = parse_count(chunk->value, reader.location(*chunk), chunk->key, 1, 10000000);
  }
  if (const IniEntry* position = reader.optional("stratum_position")) {
    if (position->value == "random") {
      campaign.stratum_position = StratumPosition::random;
    } else if (position->value == "centred" || position->value == "centered") {
      campaign.stratum_position = StratumPosition::centred;
    } else {
      throw_bad_value(reader.location(*position), position->key, position->value, "random or centred");
    }
  }
  if (const IniEntry* fidelity = reader.optional("fidelity")) {
    campaign.fidelity = parse_fidelity(fidelity->value, reader.location(*fidelity), fidelity->key);
  }
  reader.reject_unknown_keys("name, seed, samples, outputs, output_dir, formats, chunk_size, stratum_position, fidelity");
}

// [shell_fe]: the finite-element model's options (growthuq/fe/indentation.hpp), the keys of
// `growthuq indent`'s flags, read by the flags' parsers; a campaign's model is always the capped
// tube.
void read_shell_fe_section(const IniDocument& document, const IniSection& section, Campaign& campaign) {
  SectionReader reader(document, section);
  ShellFeOptions& options = campaign.shell_fe;
  // The key's value into its option, through `parse(text, location, key)`.
  const auto read = [&reader](std::string_view key, auto& option, auto parse) {
    if (const IniEntry* entry = reader.optional(key)) option = parse(entry->value, reader.location(*entry), entry->key);
  };
  read("law", options.law, parse_shell_fe_law);
  read("mesh", options.mesh, parse_shell_fe_mesh);
  read("contact", options.contact, parse_shell_fe_contact);
  read("substrate", options.substrate, parse_shell_fe_switch);
  read("bending", options.bending, parse_shell_fe_switch);
  read("half_model", options.half_model, parse_shell_fe_switch);
  read("tube_length_um", options.tube_length, parse_shell_fe_tube_length);
  // Checked against the tube's length with the whole section, below.
  read("probe_distance_um", options.probe_distance, [](std::string_view text, std::string_view location, std::string_view key) {
    return parse_shell_fe_probe_distance(text, location, key, 1.0);
  });
  read("force_window_uN", options.force_window, parse_shell_fe_force_window);
  if (const IniEntry* chunk = reader.optional("chunk_size")) {
    campaign.shell_fe_chunk_size = parse_count(chunk->value, reader.location(*chunk), chunk->key, 1, 10000);
  }
  reader.reject_unknown_keys(
      "law, mesh, contact, substrate, bending, half_model, tube_length_um, probe_distance_um, force_window_uN, chunk_size");
  try {
    options.validate(document.location(section.line));
  } catch (const InputError& error) {
    // validate() knows only the section; a key's error ("probe_distance_um = '30': ...") is
    // located at that key's own line when the section has it.
    for (const IniEntry& entry : section.entries) {
      if (error.problem().starts_with(entry.key + " = '")) throw InputError(reader.location(entry), error.problem());
    }
    throw;
  }
}

void read_instrument_section(const IniDocument& document, const IniSection& section, Campaign& campaign) {
  SectionReader reader(document, section);
  // The same parser, ranges and messages as the commands' --rho-um, --nu and --k-sys.
  const auto entry = [&reader](const IniEntry* found, std::string key) {
    return found ? InstrumentEntry{found->value, reader.location(*found), found->key}
                 : InstrumentEntry{std::nullopt, "", std::move(key)};
  };
  // Optional here: a [probe_radius] law may give it instead (checked with every section read).
  campaign.instrument = parse_instrument({entry(reader.optional("probe_radius_um"), "probe_radius_um"),
                                          entry(reader.optional("poisson_ratio"), "poisson_ratio"),
                                          entry(reader.optional("sensor_stiffness_N_per_m"), "sensor_stiffness_N_per_m")},
                                         ProbeRadius::optional);
  reader.reject_unknown_keys("probe_radius_um, poisson_ratio, sensor_stiffness_N_per_m");
}

// [probe_radius]: a law of the probe radius, for a study that does not know it (the shipped
// study's: campaigns/README.md, "An unknown probe radius"). Each sample draws its own rho, an
// uncertain input like the tubes' measurements, so its share of the outputs' spread shows in the
// intervals and the sensitivity; the keys are a line file's (distributions/README.md).
void read_probe_radius_section(const IniDocument& document, const IniSection& section, Campaign& campaign) {
  LineVariable law = detail::read_law_section(document, section, probe_radius_column);
  if (const IniEntry* tubes = section.find("tubes")) {
    throw_bad_value(document.location(tubes->line), tubes->key, tubes->value,
                    "no tubes key: a law of the probe radius is no fit to tubes, and stays fixed in the data bootstrap");
  }
  for (const double probability : {lowest_drawn_probability, highest_drawn_probability}) {
    const double rho = quantile(law.distribution, probability) * law.unit->to_si;
    if (!in_instrument_range(InstrumentField::probe_radius, rho)) {
      throw InputError(document.location(section.line),
                       "[probe_radius] law " + describe(law.distribution) + " in " + std::string(law.unit->symbol) +
                           ": its quantile at probability " + format_double(probability) + " is " +
                           format_double(rho / unit_factor::um) + " um: expected a law whose every drawn radius is " +
                           std::string(instrument_range(InstrumentField::probe_radius)) +
                           " (e.g. uniform, lognormal, or a truncated_normal with lower > 0)");
    }
  }
  campaign.probe_radius_law = std::move(law);
}

void read_growth_section(const IniDocument& document, const IniSection& section, Campaign& campaign) {
  SectionReader reader(document, section);
  if (const IniEntry* p0 = reader.optional("yield_pressure_MPa")) {
    campaign.yield_pressure = from_MPa(reader.number(*p0, 0.0, 100.0, "a yield pressure in MPa in [0, 100]"));
  }
  if (const IniEntry* reference = reader.optional("reference_line")) campaign.reference_line = reference->value;
  reader.reject_unknown_keys("yield_pressure_MPa, reference_line");
}

void read_physics_section(const IniDocument& document, const IniSection& section, Campaign& campaign) {
  SectionReader reader(document, section);
  MechanicalDrawOptions& draw = campaign.physics_correlation;
  if (const IniEntry* p = reader.optional("p_MPa")) draw.p = parse_range(reader, *p, unit_factor::MPa);
  if (const IniEntry* E = reader.optional("E_MPa")) draw.E = parse_range(reader, *E, unit_factor::MPa);
  if (const IniEntry* h = reader.optional("h_nm")) draw.h = parse_range(reader, *h, unit_factor::nm);
  if (const IniEntry* d0 = reader.optional("d0_um")) draw.d0 = parse_range(reader, *d0, unit_factor::um);
  if (const IniEntry* scale = reader.optional("scale")) {
    if (scale->value == "uniform") {
      draw.scale = DrawScale::uniform;
    } else if (scale->value == "log_uniform") {
      draw.scale = DrawScale::log_uniform;
    } else {
      throw_bad_value(reader.location(*scale), scale->key, scale->value, "uniform or log_uniform");
    }
  }
  if (const IniEntry* samples = reader.optional("samples")) {
    draw.samples = parse_count(samples->value, reader.location(*samples), samples->key, 100, 100000000);
  }
  reader.reject_unknown_keys("p_MPa, E_MPa, h_nm, d0_um, scale, samples");
  validate(draw, document.location(section.line));
}

void read_data_uncertainty_section(const IniDocument& document, const IniSection& section, Campaign& campaign) {
  SectionReader reader(document, section);
  if (const IniEntry* replicates = reader.optional("replicates")) {
    campaign.data_uncertainty.replicates = parse_count(replicates->value, reader.location(*replicates), replicates->key, 0, 100000);
    campaign.data_uncertainty.replicates_given = true;
  }
  if (const IniEntry* samples = reader.optional("samples")) {
    campaign.data_uncertainty.samples = parse_count(samples->value, reader.location(*samples), samples->key, 10, 10000000);
  }
  reader.reject_unknown_keys("replicates, samples");
}

void read_audit_section(const IniDocument& document, const IniSection& section, Campaign& campaign) {
  SectionReader reader(document, section);
  campaign.audit.samples = AuditSettings::default_samples;
  campaign.audit.line = section.line;
  if (const IniEntry* samples = reader.optional("samples")) {
    // At most the campaign's samples, checked when the run's count is known (campaign_audit.hpp).
    campaign.audit.samples = parse_count(samples->value, reader.location(*samples), samples->key, 0, 4294967295ULL);
    campaign.audit.line = samples->line;
    if (campaign.audit.samples == 1 || campaign.audit.samples == 2) {
      throw_bad_value(reader.location(*samples), samples->key, samples->value,
                      "0 (no audit) or at least 3 (the control variate fits two coefficients)");
    }
  }
  reader.reject_unknown_keys("samples");
}

// Data uncertainty is on by default for raw-data lines: replicates not stated in the file are
// the default when a line is given by raw data, 0 otherwise.
void apply_default_replicates(Campaign& campaign) {
  if (campaign.data_uncertainty.replicates_given) return;
  campaign.data_uncertainty.replicates = has_raw_data_line(campaign) ? DataUncertaintySettings::default_replicates : 0;
}

CampaignLine read_line_section(const IniDocument& document, const IniSection& section) {
  SectionReader reader(document, section);
  CampaignLine line;
  line.name = std::string(trim(std::string_view(section.name).substr(5)));
  line.line = section.line;
  if (line.name.empty() || line.name.find_first_of(" \t,/") != std::string::npos) {
    throw InputError(document.location(section.line),
                     "[" + section.name + "]: expected [line NAME] with a name without blanks, commas or slashes");
  }
  // Exactly one source of the line's distributions: a line file, or raw data to fit.
  const IniEntry* distributions = reader.optional("distributions");
  const IniEntry* raw = reader.optional("raw");
  if ((distributions == nullptr) == (raw == nullptr)) {
    throw InputError(document.location(section.line),
                     "[" + section.name + "] needs exactly one of 'distributions = <line file>' and 'raw = <raw data file>'" +
                         (raw != nullptr ? " (both are given)" : ""));
  }
  if (distributions != nullptr) {
    line.distributions_path = resolve(document.path, distributions->value);
    require_readable_file(reader, *distributions, line.distributions_path);
  } else {
    line.raw_path = resolve(document.path, raw->value);
    require_readable_file(reader, *raw, line.raw_path);
  }
  if (const IniEntry* correlation = reader.optional("rank_correlation")) {
    if (correlation->value == "none") {
      line.correlation = CorrelationSource::none;
    } else if (correlation->value == "physics") {
      line.correlation = CorrelationSource::physics;
    } else {
      line.correlation = CorrelationSource::file;
      line.correlation_path = resolve(document.path, correlation->value);
      require_readable_file(reader, *correlation, line.correlation_path);
    }
  }
  if (const IniEntry* fidelity = reader.optional("fidelity")) {
    line.fidelity = parse_fidelity(fidelity->value, reader.location(*fidelity), fidelity->key);
  }
  reader.reject_unknown_keys("distributions or raw, rank_correlation, fidelity");
  return line;
}

}  // namespace

const CampaignLine* Campaign::find_line(std::string_view line_name) const {
  for (const CampaignLine& line : lines) {
    if (line.name == line_name) return &line;
  }
  return nullptr;
}

OutputFormats parse_formats(std::string_view text, std::string_view location, std::string_view key) {
  OutputFormats formats{false, false};
  const auto items = split_list(text, location, key);
  for (const std::string& item : items) {
    if (item == "csv") {
      formats.csv = true;
    } else if (item == "hdf5") {
      formats.hdf5 = true;
    } else {
      throw_bad_value(location, key, text, "csv, hdf5 or csv,hdf5");
    }
  }
  if (items.empty()) throw_bad_value(location, key, text, "csv, hdf5 or csv,hdf5");
  return formats;
}

namespace {

// The probe radius once: [instrument] probe_radius_um (a known radius) or a [probe_radius] law.
// With a law the models read rho per sample, and the instrument's one value is the law's median.
void use_probe_radius_law(Campaign& campaign) {
  const bool has_radius = std::isfinite(campaign.instrument.probe_radius_m);
  if (!campaign.probe_radius_law) {
    if (!has_radius) {
      throw InputError(campaign.path, "[instrument] probe_radius_um is required (it dominates turgor), or a [probe_radius] "
                                      "section with a law of it where the study does not know it");
    }
    return;
  }
  if (has_radius) {
    throw InputError(file_location(campaign.path, campaign.probe_radius_law->line),
                     "[probe_radius] and [instrument] probe_radius_um both give the probe radius: expected one of them "
                     "(the law for an unknown radius, the key for a known one)");
  }
  const LineVariable& law = *campaign.probe_radius_law;
  campaign.instrument.probe_radius_m = quantile(law.distribution, 0.5) * law.unit->to_si;
  campaign.instrument.probe_radius_per_sample = true;
}

}  // namespace

Campaign parse_campaign(const std::string& text, const std::string& path) {
  const IniDocument document = parse_ini(text, path);
  Campaign campaign;
  campaign.path = path;
  campaign.text = text;
  bool has_campaign = false;
  bool has_instrument = false;
  for (const IniSection& section : document.sections) {
    if (section.name == "campaign") {
      read_campaign_section(document, section, campaign);
      has_campaign = true;
    } else if (section.name == "instrument") {
      read_instrument_section(document, section, campaign);
      has_instrument = true;
    } else if (section.name == "probe_radius") {
      read_probe_radius_section(document, section, campaign);
    } else if (section.name == "growth") {
      read_growth_section(document, section, campaign);
    } else if (section.name == "physics_correlation") {
      read_physics_section(document, section, campaign);
    } else if (section.name == "data_uncertainty") {
      read_data_uncertainty_section(document, section, campaign);
    } else if (section.name == "shell_fe") {
      read_shell_fe_section(document, section, campaign);
    } else if (section.name == "audit") {
      read_audit_section(document, section, campaign);
    } else if (section.name == "sensitivity") {
      read_sensitivity_section(document, section);  // checked now, read again by the run (sensitivity_settings.hpp)
    } else if (section.name.starts_with("line ")) {
      campaign.lines.push_back(read_line_section(document, section));
    } else {
      throw InputError(document.location(section.line),
                       "unknown section [" + section.name +
                           "] (expected [campaign], [instrument], [probe_radius], [growth], [physics_correlation], "
                           "[data_uncertainty], "
                           "[shell_fe], [audit], [sensitivity] or [line NAME])");
    }
  }
  if (!has_campaign) throw InputError(path, "no [campaign] section (name, seed, samples, outputs, output_dir)");
  if (!has_instrument && !campaign.probe_radius_law) {
    throw InputError(path, "no [instrument] section: probe_radius_um is required (it dominates turgor)");
  }
  use_probe_radius_law(campaign);
  campaign.validate();
  // [data_uncertainty] without a line it can resample (raw data, or a law stating tubes) is
  // refused by PreparedCampaign, which reads the line files; the default replicates apply only
  // when a line is given by raw data.
  apply_default_replicates(campaign);
  return campaign;
}

void Campaign::validate() const {
  const std::string where = path.empty() ? std::string("campaign") : path;
  if (samples < 1 || samples > 4294967295ULL) {
    throw_bad_value(where, "samples", std::to_string(samples), "a whole number from 1 to 4294967295");
  }
  if (outputs.empty()) throw_bad_value(where, "outputs", "", "a list such as 'p, E, eta, v'");
  for (const std::string& output : outputs) {
    if (find_quantity(output) == nullptr) {
      std::string known;
      for (const Quantity& quantity : known_quantities()) known += (known.empty() ? "" : ", ") + std::string(quantity.name);
      throw_bad_value(where, "outputs", output, "quantities among " + known);
    }
  }
  if (output_dir.empty()) throw_bad_value(where, "output_dir", output_dir, "a directory for the results");
  if (lines.empty()) throw InputError(where, "no [line NAME] section: a campaign needs at least one plant line");
  for (std::size_t i = 0; i < lines.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (lines[i].name == lines[j].name) {
        throw InputError(file_location(where, lines[i].line), "line '" + lines[i].name + "' repeats");
      }
    }
  }
  const bool wants_growth = std::find(outputs.begin(), outputs.end(), "v") != outputs.end();
  if (wants_growth && reference_line.empty()) {
    throw InputError(where, "output v needs [growth] reference_line: the line whose experimental growth rate calibrates kappa");
  }
  if (!reference_line.empty() && find_line(reference_line) == nullptr) {
    throw InputError(where, "[growth] reference_line = '" + reference_line + "': expected one of the campaign's lines");
  }
}

bool has_raw_data_line(const Campaign& campaign) {
  return std::any_of(campaign.lines.begin(), campaign.lines.end(), [](const CampaignLine& line) { return !line.raw_path.empty(); });
}

std::size_t data_uncertainty_samples(const Campaign& campaign) {
  if (campaign.data_uncertainty.samples > 0) return campaign.data_uncertainty.samples;
  return std::min(campaign.samples, DataUncertaintySettings::default_samples_cap);
}

Campaign read_campaign(const std::string& path) {
  // read_text_file names what is wrong: no such file, a directory, a file without end.
  return parse_campaign(detail::read_text_file(path), path);
}

void apply_overrides(Campaign& campaign, const CampaignOverrides& overrides) {
  if (overrides.samples) {
    if (*overrides.samples < 1 || *overrides.samples > 4294967295ULL) {
      throw_bad_value("command line", "--samples", std::to_string(*overrides.samples), "a whole number from 1 to 4294967295");
    }
    campaign.samples = *overrides.samples;
  }
  if (overrides.seed) campaign.seed = *overrides.seed;
  if (overrides.output_dir) campaign.output_dir = *overrides.output_dir;
  if (overrides.formats) campaign.formats = parse_formats(*overrides.formats, "command line", "--formats");
  if (overrides.fidelity) {
    campaign.fidelity = parse_fidelity(*overrides.fidelity, "command line", "--fidelity");
    for (CampaignLine& line : campaign.lines) line.fidelity.reset();
  }
  if (overrides.lines) {
    std::vector<CampaignLine> selected;
    for (const std::string& name : split_list(*overrides.lines, "command line", "--lines")) {
      const CampaignLine* line = campaign.find_line(name);
      if (line == nullptr) {
        std::string known;
        for (const CampaignLine& candidate : campaign.lines) known += (known.empty() ? "" : ", ") + candidate.name;
        throw_bad_value("command line", "--lines", name, "lines of " + campaign.path + ": " + known);
      }
      selected.push_back(*line);
    }
    if (selected.empty()) throw_bad_value("command line", "--lines", *overrides.lines, "a comma-separated list of line names");
    campaign.lines = std::move(selected);
    apply_default_replicates(campaign);
    if (!campaign.reference_line.empty() && campaign.find_line(campaign.reference_line) == nullptr) {
      throw_bad_value("command line", "--lines", *overrides.lines,
                      "a selection that keeps the reference line '" + campaign.reference_line + "' (it calibrates kappa)");
    }
  }
}

}  // namespace growthuq
