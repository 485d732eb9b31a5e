// growthuq eval: a fidelity's inverse for measured tubes, without any Monte Carlo. One tube from
// flags (every output printed with its unit and the status), or a CSV of tubes with columns
// named as `growthuq sample` writes them (k_N_per_m, h_nm, d_um, d0_um; h optional at
// closed_form) written back with the outputs and a status column appended. Every fidelity runs
// through the evaluators a campaign runs (fidelity/fidelity.hpp); a slow one (the
// finite-element shell) tube by tube with progress.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "growthuq/campaign/progress.hpp"
#include "commands.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/evaluation/evaluator.hpp"
#include "growthuq/fidelity/fidelity.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/mechanics/thin_shell_evaluators.hpp"
#include "options.hpp"
#include "result_output.hpp"
#include "shell_fe_flags.hpp"

namespace growthuq::cli {
namespace {

constexpr std::string_view command = "growthuq eval";

struct EvalOptions {
  // One tube (the flags are text so that errors quote what the user typed).
  std::string k;
  std::string h_nm;
  std::string d_um;
  std::string d0_um;
  // Instrument.
  std::string rho_um;
  std::string nu = "0.2";
  std::string k_sys;  // empty: an ideal sensor
  // A file of tubes.
  std::string in;
  std::string out;
  bool force = false;
  bool quiet = false;  // no progress of a slow fidelity on stderr
  std::string fidelity = "closed_form";
  ShellFeFlags model;  // the finite-element model's options (shell_fe; corrected checks them)
};

// An output eval can write, in the order it writes them, the unit it is written in, whether it
// needs the wall thickness and what it is. A fidelity writes those its evaluators write.
struct Output {
  std::string_view quantity;
  std::string_view unit;
  bool needs_h;
  std::string_view description;  // empty: the quantity's own (units.hpp)
};

constexpr std::array outputs{
    Output{"p", "MPa", false, ""},
    Output{"E", "MPa", true, ""},
    Output{"alpha", "um", false, ""},
    Output{"phi", "1", false, ""},
    Output{"lambda", "1", false, ""},
    Output{"hoop_stress", "MPa", true, ""},
    Output{"wall_stiffness", "N/m", true, ""},
    Output{"h0", "nm", true, "unstressed wall thickness (from the finite-element inflation)"},
};

const Unit& unit_of(std::string_view symbol) { return find_unit(symbol, command, "unit"); }

std::string_view description_of(const Output& output) {
  if (!output.description.empty()) return output.description;
  const Quantity* quantity = find_quantity(output.quantity);
  return quantity ? quantity->description : "";
}

double positive_flag(const std::string& text, std::string_view key, std::string_view what) {
  const double value = parse_double(text, command, key);
  if (!(value > 0)) throw_bad_value(command, key, text, what);
  return value;
}

// The fidelity's models and the plan that turns the measurements into every output they write.
class EvalModel {
 public:
  EvalModel(Fidelity fidelity, const Instrument& instrument, const ShellFeOptions& options, bool has_h)
      : models_(turgor_modulus_models(fidelity, instrument, options, command, OptionNames::command_flags,
                                      ExtraOutputs::unstressed_thickness)) {
    std::vector<const Evaluator*> available;
    for (const auto& model : models_) available.push_back(model.get());
    std::vector<std::string> inputs{"k", "d", "d0"};
    if (has_h) inputs.emplace_back("h");
    std::vector<std::string> wanted;
    for (const Output& output : outputs) {
      if (!has_h && output.needs_h) continue;
      for (const Evaluator* model : available) {
        const std::vector<std::string> writes = model->writes();
        if (std::find(writes.begin(), writes.end(), output.quantity) != writes.end()) {
          wanted.emplace_back(output.quantity);
          written_.push_back(&output);
          break;
        }
      }
    }
    plan_ = plan_evaluation(available, inputs, wanted);
  }

