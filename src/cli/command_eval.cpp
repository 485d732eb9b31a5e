// growthuq eval: the thin-shell inverse for measured tubes, without any Monte Carlo. One tube
// from flags (every output printed with its unit and the status), or a CSV of tubes with columns
// named as `growthuq sample` writes them (k_N_per_m, h_nm, d_um, d0_um; h optional) written
// back with the outputs and a status column appended.
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/evaluation/evaluator.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/mechanics/thin_shell_evaluators.hpp"
#include "options.hpp"

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

int evaluate_point(const EvalOptions& options, const Instrument& parameters) {
  for (const auto& [text, key] : {std::pair{&options.k, "--k"}, std::pair{&options.d_um, "--d-um"},
                                  std::pair{&options.d0_um, "--d0-um"}}) {
    if (text->empty()) {
      throw InputError(std::string(command), std::string(key) + " is required (or give a file with --in)");
    }
  }
  const bool has_h = !options.h_nm.empty();
  SampleBlock block(1);
  block.set_column("k", std::vector<double>{positive_flag(options.k, "--k", "a positive stiffness in N/m")});
  block.set_column("d", std::vector<double>{from_um(positive_flag(options.d_um, "--d-um", "a positive diameter in um"))});
  block.set_column("d0", std::vector<double>{from_um(positive_flag(options.d0_um, "--d0-um", "a positive diameter in um"))});
  if (has_h) {
    block.set_column("h", std::vector<double>{from_nm(positive_flag(options.h_nm, "--h-nm", "a positive thickness in nm"))});
  }
  const ThinShellTurgor turgor(parameters, command);
  const ThinShellModulus modulus;
  run_plan(plan_for(turgor, modulus, has_h), block);

  const SampleStatus status = block.status()[0];
  std::cout << "thin-shell inverse (Vogler et al. 2013, Arnoldi et al. 2000): rho = " << options.rho_um
            << " um, nu = " << format_double(parameters.poisson_ratio) << ", k_sys = "
            << (std::isinf(parameters.sensor_stiffness_N_per_m) ? "inf (ideal sensor)" : options.k_sys + " N/m") << "\n";
  for (const Output& output : outputs) {
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

// The column holding `quantity` in `table`: "<quantity>_<suffix>" for any known unit of its
// dimension (d_um, d_mm, h_nm, h_um, ...), converted to SI. Missing: nullopt.
std::optional<std::vector<double>> input_column(const CsvTable& table, std::string_view quantity_name) {
  const Quantity* quantity = find_quantity(quantity_name);
  std::optional<std::vector<double>> found;
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
    std::vector<double> values = table.numeric_column(name);
    for (double& value : values) value *= unit.to_si;
    found = std::move(values);
    found_name = name;
  }
  return found;
}

int evaluate_file(const EvalOptions& options, const Instrument& parameters) {
  if (options.out.empty()) throw InputError(std::string(command), "--in needs --out (the results CSV to write)");
  for (const auto& [text, key] : {std::pair{&options.k, "--k"}, std::pair{&options.h_nm, "--h-nm"},
                                  std::pair{&options.d_um, "--d-um"}, std::pair{&options.d0_um, "--d0-um"}}) {
    if (!text->empty()) {
      throw InputError(std::string(command), std::string(key) + " cannot be combined with --in: the file gives the measurements");
    }
  }
  const Overwrite overwrite = options.force ? Overwrite::allow : Overwrite::refuse;
  check_can_write(options.out, overwrite);

  const CsvTable table = read_csv(options.in);
  SampleBlock block(table.rows.size());
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
    block.set_column(required, *values);
  }
  const auto thickness = input_column(table, "h");
  if (thickness) block.set_column("h", *thickness);
  const bool has_h = thickness.has_value();

  const ThinShellTurgor turgor(parameters, command);
  const ThinShellModulus modulus;
  run_plan(plan_for(turgor, modulus, has_h), block);

  std::vector<std::string> header = table.header;
  std::vector<const Output*> written;
  for (const Output& output : outputs) {
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
  write_file_atomically(options.out, writer.text(), overwrite);

  std::cout << table.rows.size() << (table.rows.size() == 1 ? " tube" : " tubes") << " from " << table.path << " (rho = " << options.rho_um
            << " um, nu = " << format_double(parameters.poisson_ratio) << ", k_sys = "
            << (std::isinf(parameters.sensor_stiffness_N_per_m) ? "inf" : options.k_sys + " N/m") << ")"
            << (has_h ? "" : "; no thickness column h_nm: turgor outputs only") << "\n";
  for (const auto& [status, count] : counts) {
    std::cout << "  " << std::left << std::setw(28) << to_string(status) << count;
    if (status != SampleStatus::ok) std::cout << "  (" << describe(status) << ")";
    std::cout << "\n";
  }
  std::cout << "wrote " << options.out << "\n";
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
      ("in", po::value(&options.in), "CSV of tubes: columns k_N_per_m, d_um, d0_um [, h_nm] (other units allowed, e.g. h_um)")
      ("out", po::value(&options.out), "results CSV: the input columns, p_MPa, E_MPa, alpha_um, phi, lambda, "
                                       "hoop_stress_MPa, wall_stiffness_N_per_m, status")
      ("force", po::bool_switch(&options.force), "overwrite --out if it exists");
  po::variables_map values;
  if (!parse_arguments(arguments, "eval",
                       "--rho-um R (--k K --d-um D --d0-um D0 [--h-nm H] | --in tubes.csv --out results.csv) [options]",
                       "Inverts the thin-shell model for measured tubes: turgor p and decay length alpha from\n"
                       "(k, d, d0), modulus E, hoop stress and wall stiffness E h when h is known.\n"
                       "Valid for 1 < d/d0 <= e (beyond e the wall is past its pressure maximum); other tubes get a\n"
                       "status, not a number.",
                       described, {}, values)) {
    return 0;
  }
  if (!options.out.empty() && options.in.empty()) {
    throw InputError(std::string(command), "--out needs --in (a single tube is printed, not written)");
  }
  const Instrument parameters = instrument(options);
  return options.in.empty() ? evaluate_point(options, parameters) : evaluate_file(options, parameters);
}

}  // namespace growthuq::cli
