// Units and named quantities. Inside the engine every value is SI; units exist only at the
// edges (distribution files, CSV/HDF5 columns, command-line flags), where a column is named
// `<quantity>_<unit suffix>`, e.g. k_N_per_m, h_nm, d_um, eta_MPa_s, v_um_per_s.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace growthuq {

enum class Dimension { dimensionless, fraction, length, stiffness, pressure, time, velocity, viscosity };

std::string_view to_string(Dimension dimension);

// A unit as written in files ("nm", "N/m", "MPa s", "%"), the suffix it gives a column name
// ("nm", "N_per_m", "MPa_s", "pct") and the factor that converts a value to SI.
struct Unit {
  std::string_view symbol;
  std::string_view column_suffix;
  Dimension dimension;
  double to_si;
};

// Every unit the engine reads or writes.
std::span<const Unit> known_units();

// The unit spelled `symbol`; InputError naming location, key and the accepted symbols otherwise.
const Unit& find_unit(std::string_view symbol, std::string_view location, std::string_view key);

// A physical quantity the engine knows by name: its dimension, the unit it is written in by
// default and a short description for tables and --help.
struct Quantity {
  std::string_view name;
  Dimension dimension;
  std::string_view default_unit;
  std::string_view description;
};

// The quantities of the models (src/<concept>/README.md): measured inputs (k, h, d, d0, tau, einf,
// v_exp), model outputs (p, E, eta, v) and intermediate ones (lambda, alpha, phi, hoop_stress,
// wall_stiffness).
std::span<const Quantity> known_quantities();

// The quantity called `name`, or nullptr.
const Quantity* find_quantity(std::string_view name);

// "<name>_<suffix>" ("h_nm"); a dimensionless unit "1" gives the bare name.
std::string column_name(std::string_view quantity, const Unit& unit);

// The column name of `quantity` in its default unit.
std::string default_column_name(const Quantity& quantity);

}  // namespace growthuq
