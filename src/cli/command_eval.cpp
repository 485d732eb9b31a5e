// growthuq eval: the thin-shell inverse for measured tubes, without any Monte Carlo. One tube
// from flags (every output printed with its unit and the status), or a CSV of tubes with columns
// named as `growthuq sample` writes them (k_N_per_m, h_nm, d_um, d0_um; h optional) written
// back with the outputs and a status column appended. --fidelity shell_fe runs the
// finite-element model's inverse instead (growthuq/fe/indentation.hpp), tube by tube.
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "campaign/progress.hpp"
#include "commands.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/correction/corrected_closed_form.hpp"
#include "growthuq/evaluation/evaluator.hpp"
#include "growthuq/fe/indentation.hpp"
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
  bool quiet = false;  // no progress of the finite-element inverse on stderr
  // Model: closed_form (the thin shell) or shell_fe (the finite-element shell, with its flags).
  std::string fidelity = "closed_form";
  ShellFeFlags model;
};

// An output, the unit it is written in, and whether it needs the wall thickness.
struct Output {
  std::string_view quantity;
  std::string_view unit;
  bool needs_h;
};

constexpr std::array outputs{
    Output{"p", "MPa", false},          Output{"E", "MPa", true},
    Output{"alpha", "um", false},       Output{"phi", "1", false},
    Output{"lambda", "1", false},       Output{"hoop_stress", "MPa", true},
    Output{"wall_stiffness", "N/m", true},
};

// Fidelity corrected writes p and E together, from k, d, d0 and h.
constexpr std::array corrected_outputs{Output{"p", "MPa", true}, Output{"E", "MPa", true}};

const Unit& unit_of(std::string_view symbol) { return find_unit(symbol, command, "unit"); }

// The instrument from the flags, through the parser the campaign file uses (the evaluators
// validate again, as an invariant of the library).
Instrument instrument(const EvalOptions& options) {
  return parse_instrument(instrument_flags(command, options.rho_um, options.nu, options.k_sys), ProbeRadius::required);
}

// The evaluators for the requested outputs; the turgor-only plan never touches h.
std::vector<const Evaluator*> plan_for(const ThinShellTurgor& turgor, const ThinShellModulus& modulus,
                                       bool has_h) {
  const std::vector<const Evaluator*> available{&turgor, &modulus};
  std::vector<std::string> inputs{"k", "d", "d0"};
  if (has_h) inputs.emplace_back("h");
  std::vector<std::string> wanted;
  for (const Output& output : outputs) {
    if (has_h || !output.needs_h) wanted.emplace_back(output.quantity);
  }
  return plan_evaluation(available, inputs, wanted);
}

double positive_flag(const std::string& text, std::string_view key, std::string_view what) {
  const double value = parse_double(text, command, key);
  if (!(value > 0)) throw_bad_value(command, key, text, what);
  return value;
}

