// ShellFeOptions' names, parsing and validation, and the statuses' names: everything a user
// types or reads about the finite-element model, in one place.
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/fe/indentation.hpp"

namespace growthuq {

std::string format_micro(double si) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%.12g", si * 1e6);
  return text.data();
}

std::string_view to_string(ShellFeLaw law) {
  return law == ShellFeLaw::hencky ? "log" : "stvk";
}

std::string_view to_string(ShellFeGeometry geometry) {
  switch (geometry) {
    case ShellFeGeometry::tube: return "tube";
    case ShellFeGeometry::sphere: return "sphere";
    case ShellFeGeometry::file: return "file";
  }
  return "?";
}

std::string_view to_string(ShellFeMesh mesh) {
  switch (mesh) {
    case ShellFeMesh::coarse: return "coarse";
    case ShellFeMesh::standard: return "default";
    case ShellFeMesh::fine: return "fine";
    case ShellFeMesh::finer: return "finer";
  }
  return "?";
}

std::string_view to_string(ShellFeStabilisationEnergy energy) {
  return energy == ShellFeStabilisationEnergy::model ? "model" : "step";
}

std::string_view to_string(ShellFeContact contact) {
  return contact == ShellFeContact::active_set ? "active_set" : "penalty";
}

ShellFeContact parse_shell_fe_contact(std::string_view text, std::string_view location, std::string_view key) {
  if (text == "active_set") return ShellFeContact::active_set;
  if (text == "penalty") return ShellFeContact::penalty;
  throw_bad_value(location, key, text, "active_set (exact contact) or penalty (the smooth penalty, for comparison)");
}

ShellFeLaw parse_shell_fe_law(std::string_view text, std::string_view location, std::string_view key) {
  if (text == "log") return ShellFeLaw::hencky;
  if (text == "stvk") return ShellFeLaw::saint_venant_kirchhoff;
  throw_bad_value(location, key, text, "log (Hencky: Kirchhoff stress = Hooke of the log strain) or stvk (Saint Venant-Kirchhoff)");
}

ShellFeGeometry parse_shell_fe_geometry(std::string_view text, std::string_view location, std::string_view key) {
  if (text == "tube") return ShellFeGeometry::tube;
  if (text == "sphere") return ShellFeGeometry::sphere;
  if (text == "file") return ShellFeGeometry::file;
  throw_bad_value(location, key, text, "tube, sphere or file");
}

ShellFeMesh parse_shell_fe_mesh(std::string_view text, std::string_view location, std::string_view key) {
  if (text == "coarse") return ShellFeMesh::coarse;
  if (text == "default") return ShellFeMesh::standard;
  if (text == "fine") return ShellFeMesh::fine;
  if (text == "finer") return ShellFeMesh::finer;
  throw_bad_value(location, key, text, "coarse, default, fine or finer");
}

bool parse_shell_fe_switch(std::string_view text, std::string_view location, std::string_view key) {
  if (text == "on") return true;
  if (text == "off") return false;
  throw_bad_value(location, key, text, "on or off");
}

double parse_shell_fe_tube_length(std::string_view text, std::string_view location, std::string_view key) {
  const double um = parse_double(text, location, key);
  if (!(um >= 5.0 && um <= 1e6)) throw_bad_value(location, key, text, "a tube length in [5, 1e6] um (default 100)");
  return um * 1e-6;
}

double parse_shell_fe_probe_distance(std::string_view text, std::string_view location, std::string_view key,
                                     double tube_length) {
  const double distance = parse_double(text, location, key) * 1e-6;
  if (!(distance >= 0.0 && distance < tube_length)) {
    throw_bad_value(location, key, text, "the probe's distance behind the apex in [0, tube_length) um (default 10)");
  }
  return distance;
}

