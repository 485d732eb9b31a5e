// growthuq synth: a realistic SYNTHETIC raw data set (per-tube tables, force-relaxation curves
// with their tube sheet, growth rates and the raw line file) for plant lines whose TRUE
// distributions are given as line files, one folder per line (synthetic/synthetic_line.hpp).
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/mechanics/instrument.hpp"
#include "growthuq/synthetic/synthetic_line.hpp"
#include "options.hpp"
#include "result_output.hpp"

namespace growthuq::cli {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view location = "growthuq synth";
constexpr std::string_view raw_ini_name = "raw.ini";

// The most samples of a line's relaxation curves in their hold (about 20 bytes each in
// relaxation_curves.csv: 40 MB); the defaults give 60000.
constexpr double max_curve_samples_per_line = 2e6;

struct SynthOptions {
  std::vector<std::string> lines;
  std::string out;
  std::string seed = "1";
  std::string tubes = "20:60";
  std::string curves = "20:40";
  std::string rho_um = "0.5";  // text, parsed with the other commands' instrument flags
  std::string nu = "0.2";
  double hold_s = 30.0;
  double sample_hz = 50.0;
  double ramp_um_per_s = 100.0;
  double set_point_uN = 5.0;
  double noise_pct = 0.2;
  std::string force_curves = "0";
  std::string k_sys = "100";
  double curve_noise_uN = 0.01;
  std::string curve_samples = "1000";
  bool force = false;
};

CountRange parse_range(const std::string& text, std::string_view key) {
  const std::size_t colon = text.find(':');
  const std::string expected = "a range low:high of whole numbers with 2 <= low <= high <= 100000";
  if (colon == std::string::npos) throw_bad_value(location, key, text, expected);
  CountRange range;
  range.low = parse_count(text.substr(0, colon), location, key, 2, 100000);
  range.high = parse_count(text.substr(colon + 1), location, key, 2, 100000);
  if (range.high < range.low) throw_bad_value(location, key, text, expected);
  return range;
}

double positive(double value, std::string_view key) {
  if (!(value > 0.0) || !std::isfinite(value)) throw_bad_value(location, key, format_double(value), "a positive number");
  return value;
}

SynthSettings settings_of(const SynthOptions& options) {
  SynthSettings settings;
  settings.seed = parse_count(options.seed, location, "--seed");
  settings.tubes = parse_range(options.tubes, "--tubes");
  settings.curves = parse_range(options.curves, "--curves");
  settings.instrument = parse_instrument(instrument_flags(location, options.rho_um, options.nu, ""), ProbeRadius::required);
  settings.protocol.hold = positive(options.hold_s, "--hold-s");
  settings.protocol.sample_interval = 1.0 / positive(options.sample_hz, "--sample-hz");
  settings.protocol.rate = from_um_per_s(positive(options.ramp_um_per_s, "--ramp-um-per-s"));
  settings.protocol.set_point = from_uN(positive(options.set_point_uN, "--set-point-uN"));
  if (!(options.noise_pct >= 0.0) || !(options.noise_pct < 100.0)) {
    throw_bad_value(location, "--force-noise-pct", format_double(options.noise_pct), "a percentage in [0, 100)");
  }
  settings.force_noise = from_pct(options.noise_pct);
  settings.force_curve_repetitions = parse_count(options.force_curves, location, "--force-curves", 0, 100);
  settings.force_curve.sensor_stiffness =
      parse_instrument(instrument_flags(location, options.rho_um, options.nu, options.k_sys), ProbeRadius::required)
          .sensor_stiffness_N_per_m;
  if (!(options.curve_noise_uN >= 0.0) || !std::isfinite(options.curve_noise_uN)) {
    throw_bad_value(location, "--curve-noise-uN", format_double(options.curve_noise_uN), "a force sd >= 0 (uN)");
  }
  settings.force_curve.noise = from_uN(options.curve_noise_uN);
  settings.force_curve.approach_samples = parse_count(options.curve_samples, location, "--curve-samples", 100, 100000);
  // The curves are held in memory and read back by relax and fit-line (256 MiB per file): their
  // hold phases are bounded, in samples per line, instead of growing memory without limit.
  const double hold_samples = options.hold_s * options.sample_hz * static_cast<double>(settings.curves.high);
  if (!(hold_samples <= max_curve_samples_per_line)) {
    throw_bad_value(location, "--sample-hz", format_double(options.sample_hz),
                    "at most " + format_double(std::floor(max_curve_samples_per_line / (options.hold_s * static_cast<double>(settings.curves.high)))) +
                        " Hz with --hold-s " + format_double(options.hold_s) + " and up to " + std::to_string(settings.curves.high) +
                        " curves: a line's curves hold at most " + std::to_string(static_cast<long>(max_curve_samples_per_line)) +
                        " samples (hold x rate x curves)");
  }
  return settings;
}

// The command that regenerates the set, every setting spelled out (defaults may change between
// versions; the files must say exactly what made them).
std::string regenerate_command(const SynthOptions& options, const SynthSettings& settings) {
  std::string command = "growthuq synth";
  for (const std::string& line : options.lines) command += " " + line;
  command += " --seed " + std::to_string(settings.seed) + " --tubes " + options.tubes + " --curves " + options.curves +
             " --rho-um " + format_double(parse_double(options.rho_um, location, "--rho-um")) + " --nu " +
             format_double(settings.instrument.poisson_ratio) + " --hold-s " +
             format_double(options.hold_s) + " --sample-hz " + format_double(options.sample_hz) + " --ramp-um-per-s " +
             format_double(options.ramp_um_per_s) + " --set-point-uN " + format_double(options.set_point_uN) +
             " --force-noise-pct " + format_double(options.noise_pct) + " --force-curves " +
             std::to_string(settings.force_curve_repetitions) + " --k-sys " + options.k_sys + " --curve-noise-uN " +
             format_double(options.curve_noise_uN) + " --curve-samples " + std::to_string(settings.force_curve.approach_samples) +
             " --out " + options.out;
  return command;
}

}  // namespace

