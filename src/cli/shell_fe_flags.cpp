#include "shell_fe_flags.hpp"

#include <sstream>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"

namespace growthuq::cli {

void ShellFeFlags::declare(po::options_description& options) {
  options.add_options()
      ("law", po::value(&law), "wall law: log (default; Hencky, the Kirchhoff stress is Hooke's law of the log strain) "
                               "or stvk (Saint Venant-Kirchhoff)")
      ("geometry", po::value(&geometry), "tube (default; capped by a hemisphere, distal end pinned), sphere "
                                         "(closed, of diameter d0) or file (--mesh-file)")
      ("mesh-file", po::value(&mesh_file), "closed triangulated surface (Wavefront .obj or .off), lengths in units "
                                           "of d0 (--geometry file only)")
      ("mesh", po::value(&mesh), "mesh density: coarse, default or fine (omitted: default; each level sqrt(2) finer "
                                 "than the one before); finer, one level more, for convergence checks")
      ("contact", po::value(&contact), "contact of probe and substrate: active_set (default; exact, no penetration) or "
                                       "penalty (the smooth penalty, for comparison)")
      ("substrate", po::value(&substrate), "rigid frictionless plane under the tube, opposite the probe: on (default) or off")
      ("bending", po::value(&bending), "Kirchhoff-Love bending: on (default) or off (membrane only)")
      ("half-model", po::value(&half_model), "mirror plane through the tube axis and the probe axis: on (default) or off")
      ("tube-length-um", po::value(&tube_length_um), "tube length L [um], tip included (default 100; 5 to 1e6)")
      ("probe-distance-um", po::value(&probe_distance_um), "probe axis behind the apex [um] (default 10; 0 to L)")
      ("window-uN", po::value(&window_uN), "force window of the fit of k [uN], LOW,HIGH (default 0.4,4)");
}

void InstrumentFlags::declare(po::options_description& options) {
  options.add_options()
      ("rho-um", po::value(&rho_um), "probe radius [um] (required: it dominates k, and has no default)")
      ("nu", po::value(&nu), "Poisson ratio of the wall, in [0, 0.5) (default 0.2, as in the published FEM)")
      ("k-sys", po::value(&k_sys), "sensor stiffness [N/m] in series with the tube (default: ideal)");
}

// The one instrument parser and range check of every command and the campaign file.
Instrument InstrumentFlags::parse(std::string_view command) const {
  return parse_instrument(instrument_flags(command, rho_um, nu, k_sys), ProbeRadius::required);
}

ShellFeOptions ShellFeFlags::parse(std::string_view command) const {
  ShellFeOptions options;
  options.law = parse_shell_fe_law(law, command, "--law");
  options.geometry = parse_shell_fe_geometry(geometry, command, "--geometry");
  options.mesh_file = mesh_file;
  if (options.geometry == ShellFeGeometry::file && mesh_file.empty()) {
    throw InputError(std::string(command), "--geometry file needs --mesh-file (a closed .obj or .off surface)");
  }
  if (options.geometry != ShellFeGeometry::file && !mesh_file.empty()) {
    throw InputError(std::string(command), "--mesh-file needs --geometry file");
  }
  options.mesh = parse_shell_fe_mesh(mesh, command, "--mesh");
  options.contact = parse_shell_fe_contact(contact, command, "--contact");
  // The [shell_fe] section's parsers and messages, by the flag's name.
  options.substrate = parse_shell_fe_switch(substrate, command, "--substrate");
  options.bending = parse_shell_fe_switch(bending, command, "--bending");
  options.half_model = parse_shell_fe_switch(half_model, command, "--half-model");
  options.tube_length = parse_shell_fe_tube_length(tube_length_um, command, "--tube-length-um");
  options.probe_distance = parse_shell_fe_probe_distance(probe_distance_um, command, "--probe-distance-um", options.tube_length);
  options.force_window = parse_shell_fe_force_window(window_uN, command, "--window-uN");
  options.validate(command);  // the library's own check, as an invariant
  return options;
}

std::string describe(const ShellFeOptions& options) {
  std::ostringstream text;
  text << "law = " << to_string(options.law) << ", geometry = " << to_string(options.geometry);
  if (options.geometry == ShellFeGeometry::tube) {
    text << " (L = " << format_micro(options.tube_length) << " um, probe " << format_micro(options.probe_distance)
         << " um behind the apex)";
  } else if (options.geometry == ShellFeGeometry::file) {
    text << " (" << options.mesh_file << ")";
  }
  text << ", mesh = " << to_string(options.mesh) << ", contact " << to_string(options.contact) << ", substrate " << (options.substrate ? "on" : "off") << ", bending "
       << (options.bending ? "on" : "off") << (options.half_model ? ", half model" : ", full model") << ", window "
       << format_micro(options.force_window[0]) << "-" << format_micro(options.force_window[1]) << " uN";
  if (options.stabilisation.active()) {
    text << ", viscous stabilisation: fraction " << format_double(options.stabilisation.fraction) << " of the "
         << to_string(options.stabilisation.energy) << " strain energy, "
         << (options.stabilisation.ratio > 0 ? "capped at " + format_double(options.stabilisation.ratio) : std::string("no cap"));
  }
  return text.str();
}

}  // namespace growthuq::cli