std::array<double, 2> parse_shell_fe_force_window(std::string_view text, std::string_view location, std::string_view key) {
  const std::size_t comma = text.find(',');
  const auto low = comma == std::string_view::npos ? std::nullopt : try_parse_double(text.substr(0, comma));
  const auto high = comma == std::string_view::npos ? std::nullopt : try_parse_double(text.substr(comma + 1));
  if (!low || !high || !(*low >= 0.0) || !(*high > *low)) {
    throw_bad_value(location, key, text, "two forces 'LOW,HIGH' in uN with 0 <= LOW < HIGH (default 0.4,4)");
  }
  return {*low * 1e-6, *high * 1e-6};
}

ShellFeStabilisationEnergy parse_shell_fe_stabilisation_energy(std::string_view text, std::string_view location,
                                                               std::string_view key) {
  if (text == "model") return ShellFeStabilisationEnergy::model;
  if (text == "step") return ShellFeStabilisationEnergy::step;
  throw_bad_value(location, key, text, "model (the model's strain energy, the inflation's included) or step (what the "
                                       "indentation stores)");
}

void validate_stabilisation(const ShellFeStabilisation& stabilisation, std::string_view location,
                            std::string_view fraction_key, std::string_view ratio_key) {
  // The fraction may exceed 1: read as the share of one increment's dissipation (src/fe/README.md,
  // "Viscous stabilisation"), the step's is that times the number of increments. The cap's ratio
  // at 1 would let the damping take as much as the wall stores.
  if (!(std::isfinite(stabilisation.fraction) && stabilisation.fraction >= 0.0)) {
    throw_bad_value(location, fraction_key, format_double(stabilisation.fraction),
                    "a non-negative dissipated-energy fraction (0: off; the commercial code's default 2e-4)");
  }
  if (!(std::isfinite(stabilisation.ratio) && stabilisation.ratio >= 0.0 && stabilisation.ratio < 1.0)) {
    throw_bad_value(location, ratio_key, format_double(stabilisation.ratio),
                    "an adaptive damping ratio in [0, 1) (0: no cap; the study's driver 0.05)");
  }
  if (stabilisation.ratio > 0.0 && !stabilisation.active()) {
    throw_bad_value(location, ratio_key, format_double(stabilisation.ratio),
                    "0 unless a stabilisation fraction above 0 is given (the cap limits a damping there is none of)");
  }
}

void ShellFeOptions::validate(std::string_view location) const {
  if (geometry == ShellFeGeometry::file && mesh_file.empty()) {
    throw_bad_value(location, "mesh_file", "", "a closed triangulated surface file (geometry = file needs one)");
  }
  if (geometry != ShellFeGeometry::file && !mesh_file.empty()) {
    throw_bad_value(location, "mesh_file", mesh_file, "no mesh file unless geometry = file");
  }
  // The tube must hold its hemispherical tip (radius d0/2 <= 25 um over the envelope) and
  // reach well behind the probe; 1 m is an upper bound against a unit mistake.
  // The ends of [5, 1e6] um as typed: 5 um reaches here as 5 * 1e-6, a rounding below 5e-6.
  if (!(std::isfinite(tube_length) && tube_length >= 5e-6 * (1 - 1e-12) && tube_length <= 1.0 * (1 + 1e-12))) {
    throw_bad_value(location, "tube_length_um", format_micro(tube_length), "a tube length in [5, 1e6] um (default 100)");
  }
  if (!(std::isfinite(probe_distance) && probe_distance >= 0.0 && probe_distance < tube_length)) {
    throw_bad_value(location, "probe_distance_um", format_micro(probe_distance),
                    "the probe's distance behind the apex in [0, tube_length) um (default 10)");
  }
  const double low = force_window[0], high = force_window[1];
  if (!(std::isfinite(low) && std::isfinite(high) && low >= 0.0 && high > low)) {
    throw_bad_value(location, "force_window_uN", format_micro(low) + "," + format_micro(high),
                    "two forces 0 <= low < high in uN (default 0.4,4)");
  }
  validate_stabilisation(stabilisation, location, "stabilisation_fraction", "stabilisation_ratio");
  if (!(inflation_tolerance >= 0.0)) {
    throw_bad_value(location, "inflation_tolerance", format_double(inflation_tolerance),
                    "a non-negative relative diameter difference (default 1e-4; inf: far field only)");
  }
}

}  // namespace growthuq