int run_synth(const Arguments& arguments) {
  SynthOptions options;
  po::options_description described("options");
  described.add_options()
      ("line", po::value(&options.lines)->required()->multitoken(), "line files of the TRUE distributions (distributions/<line>.ini)")
      ("out", po::value(&options.out)->required(), "output folder; each line's files go to OUT/<line name>/")
      ("seed", po::value(&options.seed)->default_value(options.seed), "seed, 0 to 2^64 - 1; a line's files depend only on it, the line's name and its truth")
      ("tubes", po::value(&options.tubes)->default_value(options.tubes), "tubes per table and line, drawn uniformly in low:high")
      ("curves", po::value(&options.curves)->default_value(options.curves), "relaxation curves per line, drawn uniformly in low:high")
      ("rho-um", po::value(&options.rho_um)->default_value(options.rho_um), "probe radius (um), written to the tube sheet")
      ("nu", po::value(&options.nu)->default_value(options.nu), "Poisson ratio of the wall")
      ("hold-s", po::value(&options.hold_s)->default_value(options.hold_s, "30"), "hold after the set point (s); must outlast tau_slow")
      ("sample-hz", po::value(&options.sample_hz)->default_value(options.sample_hz, "50"), "sampling rate of the exported curves (Hz)")
      ("ramp-um-per-s", po::value(&options.ramp_um_per_s)->default_value(options.ramp_um_per_s, "100"), "indentation speed of the ramp (um/s)")
      ("set-point-uN", po::value(&options.set_point_uN)->default_value(options.set_point_uN, "5"), "force that ends the ramp (uN)")
      ("force-noise-pct", po::value(&options.noise_pct)->default_value(options.noise_pct, "0.2"), "force noise, standard deviation in % of the set point")
      ("force-curves", po::value(&options.force_curves)->default_value(options.force_curves),
       "raw force-indentation curves per indented tube (0: none): force_curves.csv, its sheet and its truth")
      ("k-sys", po::value(&options.k_sys)->default_value(options.k_sys), "sensor stiffness in series of the force curves "
                                                                          "(N/m, inf for none)")
      ("curve-noise-uN", po::value(&options.curve_noise_uN)->default_value(options.curve_noise_uN, "0.01"),
       "force noise of the force curves, standard deviation (uN)")
      ("curve-samples", po::value(&options.curve_samples)->default_value(options.curve_samples),
       "approach samples of a force curve (the retract has as many)")
      ("force", po::bool_switch(&options.force), "replace existing files");
  po::positional_options_description positional;
  positional.add("line", -1);
  po::variables_map values;
  if (!parse_arguments(
          arguments, "synth", "LINE.ini [LINE.ini ...] --out DIR [options]",
          "Draws a SYNTHETIC raw data set from the TRUE distributions in each line file, as a lab would hand\n"
          "it over, one folder per line (DIR/<line>/): indentation.csv (tube, k, d), plasmolysis.csv (tube,\n"
          "d0), tem_sections.csv (section, h), growth.csv (tube, v_exp), relaxation_curves.csv (curve, t_s,\n"
          "F_uN) with relaxation_meta.csv (curve, delta_um, p_MPa, d_um, h_nm, rho_um), raw.ini naming them (the\n"
          "raw line file a campaign reads with raw = FILE), and relaxation_truth.csv (each curve's true tau_slow\n"
          "and einf, which no lab has; not named by raw.ini). Each quantity is measured on its own tubes and\n"
          "drawn independently from its true law, rounded to instrument resolution. A relaxation curve is the\n"
          "simulated ramp and hold of a tube with its own k, d, d0 (p from the thin shell; redrawn until E_r can\n"
          "relax to its einf above the membrane limit), the line's median h, tau_slow and einf drawn from the\n"
          "truth and an illustrative fast phase (tau_fast ~0.25 s), with Gaussian force noise. Every file starts\n"
          "with '#' lines marking it SYNTHETIC, naming the truth and the command that regenerates it (the same\n"
          "seed gives the same files).\n\n"
          "With --force-curves N, also N raw force-indentation curves per indented tube from its true k\n"
          "(force_curves.csv, force_curves_sheet.csv for growthuq curves, and force_curves_truth.csv): a linear\n"
          "force above a drawn contact point, the sensor in series, a baseline offset and drift, Gaussian noise.",
          described, positional, values)) {
    return 0;
  }
  const SynthSettings settings = settings_of(options);
  const Overwrite overwrite = options.force ? Overwrite::allow : Overwrite::refuse;
  const std::string command = regenerate_command(options, settings);

  std::vector<LineDistributions> truths;
  for (const std::string& path : options.lines) {
    truths.push_back(read_line_file(path));
    for (std::size_t i = 0; i + 1 < truths.size(); ++i) {
      if (truths[i].name == truths.back().name) {
        throw_bad_value(location, "line", path, "line files of different lines (" + truths[i].name + " is also in " + truths[i].path + ")");
      }
    }
  }
  for (const LineDistributions& truth : truths) {
    if (truth.name.empty() || truth.name.find_first_of("/\\") != std::string::npos || truth.name == "." || truth.name == "..") {
      throw_bad_value(truth.path, "name", truth.name, "a line name usable as a folder name");
    }
  }

  if (is_standard_output(options.out)) {
    throw InputError(options.out, "standard output cannot take a data set (a folder per line): expected a folder "
                                  "name (./- for one named -)");
  }
  const auto start = std::chrono::steady_clock::now();
  for (const LineDistributions& truth : truths) {
    const auto line_start = std::chrono::steady_clock::now();
    const std::vector<SynthFile> files = synthesize_line(truth, settings, command);
    const fs::path folder = fs::path(options.out) / truth.name;
    for (const SynthFile& file : files) check_can_write((folder / file.name).string(), overwrite, Folder::created_if_missing);
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) throw InputError(folder.string(), "cannot create the folder: " + error.message());
    // raw.ini names the other files: written together, raw.ini moved in last, so a full disk
    // never leaves a raw.ini naming a file that is not there.
    std::vector<FileContent> together;
    std::size_t bytes = 0;
    for (const SynthFile& file : files) {
      if (file.name != raw_ini_name) together.push_back({(folder / file.name).string(), file.text});
      bytes += file.text.size();
    }
    for (const SynthFile& file : files) {
      if (file.name == raw_ini_name) together.push_back({(folder / file.name).string(), file.text});
    }
    write_files_together(together, overwrite);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - line_start).count();
    std::cout << "growthuq synth: " << truth.name << ": " << files.size() << " files, " << (bytes + 512) / 1024
              << " KiB in " << folder.string() << " (" << format_double(std::round(seconds * 100.0) / 100.0) << " s)\n";
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "growthuq synth: " << truths.size() << " line(s) in " << format_double(std::round(seconds * 100.0) / 100.0)
            << " s; every file is marked SYNTHETIC and names the command that regenerates it\n";
  return 0;
}

}  // namespace growthuq::cli
