#include "growthuq/synthetic/synthetic_line.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/distributions/standard_normal.hpp"
#include "growthuq/forcecurves/force_curve.hpp"
#include "growthuq/mechanics/thin_shell.hpp"
#include "growthuq/relaxation/modulus.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/synthetic/relaxation_tube.hpp"

namespace growthuq {
namespace {

struct TableColumn {
  const char* variable;
  const char* unit;   // the unit the table is written in
  double resolution;  // in that unit
};

struct TableSpec {
  const char* file;
  const char* id_column;
  const char* id_prefix;
  std::vector<TableColumn> columns;
  const char* what;
};

const std::vector<TableSpec>& tables() {
  static const std::vector<TableSpec> specs{
      {"indentation.csv", "tube", "I", {{"k", "N/m", 0.01}, {"d", "um", 0.01}},
       "indented tubes: CFM apparent stiffness k (10 um behind the tip) and turgid diameter d (light microscopy)"},
      {"plasmolysis.csv", "tube", "P", {{"d0", "um", 0.01}},
       "plasmolysed tubes (15 % mannitol): diameter d0 (light microscopy)"},
      {"tem_sections.csv", "section", "S", {{"h", "nm", 1.0}}, "TEM cross sections: wall thickness h of turgid tubes"},
      {"growth.csv", "tube", "G", {{"v_exp", "um/s", 1e-4}}, "growing tubes: growth rate v_exp from kymographs"},
  };
  return specs;
}

constexpr const char* curves_file = "relaxation_curves.csv";
constexpr const char* meta_file = "relaxation_meta.csv";
constexpr const char* truth_file = "relaxation_truth.csv";

// Decimal places of a resolution such as 0.01 (2) or 1 (0).
int decimals_of(double resolution) {
  int decimals = 0;
  while (decimals < 12 && std::abs(resolution * std::pow(10.0, decimals) - std::round(resolution * std::pow(10.0, decimals))) > 1e-9) {
    ++decimals;
  }
  return decimals;
}

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string two_digit_name(const char* prefix, std::size_t index) {
  char text[32];
  std::snprintf(text, sizeof text, "%s%02zu", prefix, index + 1);
  return text;
}

const Unit& unit_named(std::string_view symbol) { return find_unit(symbol, "synth unit table", "unit"); }

std::string header(const std::string& what, const LineDistributions& truth, const std::string& command) {
  return "# SYNTHETIC DATA, not measurements: " + what + ".\n# Drawn by growthuq synth from the TRUE distributions in " +
         truth.path + " (line " + truth.name + ").\n# Regenerate: " + command + "\n";
}

std::string truth_comment(const LineVariable& variable) {
  return "# true " + variable.name + ": " + describe(variable.distribution) + " " + std::string(variable.unit->symbol) + "\n";
}

// Draws of one line's variables from a keyed stream, in SI.
class Draws {
 public:
  Draws(const LineDistributions& truth, std::uint64_t key) : truth_(truth), stream_(key) {}

  double si(const LineVariable& variable) { return quantile(variable.distribution, stream_.uniform_open()) * variable.unit->to_si; }

  // A value of `variable` written in `unit` at `resolution`, redrawn while it rounds to <= 0.
  double rounded(const LineVariable& variable, const Unit& unit, double resolution) {
    for (int attempt = 0; attempt < 1000; ++attempt) {
      last_unrounded_ = si(variable);
      const double value = std::round(last_unrounded_ / unit.to_si / resolution) * resolution;
      if (value > 0.0) return value;
    }
    throw InputError(truth_.path, "[" + variable.name + "]: 1000 draws in a row round to <= 0 at the resolution " +
                                      format_double(resolution) + " " + std::string(unit.symbol));
  }

  // The value (SI) behind the last rounded() one, before rounding: the tube's truth.
  double last_unrounded() const { return last_unrounded_; }