int evaluate_point(const EvalOptions& options, const Instrument& parameters, const Evaluator* corrected) {
  for (const auto& [text, key] : {std::pair{&options.k, "--k"}, std::pair{&options.d_um, "--d-um"},
                                  std::pair{&options.d0_um, "--d0-um"}}) {
    if (text->empty()) {
      throw InputError(std::string(command), std::string(key) + " is required (or give a file with --in)");
    }
  }
  const bool has_h = !options.h_nm.empty();
  if (corrected != nullptr && !has_h) throw InputError(std::string(command), "--h-nm is required with --fidelity corrected");
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
  const ThinShellTurgor turgor(parameters, command);
  const ThinShellModulus modulus;
  if (corrected != nullptr) {
    run_plan(std::vector<const Evaluator*>{corrected}, block);
  } else {
    run_plan(plan_for(turgor, modulus, has_h), block);
  }

  const SampleStatus status = block.status()[0];
  std::cout << (corrected != nullptr ? "corrected closed form (src/correction/README.md)"
                                     : "thin-shell inverse (Vogler et al. 2013, Arnoldi et al. 2000)")
            << ": rho = " << options.rho_um << " um, nu = " << format_double(parameters.poisson_ratio) << ", k_sys = "
            << (std::isinf(parameters.sensor_stiffness_N_per_m) ? "inf (ideal sensor)" : options.k_sys + " N/m") << "\n";
  for (const Output& output : corrected != nullptr ? std::span<const Output>(corrected_outputs) : std::span<const Output>(outputs)) {
    if (output.needs_h && !has_h) continue;
    const Quantity* quantity = find_quantity(output.quantity);
    const double value = block.column(output.quantity)[0];
    std::ostringstream line;
    line << "  " << std::left << std::setw(16) << output.quantity << std::setw(22)
         << (status == SampleStatus::ok ? format_double(value / unit_of(output.unit).to_si) : "-") << std::setw(6)
         << (output.unit == "1" ? "" : output.unit) << (quantity ? quantity->description : "");
    std::cout << line.str() << "\n";
  }
  if (!has_h) std::cout << "  (E, hoop stress and wall stiffness need the wall thickness: --h-nm)\n";
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

// The column holding `quantity` in `table`: "<quantity>_<suffix>" for any known unit of its
// dimension (d_um, d_mm, h_nm, h_um, ...). Missing: nullopt.
std::optional<MeasuredColumn> input_column(const CsvTable& table, std::string_view quantity_name) {
  const Quantity* quantity = find_quantity(quantity_name);
  std::optional<MeasuredColumn> found;
  std::string found_name;
  for (const Unit& unit : known_units()) {
    if (unit.dimension != quantity->dimension) continue;
    const std::string name = column_name(quantity_name, unit);
    if (!table.has_column(name)) continue;
    if (found) {
      throw InputError(file_location(table.path, 0), "columns '" + found_name + "' and '" + name +
                                                         "' both give " + std::string(quantity_name) +
                                                         ": keep one");
    }
    found = MeasuredColumn{table.numeric_column(name), &unit};
    found_name = name;
  }
  // A column named like the quantity with a unit that is not one of its own (h_s, d_mmm) would
  // be passed through unread, and the outputs that need it left out without a word.
  const std::string prefix = std::string(quantity_name) + "_";
  for (const std::string& name : table.header) {
    if (!name.starts_with(prefix) || (found && name == found_name)) continue;
    std::string units;
    for (const Unit& unit : known_units()) {
      if (unit.dimension == quantity->dimension) units += (units.empty() ? "" : ", ") + column_name(quantity_name, unit);
    }
    throw InputError(file_location(table.path, 0), "column '" + name + "' names " + std::string(quantity_name) +
                                                       " with no unit of " + std::string(to_string(quantity->dimension)) +
                                                       ": expected one of " + units + " (or rename the column)");
  }
  return found;
}

// The finite-element inverse's outputs: the closed form's that keep their meaning (alpha and
// phi are the closed form's own), and the unstressed thickness.
constexpr std::array shell_fe_outputs{
    Output{"p", "MPa", true},      Output{"E", "MPa", true},
    Output{"lambda", "1", true},   Output{"hoop_stress", "MPa", true},
    Output{"wall_stiffness", "N/m", true},
};

struct ShellFeValues {
  ShellFeInverse inverse;
  double lambda = 0, hoop_stress = 0, wall_stiffness = 0;
  double value(std::string_view quantity) const {
    if (quantity == "p") return inverse.pressure;
    if (quantity == "E") return inverse.young;
    if (quantity == "lambda") return lambda;
    if (quantity == "hoop_stress") return hoop_stress;
    return wall_stiffness;
  }
};

// One tube through the finite-element inverse; the hoop stress p d / (2 h) is the far field's
// exact equilibrium (mid-surface d, turgid h), E h the wall stiffness.
ShellFeValues shell_fe_tube(const ShellFeMeasurement& tube, const Instrument& parameters,
                            const ShellFeOptions& model) {
  ShellFeValues values;
  values.inverse = invert_indentation(tube, parameters, model);
  values.lambda = tube.diameter / tube.plasmolysed_diameter;
  values.hoop_stress = values.inverse.pressure * tube.diameter / (2.0 * tube.thickness);
  values.wall_stiffness = values.inverse.young * tube.thickness;
  return values;
}

std::string instrument_text(const EvalOptions& options, const Instrument& parameters) {
  return "rho = " + options.rho_um + " um, nu = " + format_double(parameters.poisson_ratio) +
         ", k_sys = " + (options.k_sys.empty() ? std::string("inf (ideal sensor)") : options.k_sys + " N/m");
}

int evaluate_point_shell_fe(const EvalOptions& options, const Instrument& parameters, const ShellFeOptions& model) {
  for (const auto& [text, key] : {std::pair{&options.k, "--k"}, std::pair{&options.d_um, "--d-um"},
                                  std::pair{&options.d0_um, "--d0-um"}, std::pair{&options.h_nm, "--h-nm"}}) {
    if (text->empty()) {
      throw InputError(std::string(command), std::string(key) + " is required with --fidelity shell_fe (or give a file with --in)");
    }
  }
  ShellFeMeasurement tube;
  tube.stiffness = positive_flag(options.k, "--k", "a positive stiffness in N/m");
  tube.thickness = positive_flag(options.h_nm, "--h-nm", "a positive thickness in nm") * 1e-9;
  tube.diameter = positive_flag(options.d_um, "--d-um", "a positive diameter in um") * 1e-6;
  tube.plasmolysed_diameter = positive_flag(options.d0_um, "--d0-um", "a positive diameter in um") * 1e-6;
  // One inverse takes seconds to minutes (README.md, "Fidelity"): say so before the wait.
  if (choose_progress_mode(options.quiet) != ProgressMode::none) {
    std::cerr << "eval: inverting the tube with the finite-element shell (" << describe(model)
              << "); seconds to minutes (--quiet: no such line)\n";
  }
  const ShellFeValues values = shell_fe_tube(tube, parameters, model);
  const ShellFeInverse& inverse = values.inverse;
  const bool ok = inverse.status == ShellFeStatus::ok;

  std::cout << "finite-element shell inverse: " << describe(model) << "; " << instrument_text(options, parameters) << "\n";
  for (const Output& output : shell_fe_outputs) {
    const Quantity* quantity = find_quantity(output.quantity);
    std::ostringstream line;
    line << "  " << std::left << std::setw(20) << output.quantity << std::setw(22)
         << (ok ? format_double(values.value(output.quantity) / unit_of(output.unit).to_si) : "-") << std::setw(6)
         << (output.unit == "1" ? "" : output.unit) << (quantity ? quantity->description : "");
    std::cout << line.str() << "\n";
  }
  const auto extra = [&](std::string_view name, const std::string& value, std::string_view unit, std::string_view what) {
    std::ostringstream line;
    line << "  " << std::left << std::setw(20) << name << std::setw(22) << value << std::setw(6) << unit << what;
    std::cout << line.str() << "\n";
  };
  extra("h0", ok ? format_double(inverse.unstressed_thickness * 1e9) : "-", "nm", "unstressed wall thickness");
  extra("p_over_E", ok ? format_double(inverse.pressure_over_young) : "-", "", "turgor over modulus, from the inflation");
  extra("E_closed_form", inverse.closed_form_young > 0 ? format_double(inverse.closed_form_young * 1e-6) : "-", "MPa",
        "the thin-shell inverse's E (the root's first estimate)");
  extra("newton_iterations", std::to_string(inverse.newton_iterations), "", "");
  extra("inflation_solves", std::to_string(inverse.inflation_solves), "", "finite-element inflations refining p/E");
  extra("seconds", format_double(inverse.seconds), "s", "");
  std::cout << "status: " << to_string(inverse.status);
  if (!ok) std::cout << " (" << describe(inverse.status) << (inverse.message.empty() ? "" : ": " + inverse.message) << ")";
  std::cout << "\n";
  return 0;
}


// Every tube of a file through the finite-element inverse (after evaluate_file has read the
// columns into `block`): the input columns, then p_MPa, E_MPa, lambda, hoop_stress_MPa,
// wall_stiffness_N_per_m, h0_nm, status.
int write_shell_fe_file(const EvalOptions& options, const Instrument& parameters, const ShellFeOptions& model,
                        const CsvTable& table, const SampleBlock& block, Overwrite overwrite) {
  std::vector<std::string> header = table.header;
  std::vector<std::string> added;
  for (const Output& output : shell_fe_outputs) added.push_back(column_name(output.quantity, unit_of(output.unit)));
  added.emplace_back("h0_nm");
  added.emplace_back("status");
  for (const std::string& name : added) {
    if (table.has_column(name)) {
      throw InputError(file_location(table.path, 0), "the input already has a column '" + name + "', which eval writes: rename or drop it");
    }
    header.push_back(name);
  }
  CsvWriter writer(header);
  std::map<ShellFeStatus, std::size_t> counts;
  double seconds = 0;
  // Seconds to minutes a tube: the tubes done, the time and the time left on stderr.
  StepProgress progress(choose_progress_mode(options.quiet), std::cerr, "eval", "tube", block.size());
  for (std::size_t i = 0; i < block.size(); ++i) {
    const ShellFeMeasurement tube{block.column("k")[i], block.column("h")[i], block.column("d")[i], block.column("d0")[i]};
    const ShellFeValues values = shell_fe_tube(tube, parameters, model);
    progress.advance();
    const bool ok = values.inverse.status == ShellFeStatus::ok;
    ++counts[values.inverse.status];
    seconds += values.inverse.seconds;
    std::vector<std::string> cells = table.rows[i];
    // A flagged tube gets empty cells, never "nan" (its status says why).
    for (const Output& output : shell_fe_outputs) {
      cells.push_back(ok ? format_double(values.value(output.quantity) / unit_of(output.unit).to_si) : "");
    }
    cells.push_back(ok ? format_double(values.inverse.unstressed_thickness * 1e9) : "");
    cells.emplace_back(to_string(values.inverse.status));
    writer.add_row(cells);
  }
  progress.finish();
  write_result(options.out, writer.text(), overwrite);
  std::ostream& report = report_stream(options.out);
  report << table.rows.size() << (table.rows.size() == 1 ? " tube" : " tubes") << " from " << table.path
            << " through the finite-element shell inverse (" << describe(model) << "; " << instrument_text(options, parameters)
            << "), " << format_double(seconds) << " s\n";
  for (const auto& [status, count] : counts) {
    report << "  " << std::left << std::setw(28) << to_string(status) << count;
    if (status != ShellFeStatus::ok) report << "  (" << describe(status) << ")";
    report << "\n";
  }
  report << wrote(options.out) << "\n";
  return 0;
}

int evaluate_file(const EvalOptions& options, const Instrument& parameters, const ShellFeOptions* model,
                  const Evaluator* corrected = nullptr) {
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
      throw InputError(file_location(table.path, 0),
                       "no column for " + std::string(quantity->description) + ": expected '" +
                           default_column_name(*quantity) + "' (columns: " + [&] {
                             std::string names;
                             for (const auto& name : table.header) names += (names.empty() ? "" : ", ") + name;
                             return names;
                           }() + ")");
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
  if (model != nullptr) {
    if (!has_h) {
      throw InputError(file_location(table.path, 0), "--fidelity shell_fe needs the wall thickness: a column h_nm (or h_um, ...)");
    }
    return write_shell_fe_file(options, parameters, *model, table, block, overwrite);
  }

  const ThinShellTurgor turgor(parameters, command);
  const ThinShellModulus modulus;
  if (corrected != nullptr) {
    if (!has_h) {
      throw InputError(file_location(table.path, 0), "--fidelity corrected needs the wall thickness: a column h_nm (or h_um, ...)");
    }
    run_plan(std::vector<const Evaluator*>{corrected}, block);
  } else {
    run_plan(plan_for(turgor, modulus, has_h), block);
  }

  std::vector<std::string> header = table.header;
  std::vector<const Output*> written;
  for (const Output& output : corrected != nullptr ? std::span<const Output>(corrected_outputs) : std::span<const Output>(outputs)) {
    if (output.needs_h && !has_h) continue;
    const std::string name = column_name(output.quantity, unit_of(output.unit));
    if (table.has_column(name)) {
      throw InputError(file_location(table.path, 0), "the input already has a column '" + name +
                                                         "', which eval writes: rename or drop it");
    }
    header.push_back(name);
    written.push_back(&output);
  }
  if (table.has_column("status")) {
    throw InputError(file_location(table.path, 0), "the input already has a column 'status', which eval writes");
  }
  header.emplace_back("status");

  CsvWriter writer(header);
  std::map<SampleStatus, std::size_t> counts;
  for (std::size_t i = 0; i < block.size(); ++i) {
    const SampleStatus status = block.status()[i];
    ++counts[status];
    std::vector<std::string> cells = table.rows[i];
    for (const Output* output : written) {
      // A flagged sample gets empty cells, never "nan" (its status says why).
      const double value = block.column(output->quantity)[i];
      cells.push_back(status == SampleStatus::ok ? format_double(value / unit_of(output->unit).to_si) : "");
    }
    cells.emplace_back(to_string(status));
    writer.add_row(cells);
  }
  write_result(options.out, writer.text(), overwrite);

  std::ostream& report = report_stream(options.out);
  report << table.rows.size() << (table.rows.size() == 1 ? " tube" : " tubes") << " from " << table.path << " (rho = " << options.rho_um
            << " um, nu = " << format_double(parameters.poisson_ratio) << ", k_sys = "
            << (std::isinf(parameters.sensor_stiffness_N_per_m) ? "inf" : options.k_sys + " N/m") << ")"
            << (has_h ? "" : "; no thickness column h_nm: turgor outputs only") << "\n";
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
      ("h-nm", po::value(&options.h_nm), "wall thickness [nm] (optional: without it, turgor outputs only)")
      ("d-um", po::value(&options.d_um), "turgid diameter [um]")
      ("d0-um", po::value(&options.d0_um), "plasmolysed diameter [um]")
      ("rho-um", po::value(&options.rho_um), "probe radius [um] (required)")
      ("nu", po::value(&options.nu), "Poisson ratio of the wall (default 0.2, as in the published FEM)")
      ("k-sys", po::value(&options.k_sys), "sensor stiffness [N/m] in series with the tube (default: ideal)")
      ("in", po::value(&options.in), "CSV of tubes: columns k_N_per_m, d_um, d0_um [, h_nm] (other units allowed, e.g. h_um); "
                                     "- reads standard input")
      ("out", po::value(&options.out), "results CSV: the input columns, p_MPa, E_MPa, alpha_um, phi, lambda, "
                                       "hoop_stress_MPa, wall_stiffness_N_per_m, status; - writes it to standard "
                                       "output (the report then goes to standard error)")
      ("force", po::bool_switch(&options.force), "overwrite --out if it exists")
      ("quiet", po::bool_switch(&options.quiet), "no progress on stderr (shell_fe: a line before a single tube's "
                                                 "inverse; for a file, the tubes done and the time left)")
      ("fidelity", po::value(&options.fidelity), "the model inverted: closed_form (default; the thin shell, instant), "
                                                 "corrected (the closed form corrected to the finite-element shell, "
                                                 "instant; needs h; writes p_MPa, E_MPa, status) or shell_fe (the "
                                                 "finite-element shell, minutes per tube; needs h; writes p_MPa, E_MPa, "
                                                 "lambda, hoop_stress_MPa, wall_stiffness_N_per_m, h0_nm, status). The "
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
  const Instrument parameters = instrument(options);
  if (options.fidelity == "closed_form") {
    for (const char* flag : {"law", "geometry", "mesh-file", "mesh", "contact", "substrate", "bending", "half-model", "tube-length-um",
                             "probe-distance-um", "window-uN"}) {
      if (values.count(flag)) {
        throw InputError(std::string(command), "--" + std::string(flag) + " needs --fidelity shell_fe (or corrected)");
      }
    }
    return options.in.empty() ? evaluate_point(options, parameters, nullptr) : evaluate_file(options, parameters, nullptr);
  }
  if (options.fidelity == "corrected") {
    // The model options say what the correction must have been fitted for: refused otherwise,
    // naming the flag typed.
    const CorrectedTurgorModulus corrected(parameters, options.model.parse(command), command, OptionNames::command_flags);
    return options.in.empty() ? evaluate_point(options, parameters, &corrected)
                              : evaluate_file(options, parameters, nullptr, &corrected);
  }
  if (options.fidelity != "shell_fe") {
    throw_bad_value(command, "--fidelity", options.fidelity, "closed_form, corrected or shell_fe");
  }
  const ShellFeOptions model = options.model.parse(command);
  return options.in.empty() ? evaluate_point_shell_fe(options, parameters, model) : evaluate_file(options, parameters, &model);
}

}  // namespace growthuq::cli
