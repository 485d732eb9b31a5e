// growthuq indent: one forward simulation of the finite-element shell model (src/fe/README.md):
// inflate a tube of given p, E, h, d0 and press the probe into it. Writes the force curve as
// CSV (and, with --field, the deformed wall as HDF5 + XDMF) and prints `name = value` lines.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "growthuq/campaign/progress.hpp"
#include "commands.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/fe/field_output.hpp"
#include "growthuq/fe/indentation.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/io/output_file.hpp"
#include "options.hpp"
#include "shell_fe_flags.hpp"

namespace growthuq::cli {
namespace {

constexpr std::string_view command = "growthuq indent";
constexpr std::string_view usage =
    "--p-MPa P --E-MPa E (--h-nm H | --h0-nm H0) --d0-um D0 --rho-um R --out CURVE.csv [options]";

struct IndentFlags {
  std::string p_MPa, E_MPa, h_nm, h0_nm, d0_um, depth_um = "0";
  InstrumentFlags instrument;
  ShellFeFlags model;
  std::string stabilisation_fraction = "0", stabilisation_ratio = "0", stabilisation_energy = "model";
  std::string field;
  std::string out;
  bool force = false;
  bool quiet = false;
};

double positive(const std::string& text, std::string_view key, std::string_view what) {
  if (text.empty()) throw InputError(std::string(command), std::string(key) + " is required");
  const double value = parse_double(text, command, key);
  if (!(value > 0)) throw_bad_value(command, key, text, what);
  return value;
}

IndentationInput input_from(const IndentFlags& flags) {
  IndentationInput input;
  input.pressure = positive(flags.p_MPa, "--p-MPa", "a positive turgor in MPa") * 1e6;
  input.young = positive(flags.E_MPa, "--E-MPa", "a positive Young's modulus in MPa") * 1e6;
  if (flags.h_nm.empty() == flags.h0_nm.empty()) {
    throw InputError(std::string(command), "give the wall thickness once: --h-nm (turgid, as measured) or --h0-nm (unstressed)");
  }
  if (!flags.h_nm.empty()) {
    input.thickness = positive(flags.h_nm, "--h-nm", "a positive thickness in nm") * 1e-9;
    input.thickness_kind = ThicknessKind::turgid;
  } else {
    input.thickness = positive(flags.h0_nm, "--h0-nm", "a positive thickness in nm") * 1e-9;
    input.thickness_kind = ThicknessKind::unstressed;
  }
  input.plasmolysed_diameter = positive(flags.d0_um, "--d0-um", "a positive diameter in um") * 1e-6;
  if (input.thickness >= 0.5 * input.plasmolysed_diameter) {
    throw InputError(std::string(command), "the wall (" + (flags.h_nm.empty() ? flags.h0_nm : flags.h_nm) +
                                               " nm) must be thinner than half the diameter d0 (" + flags.d0_um + " um)");
  }
  input.depth = parse_double(flags.depth_um, command, "--depth-um") * 1e-6;
  if (!(input.depth >= 0 && input.depth <= input.plasmolysed_diameter)) {
    throw_bad_value(command, "--depth-um", flags.depth_um, "a depth in [0, d0] um (0: deep enough for the force window)");
  }
  input.instrument = flags.instrument.parse(command);
  return input;
}

// The study's driver's viscous stabilisation, from its three flags.
ShellFeStabilisation stabilisation_from(const IndentFlags& flags) {
  ShellFeStabilisation stabilisation;
  stabilisation.fraction = parse_double(flags.stabilisation_fraction, command, "--stabilisation-fraction");
  stabilisation.ratio = parse_double(flags.stabilisation_ratio, command, "--stabilisation-ratio");
  stabilisation.energy = parse_shell_fe_stabilisation_energy(flags.stabilisation_energy, command, "--stabilisation-energy");
  validate_stabilisation(stabilisation, command, "--stabilisation-fraction", "--stabilisation-ratio");
  return stabilisation;
}

void print(std::string_view name, const std::string& value) { std::cout << name << " = " << value << "\n"; }
void print(std::string_view name, double value) { print(name, format_double(value)); }

}  // namespace

int run_indent(const Arguments& arguments) {
  IndentFlags flags;
  po::options_description described("options");
  described.add_options()
      ("p-MPa", po::value(&flags.p_MPa), "turgor pressure p [MPa]")
      ("E-MPa", po::value(&flags.E_MPa), "Young's modulus of the wall E [MPa]")
      ("h-nm", po::value(&flags.h_nm), "wall thickness [nm] of the TURGID wall, as measured (h0 follows through the "
                                       "law's thickness stretch in the far field)")
      ("h0-nm", po::value(&flags.h0_nm), "instead of --h-nm: the unstressed (plasmolysed) wall thickness h0 [nm]")
      ("d0-um", po::value(&flags.d0_um), "plasmolysed (unstressed) mid-surface diameter d0 [um]")
      ("depth-um", po::value(&flags.depth_um), "deepest indentation [um], 0 to d0 (default 0: until the force passes "
                                               "the window's top, at most 0.6 d0)");
  flags.instrument.declare(described);
  flags.model.declare(described);
  described.add_options()
      ("stabilisation-fraction", po::value(&flags.stabilisation_fraction),
       "the study's driver's viscous stabilisation of the indentation, for measuring what it does (not for "
       "use): its dissipated-energy fraction, >= 0 (default 0: off; the commercial code's default 2e-4). "
       "Viscous forces c M* v (M* lumped, of unit density) resist each load step; c is set after the first "
       "increment (the driver's, 0.0005 um) so that increments like it would dissipate this fraction of the "
       "strain energy, both extrapolated over the step. The probe's force includes the viscous resistance")
      ("stabilisation-ratio", po::value(&flags.stabilisation_ratio),
       "adaptive cap of the stabilisation, in [0, 1): c is lowered (and the step solved again) wherever the "
       "dissipated energy would exceed this ratio of the strain energy (default 0: no cap; the driver's 0.05)")
      ("stabilisation-energy", po::value(&flags.stabilisation_energy),
       "the strain energy of the fraction and the cap: model (default; the model's, the inflation's included) or "
       "step (what the indentation stores: strain energy and -p V, from the indentation's start)")
      ("field", po::value(&flags.field), "also write the deformed wall at the deepest point: FILE.xdmf and FILE.h5 "
                                         "(per-face von Mises and principal membrane stresses in MPa, displacement per "
                                         "vertex in um; ParaView opens the .xdmf)")
      ("out", po::value(&flags.out), "force curve CSV: delta_um, F_uN, contact_radius_um (required)")
      ("force", po::bool_switch(&flags.force), "overwrite --out and --field if they exist")
      ("quiet", po::bool_switch(&flags.quiet), "no progress on stderr (by default: the depth reached, the time and "
                                               "the time left, as a bar on a terminal, a line every 5 s otherwise)");
  po::variables_map values;
  if (!parse_arguments(arguments, "indent", usage,
                       "One finite-element simulation of a pressurised pollen tube under a spherical probe: the wall\n"
                       "a nonlinear Kirchhoff-Love shell (membrane + bending), inflated from the plasmolysed state by\n"
                       "turgor p, then indented at the probe (displacement-controlled, frictionless contact with probe\n"
                       "and substrate). Diameters are mid-surface diameters. k is the slope of a least-squares line of\n"
                       "F against delta over the force window, as the instrument's software fits it.\n\n"
                       "Prints name = value lines: k_N_per_m (the tube; k_measured_N_per_m in series with --k-sys),\n"
                       "d_um (turgid diameter far from tip and end; the sphere's for --geometry sphere), axial_stretch,\n"
                       "thickness_stretch, h0_nm, contact_radius_um (at the window's top), newton_iterations, seconds,\n"
                       "seconds_assembly, seconds_factorisation, factorisations, seconds_contact, status (ok or why not: the\n"
                       "exit status is 0 whenever the simulation ran; k is printed only for status ok). With\n"
                       "--stabilisation-fraction, at the deepest point: strain_energy_pJ (the model's),\n"
                       "stored_by_indentation_pJ (strain energy and -p V the indentation added), dissipated_energy_pJ,\n"
                       "damping_factor and damping_lowerings (steps the cap solved again).",
                       described, {}, values)) {
    return 0;
  }
  if (flags.out.empty()) throw missing_argument("indent", usage, "--out");
  const IndentationInput input = input_from(flags);
  ShellFeOptions options = flags.model.parse(command);
  options.stabilisation = stabilisation_from(flags);
  const Overwrite overwrite = flags.force ? Overwrite::allow : Overwrite::refuse;
  check_can_write(flags.out, overwrite);
  if (!flags.field.empty()) {
    if (!flags.field.ends_with(".xdmf")) throw_bad_value(command, "--field", flags.field, "a file name ending in .xdmf");
    check_can_write(flags.field, overwrite);
    check_can_write(shell_field_data_path(flags.field), overwrite);
  }

  // A curve takes minutes: its progress in nanometres of depth, of the deepest it may go (an
  // automatic curve stops earlier, at the window's top: src/fe/indentation.cpp).
  const ProgressMode mode = choose_progress_mode(flags.quiet);
  std::optional<StepProgress> progress;
  std::size_t shown = 0;
  const auto follow = [&](double depth, double max_depth) {
    const auto total = static_cast<std::size_t>(std::lround(max_depth * 1e9));
    const auto reached = std::min(total, static_cast<std::size_t>(std::lround(depth * 1e9)));
    if (!progress) progress.emplace(mode, std::cerr, "indent", "nm of depth", total);
    progress->advance(reached - shown);
    shown = reached;
  };
  const IndentationCurve curve = indent(input, options, !flags.field.empty(), follow);
  if (progress) progress->clear();

  CsvWriter writer({"delta_um", "F_uN", "contact_radius_um"});
  for (std::size_t i = 0; i < curve.depth.size(); ++i) {
    const double radius = i < curve.contact_radius.size() ? curve.contact_radius[i] : 0.0;
    writer.add_row({format_double(curve.depth[i] * 1e6), format_double(curve.force[i] * 1e6), format_double(radius * 1e6)});
  }
  // The curve and its field commit together: the curve is written in full (a full disk shows
  // here) but renamed into place only after the field's files are, so a field that fails leaves
  // no curve behind (its partial file goes with `csv`).
  check_can_write(flags.out, overwrite);
  PartialFile csv(flags.out);
  csv.write(writer.text());
  csv.close();
  if (!flags.field.empty() && !curve.field.faces.empty()) write_shell_field(curve.field, flags.field, overwrite);
  csv.commit();

  std::cout << "# finite-element shell: " << describe(options) << ", rho = " << flags.instrument.rho_um
            << " um, nu = " << flags.instrument.nu << "\n";
  if (curve.status == SampleStatus::ok) {
    print("k_N_per_m", curve.stiffness);
    print("k_measured_N_per_m", curve.measured_stiffness);
    print("contact_radius_um", curve.window_contact_radius * 1e6);
  }
  if (curve.turgid_diameter > 0) {
    print("d_um", curve.turgid_diameter * 1e6);
    if (options.geometry == ShellFeGeometry::tube) print("axial_stretch", curve.axial_stretch);
    print("thickness_stretch", curve.thickness_stretch);
  }
  if (curve.unstressed_thickness > 0) print("h0_nm", curve.unstressed_thickness * 1e9);
  if (options.stabilisation.active() && !curve.strain_energy.empty()) {
    // At the curve's deepest point: what the damping dissipated against the strain energies the
    // fraction and the cap may be measured against.
    const double model = curve.strain_energy.back();
    const double step = model + curve.pressure_energy.back() - curve.strain_energy.front() - curve.pressure_energy.front();
    print("strain_energy_pJ", model * 1e12);
    print("stored_by_indentation_pJ", step * 1e12);
    print("dissipated_energy_pJ", curve.dissipated_energy.back() * 1e12);
    print("damping_factor", curve.damping_factor);
    print("damping_lowerings", static_cast<double>(curve.damping_lowerings));
  }
  print("points", static_cast<double>(curve.depth.size()));
  print("newton_iterations", static_cast<double>(curve.newton_iterations));
  print("seconds", curve.seconds);
  print("seconds_assembly", curve.seconds_assembly);
  print("seconds_factorisation", curve.seconds_factorisation);
  print("factorisations", static_cast<double>(curve.factorisations));
  print("seconds_contact", curve.seconds_contact);
  print("status", std::string(to_string(curve.status)));
  if (!curve.message.empty()) print("message", curve.message);
  std::cout << "wrote " << flags.out << (flags.field.empty() || curve.field.faces.empty() ? "" : " and " + flags.field) << "\n";
  return 0;
}

}  // namespace growthuq::cli