  double uniform() { return stream_.uniform_open(); }
  double normal() { return standard_normal_quantile(stream_.uniform_open()); }

 private:
  const LineDistributions& truth_;
  RandomStream stream_;
  double last_unrounded_ = 0.0;
};

const LineVariable& need(const LineDistributions& truth, std::string_view name, std::string_view why) {
  const LineVariable* variable = truth.find(name);
  if (variable == nullptr) {
    throw InputError(truth.path, "no [" + std::string(name) + "] section: synth needs it for " + std::string(why));
  }
  return *variable;
}

struct Counts {
  std::vector<std::size_t> tables;
  std::size_t curves = 0;
};

// Counts of tubes per table and of curves, always drawn in the same order so that a line
// without some quantity keeps the others' counts.
Counts draw_counts(std::uint64_t line_key, const SynthSettings& settings) {
  RandomStream stream(derive_key(line_key, "counts"));
  Counts counts;
  for (std::size_t t = 0; t < tables().size(); ++t) {
    counts.tables.push_back(settings.tubes.low + stream.below(settings.tubes.high - settings.tubes.low + 1));
  }
  counts.curves = settings.curves.low + stream.below(settings.curves.high - settings.curves.low + 1);
  return counts;
}

std::string raw_ini_section(const TableSpec& table, const TableColumn& column) {
  const Unit& unit = unit_named(column.unit);
  return "\n[measurement " + std::string(column.variable) + "]\nfile = " + table.file + "\ncolumn = " +
         column_name(column.variable, unit) + "\nunit = " + column.unit + "\n";
}

struct RelaxationFiles {
  std::string curves;
  std::string meta;
  std::string truth;
};

RelaxationFiles relaxation_files(const LineDistributions& truth, const SynthSettings& settings, std::size_t count,
                                 std::uint64_t line_key, const std::string& command) {
  const std::string why = "the relaxation tubes";
  const LineVariable& k = need(truth, "k", why);
  const LineVariable& d = need(truth, "d", why);
  const LineVariable& d0 = need(truth, "d0", why);
  const LineVariable& h = need(truth, "h", why);
  const LineVariable& tau = need(truth, "tau", why);
  const LineVariable& einf = need(truth, "einf", why);
  const Instrument& instrument = settings.instrument;
  // h: the line's median TEM thickness, to the nm, on every tube sheet row.
  const double thickness_nm = std::round(to_nm(quantile(h.distribution, 0.5) * h.unit->to_si));

  Draws draws(truth, derive_key(line_key, "relaxation"));
  const std::uint64_t noise_key = derive_key(line_key, "relaxation_noise");
  const int time_decimals = decimals_of(settings.protocol.sample_interval);
  const std::string rho_um = format_double(to_um(instrument.probe_radius_m));
  RelaxationFiles files;
  const std::string common = header("stress relaxation of further tubes (ramp to " +
                                        format_double(to_uN(settings.protocol.set_point)) + " uN at " +
                                        fixed(to_um_per_s(settings.protocol.rate), 0) + " um/s, hold " +
                                        format_double(settings.protocol.hold) + " s, exported at " +
                                        fixed(1.0 / settings.protocol.sample_interval, 0) + " Hz)",
                                    truth, command);
  files.curves = common + "# Force noise " + format_double(to_pct(settings.force_noise)) +
                 " % of the set point; simulated ramp and hold (growthuq synthetic/relaxation_tube.hpp).\n" +
                 truth_comment(tau) + truth_comment(einf) + "curve,t_s,F_uN\n";
  files.meta = common + "# The tube sheet: delta = probe displacement during the hold, p = turgor from the tube's own\n"
                        "# k, d, d0 (thin shell), d = turgid diameter, h = the line's median TEM thickness, rho = probe radius.\n"
                        "curve,delta_um,p_MPa,d_um,h_nm,rho_um\n";
  files.truth = common + "# THE TRUTH of every curve, which no lab has: for checking fits, not read by raw.ini. E_r(t)/E_r(0) =\n"
                         "# einf + (1 - einf) [fast_share exp(-t/tau_fast) + (1 - fast_share) exp(-t/tau_slow)]; k0 = k(E_r(0)).\n"
                         "curve,tau_slow_s,einf_frac,tau_fast_s,fast_share,k0_N_per_m\n";
  for (std::size_t c = 0; c < count; ++c) {
    const std::string name = two_digit_name("R", c);
    RelaxationTube tube;
    tube.instrument = instrument;
    tube.thickness = from_nm(thickness_nm);
    tube.tau_slow = draws.si(tau);
    tube.einf = draws.si(einf);
    for (int attempt = 0; attempt < 1000 && !(tube.einf >= 0.0 && tube.einf < 1.0); ++attempt) tube.einf = draws.si(einf);
    // The tube: redrawn until its thin-shell turgor exists and its relaxed modulus einf E_r(0)
    // stays above 1.5 x the membrane limit (1 - nu^2) p d / (2 h), below which the Arnoldi
    // relation has no stiffness (a soft, wide tube cannot relax that far; near the limit k(E_r)
    // is logarithmic and the fit ill-conditioned). Only the geometry is conditioned: tau_slow
    // and einf keep their true laws.
    bool valid = false;
    for (int attempt = 0; attempt < 1000 && !valid; ++attempt) {
      tube.stiffness0 = draws.si(k);
      tube.diameter = std::round(draws.si(d) * 1e8) * 1e-8;  // to 0.01 um, as written
      const double plasmolysed = std::round(draws.si(d0) * 1e8) * 1e-8;
      const TurgorResult turgor = invert_turgor(tube.stiffness0, tube.diameter, plasmolysed, instrument);
      tube.turgor = std::round(turgor.p * 1e-2) * 1e2;  // to 1e-4 MPa, as written
      if (turgor.status != SampleStatus::ok || !(tube.turgor > 0.0)) continue;
      const ShellGeometry shell{tube.turgor, tube.diameter, tube.thickness, instrument};
      const double nu = instrument.poisson_ratio;
      const double membrane = (1.0 - nu * nu) * tube.turgor * tube.diameter / (2.0 * tube.thickness);
      valid = tube.einf * relaxation_modulus(tube.stiffness0, shell) > 1.5 * membrane;
    }
    if (!valid) {
      throw InputError(truth.path, "1000 draws of k, d, d0 in a row give no thin-shell turgor or no tube that can relax to einf = " +
                                       format_double(tube.einf) + " above the membrane limit");
    }
    tube.tau_fast = 0.25 * std::exp(0.3 * draws.normal());
    for (int attempt = 0; attempt < 1000 && tube.tau_slow / tube.tau_fast < 4.0; ++attempt) {
      tube.tau_fast = 0.25 * std::exp(0.3 * draws.normal());
    }
    tube.tau_fast = std::min(tube.tau_fast, tube.tau_slow / 4.0);  // only a truth with tau_slow < 0.25 s gets here
    tube.fast_share = 0.2 + 0.2 * draws.uniform();

    const SimulatedCurve curve = simulate_relaxation_tube(tube, settings.protocol, settings.force_noise, counter_bits(noise_key, c));
    for (std::size_t i = 0; i < curve.t.size(); ++i) {
      files.curves += name + "," + fixed(curve.t[i], time_decimals) + "," + fixed(to_uN(curve.force[i]), 3) + "\n";
    }
    files.meta += name + "," + fixed(to_um(curve.indentation), 4) + "," + fixed(to_MPa(tube.turgor), 4) + "," +
                  fixed(to_um(tube.diameter), 2) + "," + fixed(thickness_nm, 0) + "," + rho_um + "\n";
    files.truth += name + "," + format_double(tube.tau_slow) + "," + format_double(tube.einf) + "," +
                   format_double(tube.tau_fast) + "," + format_double(tube.fast_share) + "," + format_double(tube.stiffness0) + "\n";
  }
  return files;
}

// The force at which the stage turns back (N): above the relative window's 4 uN below the maximum
// and the absolute window's 4 uN.
constexpr double force_curve_set_point = 6e-6;

struct ForceCurveFiles {
  std::string curves;
  std::string sheet;
  std::string truth;
};

// The force curves' t_s, z_um and F_uN are written with 4 decimals (0.1 ms, 0.1 nm, 0.1 nN), as
// an instrument records them: the file is a third of its exact size, and the rounding's error
// (sd 0.03 nN) is far below the force noise (0.01 uN by default).
constexpr int recorded_decimals = 4;

// Raw force curves of the indented tubes, force_curve_repetitions per tube, each from the tube's
// true k with its own contact point and noise.
ForceCurveFiles force_curve_files(const LineDistributions& truth, const SynthSettings& settings,
                                  const std::vector<double>& stiffness, std::uint64_t line_key, const std::string& command) {
  RandomStream contacts(derive_key(line_key, "force_curve_contacts"));
  const std::uint64_t noise_key = derive_key(line_key, "force_curve_noise");
  std::vector<ForceCurve> curves;
  ForceCurveFiles files;
  const IndentationTruth& shape = settings.force_curve;
  const std::string common = header("raw force-indentation curves of the indented tubes of indentation.csv (" +
                                        std::to_string(settings.force_curve_repetitions) + " per tube, to " +
                                        format_double(to_uN(force_curve_set_point)) + " uN at " +
                                        format_double(to_um_per_s(shape.speed)) + " um/s, k_sys " +
                                        format_double(shape.sensor_stiffness) + " N/m, noise " +
                                        format_double(to_uN(shape.noise)) + " uN)",
                                    truth, command);
  files.truth = common + "# THE TRUTH of every curve, which no lab has: the tube's k before rounding and the contact.\n"
                         "curve,tube,k_N_per_m,contact_um\n";
  for (std::size_t tube = 0; tube < stiffness.size(); ++tube) {
    for (std::size_t r = 1; r <= settings.force_curve_repetitions; ++r) {
      IndentationTruth curve_truth = shape;
      curve_truth.stiffness = stiffness[tube];
      curve_truth.probe_radius = settings.instrument.probe_radius_m;
      // The stage turns back at the set force, as the instrument's protocol does, so every tube
      // spans the fit window whatever its k. Contact after 40-60 % of the approach: a soft tube's
      // long travel in contact would otherwise put the contact inside the baseline region (the
      // leading 25 % of the approach, Eq. (C1)).
      const double in_contact = force_curve_set_point / measured_stiffness(curve_truth.stiffness, Instrument{
                                                            curve_truth.probe_radius, 0.2, shape.sensor_stiffness});
      const double share = 0.4 + 0.2 * contacts.uniform_open();
      curve_truth.contact = shape.start + in_contact * share / (1.0 - share);
      curve_truth.end = curve_truth.contact + in_contact;
      const std::string tube_name = two_digit_name("I", tube);
      const std::string name = tube_name + "_r" + std::to_string(r);
      curves.push_back(simulate_indentation_curve(curve_truth, counter_bits(noise_key, curves.size()), name, tube_name,
                                                  static_cast<int>(r)));
      files.truth += name + "," + tube_name + "," + format_double(curve_truth.stiffness) + "," +
                     format_double(to_um(curve_truth.contact)) + "\n";
    }
  }
  files.curves = common + "# Recorded to 0.1 nm, 0.1 nN and 0.1 ms, an instrument's resolution.\n"
                          "# Read with: growthuq curves force_curves.csv --sheet force_curves_sheet.csv --out K.csv\n" +
                 force_curves_csv(curves, recorded_decimals);
  files.sheet = common + curve_sheet_csv(curves);
  return files;
}

}  // namespace

std::vector<SynthFile> synthesize_line(const LineDistributions& truth, const SynthSettings& settings,
                                       const std::string& regenerate_command) {
  if (settings.tubes.low < 2 || settings.tubes.high < settings.tubes.low || settings.curves.low < 2 ||
      settings.curves.high < settings.curves.low) {
    throw InputError("synth", "tube and curve counts: expected ranges low:high with 2 <= low <= high");
  }
  const std::uint64_t line_key = derive_key(mix64(settings.seed), truth.name);
  const Counts counts = draw_counts(line_key, settings);
  std::vector<SynthFile> files;
  std::vector<double> indented_stiffness;  // true k of indentation.csv's tubes, for the force curves
  std::string raw_ini = header("the raw line file naming this folder's tables and curves", truth, regenerate_command) +
                        "[line]\nname = " + truth.name + "\ndescription = SYNTHETIC raw data drawn from " + truth.path + "\n";

  for (std::size_t t = 0; t < tables().size(); ++t) {
    const TableSpec& table = tables()[t];
    std::vector<const TableColumn*> present;
    for (const TableColumn& column : table.columns) {
      if (truth.find(column.variable) != nullptr) present.push_back(&column);
    }
    if (present.empty()) continue;
    std::string text = header(table.what, truth, regenerate_command);
    std::string columns = table.id_column;
    for (const TableColumn* column : present) {
      text += truth_comment(*truth.find(column->variable));
      columns += "," + column_name(column->variable, unit_named(column->unit));
      // With force curves, k comes from them (the [force_curves] section below), not the column.
      const bool from_curves = settings.force_curve_repetitions > 0 && std::string_view(column->variable) == "k";
      if (!from_curves) raw_ini += raw_ini_section(table, *column);
    }
    text += columns + "\n";
    Draws draws(truth, derive_key(line_key, table.file));
    for (std::size_t tube = 0; tube < counts.tables[t]; ++tube) {
      text += two_digit_name(table.id_prefix, tube);
      for (const TableColumn* column : present) {
        const double value = draws.rounded(*truth.find(column->variable), unit_named(column->unit), column->resolution);
        text += "," + fixed(value, decimals_of(column->resolution));
        if (std::string_view(table.file) == "indentation.csv" && std::string_view(column->variable) == "k") {
          indented_stiffness.push_back(draws.last_unrounded());
        }
      }
      text += "\n";
    }
    files.push_back({table.file, std::move(text)});
  }

  if (settings.force_curve_repetitions > 0) {
    if (indented_stiffness.empty()) need(truth, "k", "raw force curves");
    ForceCurveFiles curves = force_curve_files(truth, settings, indented_stiffness, line_key, regenerate_command);
    files.push_back({"force_curves.csv", std::move(curves.curves)});
    files.push_back({"force_curves_sheet.csv", std::move(curves.sheet)});
    files.push_back({"force_curves_truth.csv", std::move(curves.truth)});
    raw_ini += "\n# k per tube from its raw force curves (src/forcecurves/README.md), then its distribution\n"
               "[force_curves]\ncurves = force_curves.csv\nsheet = force_curves_sheet.csv\n";
  }

  if (truth.find("tau") != nullptr || truth.find("einf") != nullptr) {
    RelaxationFiles relaxation = relaxation_files(truth, settings, counts.curves, line_key, regenerate_command);
    files.push_back({curves_file, std::move(relaxation.curves)});
    files.push_back({meta_file, std::move(relaxation.meta)});
    files.push_back({truth_file, std::move(relaxation.truth)});
    raw_ini += "\n# tau and einf: from fitting every curve (growthuq relax's step fit), then their distributions\n"
               "[relaxation]\ncurves = " + std::string(curves_file) + "\nmeta = " + meta_file + "\nterms = 2\nfit = step\n";
  }
  files.insert(files.begin(), SynthFile{"raw.ini", std::move(raw_ini)});
  return files;
}

}  // namespace growthuq