  const std::vector<const Output*>& written() const { return written_; }
  bool slow() const { return seconds_per_sample(plan_) >= slow_sample_seconds; }
  double seconds_per_tube() const { return seconds_per_sample(plan_); }

  // Runs the plan on `block`; a slow model tube by tube, saying on `log` how far it is (the
  // tubes done, the time and the time left, as `mode` says).
  void run(SampleBlock& block, ProgressMode mode, std::ostream& log) const {
    if (!slow()) {
      run_plan(plan_, block);
      return;
    }
    const std::vector<std::string> inputs = block.quantities();
    for (const Output* output : written_) block.add_column(output->quantity);
    StepProgress progress(block.size() > 1 ? mode : ProgressMode::none, log, "eval", "tube", block.size());
    for (std::size_t i = 0; i < block.size(); ++i) {
      SampleBlock one(1);
      for (const std::string& name : inputs) one.set_column(name, std::vector<double>{std::as_const(block).column(name)[i]});
      one.status()[0] = block.status()[i];
      run_plan(plan_, one);
      for (const Output* output : written_) block.column(output->quantity)[i] = one.column(output->quantity)[0];
      block.status()[i] = one.status()[0];
      progress.advance();
    }
    progress.finish();
  }

 private:
  std::vector<std::unique_ptr<const Evaluator>> models_;
  std::vector<const Evaluator*> plan_;
  std::vector<const Output*> written_;
};

// What the model is, for the first line of the report.
std::string model_text(Fidelity fidelity, const ShellFeOptions& options) {
  switch (fidelity) {
    case Fidelity::closed_form: return "thin-shell inverse (Vogler et al. 2013, Arnoldi et al. 2000)";
    case Fidelity::corrected: return "corrected closed form (src/correction/README.md)";
    case Fidelity::shell_fe: return "finite-element shell inverse (" + describe(options) + ")";
  }
  return "?";
}

std::string instrument_text(const EvalOptions& options, const Instrument& parameters) {
  return "rho = " + options.rho_um + " um, nu = " + format_double(parameters.poisson_ratio) +
         ", k_sys = " + (std::isinf(parameters.sensor_stiffness_N_per_m) ? std::string("inf (ideal sensor)") : options.k_sys + " N/m");
}

std::string missing_thickness(Fidelity fidelity) {
  return "--fidelity " + std::string(to_string(fidelity)) + " needs the wall thickness";
}

int evaluate_point(const EvalOptions& options, const Instrument& parameters, Fidelity fidelity,
                   const ShellFeOptions& model_options) {
  for (const auto& [text, key] : {std::pair{&options.k, "--k"}, std::pair{&options.d_um, "--d-um"},
                                  std::pair{&options.d0_um, "--d0-um"}}) {
    if (text->empty()) {
      throw InputError(std::string(command), std::string(key) + " is required (or give a file with --in)");
    }
  }
  const bool has_h = !options.h_nm.empty();
  if (fidelity != Fidelity::closed_form && !has_h) {
    throw InputError(std::string(command), "--h-nm is required with --fidelity " + std::string(to_string(fidelity)));
  }
  SampleBlock block(1);
  block.set_column("k", std::vector<double>{positive_flag(options.k, "--k", "a positive stiffness in N/m")});
  const double d_um = positive_flag(options.d_um, "--d-um", "a positive diameter in um");
  const double d0_um = positive_flag(options.d0_um, "--d0-um", "a positive diameter in um");
  block.set_column("d", std::vector<double>{from_um(d_um)});
  block.set_column("d0", std::vector<double>{from_um(d0_um)});
  // The stretch in um, as given (thin_shell.hpp, TubeDiameters).
  add_hoop_strain(block, std::vector<double>{d_um}, unit_factor::um, std::vector<double>{d0_um}, unit_factor::um);
  if (has_h) {
    block.set_column("h", std::vector<double>{from_nm(positive_flag(options.h_nm, "--h-nm", "a positive thickness in nm"))});
  }
  const EvalModel model(fidelity, parameters, model_options, has_h);
  const ProgressMode progress = choose_progress_mode(options.quiet);
  if (model.slow() && progress != ProgressMode::none) {
    std::cerr << "eval: inverting the tube with the " << model_text(fidelity, model_options) << ": about "
              << format_double(model.seconds_per_tube()) << " s of one core (--quiet: no such line)\n";
  }
  const auto start = std::chrono::steady_clock::now();
  model.run(block, progress, std::cerr);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const SampleStatus status = block.status()[0];
  std::cout << model_text(fidelity, model_options) << ": " << instrument_text(options, parameters) << "\n";
  for (const Output* output : model.written()) {
    std::ostringstream line;
    line << "  " << std::left << std::setw(16) << output->quantity << std::setw(22)
         << (status == SampleStatus::ok ? format_double(block.column(output->quantity)[0] / unit_of(output->unit).to_si) : "-")
         << std::setw(6) << (output->unit == "1" ? "" : output->unit) << description_of(*output);
    std::cout << line.str() << "\n";
  }
  if (!has_h) std::cout << "  (E, hoop stress and wall stiffness need the wall thickness: --h-nm)\n";
  if (model.slow()) std::cout << "  " << std::left << std::setw(16) << "seconds" << format_double(seconds) << "\n";
  std::cout << "status: " << to_string(status);
  if (status != SampleStatus::ok) std::cout << " (" << describe(status) << ")";
  std::cout << "\n";
  return 0;
}

// A column of measurements as the file gives them, in `unit`.
struct MeasuredColumn {
  std::vector<double> values;
  const Unit* unit;
  std::vector<double> si() const {
    std::vector<double> converted = values;
    for (double& value : converted) value *= unit->to_si;
    return converted;
  }
};

std::string units_of(const Quantity& quantity) {
  std::string units;
  for (const Unit& unit : known_units()) {
    if (unit.dimension == quantity.dimension) units += (units.empty() ? "" : ", ") + column_name(quantity.name, unit);
  }
  return units;
}

// The column holding `quantity` in `table`: "<quantity>_<suffix>" for any known unit of its
// dimension (d_um, d_mm, h_nm, h_um, ...). Missing: nullopt.
std::optional<MeasuredColumn> input_column(const CsvTable& table, std::string_view quantity_name) {
  const Quantity& quantity = *find_quantity(quantity_name);
  std::optional<MeasuredColumn> found;
  std::string found_name;
  const std::string prefix = std::string(quantity_name) + "_";
  for (const std::string& name : table.header) {
    const Unit* unit = unit_of_column(quantity, name);
    if (unit == nullptr) {
      // A column named like the quantity with a unit that is not one of its own (h_s, d_mmm)
      // would be passed through unread, and the outputs that need it left out without a word.
      if (name.starts_with(prefix)) {
        throw InputError(file_location(table.path, 0), "column '" + name + "' names " + std::string(quantity_name) +
                                                           " with no unit of " + std::string(to_string(quantity.dimension)) +
                                                           ": expected one of " + units_of(quantity) + " (or rename the column)");
      }
      continue;
    }
    if (found) {
      throw InputError(file_location(table.path, 0), "columns '" + found_name + "' and '" + name + "' both give " +
                                                         std::string(quantity_name) + ": keep one");
    }
    found = MeasuredColumn{table.numeric_column(name), unit};
    found_name = name;
  }
  return found;
}

int evaluate_file(const EvalOptions& options, const Instrument& parameters, Fidelity fidelity,
                  const ShellFeOptions& model_options) {
  if (options.out.empty()) throw InputError(std::string(command), "--in needs --out (the results CSV to write)");
  for (const auto& [text, key] : {std::pair{&options.k, "--k"}, std::pair{&options.h_nm, "--h-nm"},
                                  std::pair{&options.d_um, "--d-um"}, std::pair{&options.d0_um, "--d0-um"}}) {
    if (!text->empty()) {
      throw InputError(std::string(command), std::string(key) + " cannot be combined with --in: the file gives the measurements");
    }
  }
  const Overwrite overwrite = options.force ? Overwrite::allow : Overwrite::refuse;
  check_result_target(options.out, overwrite);

  const CsvTable table = read_csv(options.in);
  SampleBlock block(table.rows.size());
  std::optional<MeasuredColumn> d, d0;
  for (std::string_view required : {"k", "d", "d0"}) {
    auto values = input_column(table, required);
    if (!values) {
      const Quantity* quantity = find_quantity(required);
      std::string names;
      for (const auto& name : table.header) names += (names.empty() ? "" : ", ") + name;
      throw InputError(file_location(table.path, 0), "no column for " + std::string(quantity->description) +
                                                         ": expected '" + default_column_name(*quantity) +
                                                         "' (columns: " + names + ")");
    }
    block.set_column(required, values->si());
    if (required == "d") d = values;
    if (required == "d0") d0 = values;
  }
  // The stretch in the file's units, as measured (thin_shell.hpp, TubeDiameters).
  add_hoop_strain(block, d->values, d->unit->to_si, d0->values, d0->unit->to_si);
  const auto thickness = input_column(table, "h");
  if (thickness) block.set_column("h", thickness->si());
  const bool has_h = thickness.has_value();
  if (fidelity != Fidelity::closed_form && !has_h) {
    throw InputError(file_location(table.path, 0), missing_thickness(fidelity) + ": a column h_nm (or h_um, ...)");
  }
  const EvalModel model(fidelity, parameters, model_options, has_h);

  std::vector<std::string> header = table.header;
  for (const Output* output : model.written()) header.push_back(column_name(output->quantity, unit_of(output->unit)));
  header.emplace_back("status");
  for (std::size_t c = table.header.size(); c < header.size(); ++c) {
    if (table.has_column(header[c])) {
      throw InputError(file_location(table.path, 0), "the input already has a column '" + header[c] +
                                                         "', which eval writes: rename or drop it");
    }
  }

  std::ostream& report = report_stream(options.out);
  const auto start = std::chrono::steady_clock::now();
  model.run(block, choose_progress_mode(options.quiet), std::cerr);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  CsvWriter writer(header);
  std::map<SampleStatus, std::size_t> counts;
  for (std::size_t i = 0; i < block.size(); ++i) {
    const SampleStatus status = block.status()[i];
    ++counts[status];
    std::vector<std::string> cells = table.rows[i];
    for (const Output* output : model.written()) {
      // A flagged sample gets empty cells, never "nan" (its status says why).
      const double value = block.column(output->quantity)[i];
      cells.push_back(status == SampleStatus::ok ? format_double(value / unit_of(output->unit).to_si) : "");
    }
    cells.emplace_back(to_string(status));
    writer.add_row(cells);
  }
  write_result(options.out, writer.text(), overwrite);

  report << table.rows.size() << (table.rows.size() == 1 ? " tube" : " tubes") << " from " << table.path << " ("
         << model_text(fidelity, model_options) << "; " << instrument_text(options, parameters) << ")"
         << (has_h ? "" : "; no thickness column h_nm: turgor outputs only");
  if (model.slow()) report << ", " << format_double(seconds) << " s";
  report << "\n";
  for (const auto& [status, count] : counts) {
    report << "  " << std::left << std::setw(28) << to_string(status) << count;
    if (status != SampleStatus::ok) report << "  (" << describe(status) << ")";
    report << "\n";
  }
  report << wrote(options.out) << "\n";
  return 0;
}

}  // namespace

int run_eval(const Arguments& arguments) {
  EvalOptions options;
  po::options_description described("options");
  described.add_options()
      ("k", po::value(&options.k), "measured apparent stiffness [N/m] (one tube)")
      ("h-nm", po::value(&options.h_nm), "wall thickness [nm] (optional at closed_form: without it, turgor outputs only)")
      ("d-um", po::value(&options.d_um), "turgid diameter [um]")
      ("d0-um", po::value(&options.d0_um), "plasmolysed diameter [um]")
      ("rho-um", po::value(&options.rho_um), "probe radius [um] (required)")
      ("nu", po::value(&options.nu), "Poisson ratio of the wall (default 0.2, as in the published FEM)")
      ("k-sys", po::value(&options.k_sys), "sensor stiffness [N/m] in series with the tube (default: ideal)")
      ("in", po::value(&options.in), "CSV of tubes: columns k_N_per_m, d_um, d0_um [, h_nm] (other units allowed, e.g. h_um); "
                                     "- reads standard input")
      ("out", po::value(&options.out), "results CSV: the input columns, the fidelity's outputs (closed_form: p_MPa, E_MPa, "
                                       "alpha_um, phi, lambda, hoop_stress_MPa, wall_stiffness_N_per_m; corrected: p_MPa, "
                                       "E_MPa, lambda, hoop_stress_MPa, wall_stiffness_N_per_m; shell_fe: the same and "
                                       "h0_nm), then status; - writes it to standard output (the report then goes to "
                                       "standard error)")
      ("force", po::bool_switch(&options.force), "overwrite --out if it exists")
      ("quiet", po::bool_switch(&options.quiet), "no progress on stderr (shell_fe: a line before a single tube's "
                                                 "inverse; for a file, the tubes done and the time left)")
      ("fidelity", po::value(&options.fidelity), "the model inverted, as a campaign's fidelity = ...: closed_form (default; "
                                                 "the thin shell, instant), corrected (the closed form corrected to the "
                                                 "finite-element shell, instant; needs h) or shell_fe (the finite-element "
                                                 "shell, seconds per tube, progress on standard error; needs h). The "
                                                 "options below are the finite-element model's (corrected refuses values "
                                                 "other than those it was fitted for):");
  options.model.declare(described);
  po::variables_map values;
  if (!parse_arguments(arguments, "eval",
                       "--rho-um R (--k K --d-um D --d0-um D0 [--h-nm H] | --in tubes.csv --out results.csv) [options]",
                       "Inverts the thin-shell model for measured tubes: turgor p and decay length alpha from\n"
                       "(k, d, d0), modulus E, hoop stress and wall stiffness E h when h is known.\n"
                       "Valid for 1 < d/d0 <= e (beyond e the wall is past its pressure maximum); other tubes get a\n"
                       "status, not a number.\n\n"
                       "--fidelity shell_fe inverts the finite-element shell instead (src/fe/README.md): p/E and h0 from\n"
                       "the turgid d/d0 and the turgid (measured) h, then E from k over the force window; it needs h.\n"
                       "--fidelity corrected applies the correction fitted to that inverse over the Arabidopsis-like\n"
                       "envelope (src/correction/README.md); a tube outside it gets status outside_correction.",
                       described, {}, values)) {
    return 0;
  }
  if (!options.out.empty() && options.in.empty()) {
    throw InputError(std::string(command), "--out needs --in (a single tube is printed, not written)");
  }
  const Instrument parameters = parse_instrument(instrument_flags(command, options.rho_um, options.nu, options.k_sys),
                                                 ProbeRadius::required);
  const Fidelity fidelity = parse_fidelity(options.fidelity, command, "--fidelity");
  if (fidelity == Fidelity::closed_form) {
    for (const char* flag : {"law", "geometry", "mesh-file", "mesh", "contact", "substrate", "bending", "half-model",
                             "tube-length-um", "probe-distance-um", "window-uN"}) {
      if (values.count(flag)) {
        throw InputError(std::string(command), "--" + std::string(flag) + " needs --fidelity shell_fe (or corrected)");
      }
    }
  }
  const ShellFeOptions model = options.model.parse(command);
  return options.in.empty() ? evaluate_point(options, parameters, fidelity, model)
                            : evaluate_file(options, parameters, fidelity, model);
}

}  // namespace growthuq::cli
