// The finite-element model's command-line flags, shared by `growthuq indent` and `growthuq eval
// --fidelity shell_fe`: declared once, parsed once into ShellFeOptions (the struct a campaign's
// [shell_fe] section fills), with errors that name the flag and what was typed.
#pragma once

#include <string>
#include <string_view>

#include "growthuq/fe/indentation.hpp"
#include "options.hpp"

namespace growthuq::cli {

struct ShellFeFlags {
  std::string law = "log";
  std::string geometry = "tube";
  std::string mesh_file;
  std::string mesh = "default";
  std::string contact = "active_set";
  std::string substrate = "on";
  std::string bending = "on";
  std::string half_model = "on";
  std::string tube_length_um = "100";
  std::string probe_distance_um = "10";
  std::string window_uN = "0.4,4";

  // Adds --law, --geometry, --mesh-file, --mesh, --substrate, --bending, --half-model,
  // --tube-length-um, --probe-distance-um, --window-uN with their help lines.
  void declare(po::options_description& options);
  // The options, validated; InputError("<command>", "--<flag> = '<text>': expected ...").
  ShellFeOptions parse(std::string_view command) const;
};

// The instrument: probe radius, the wall's Poisson ratio, the sensor stiffness (the flags
// `growthuq eval` takes; kept here in one place for the instrument type that will unify them).
struct InstrumentFlags {
  std::string rho_um;
  std::string nu = "0.2";
  std::string k_sys;  // empty: an ideal sensor

  void declare(po::options_description& options);  // --rho-um, --nu, --k-sys
  Instrument parse(std::string_view command) const;
};

// One line of what the options are, for the output's header ("law = log, geometry = tube, ...").
std::string describe(const ShellFeOptions& options);

}  // namespace growthuq::cli
