// Units and named quantities. Inside the engine every value is SI; units exist only at the
// edges (distribution files, CSV/HDF5 columns, command-line flags), where a column is named
// `<quantity>_<unit suffix>`, e.g. k_N_per_m, h_nm, d_um, eta_MPa_s, v_um_per_s.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace growthuq {

// Conversions between SI and the units written at the edges, for code that knows its unit at
// compile time (a flag named --rho-um, a column named h_nm). Each is one multiplication by a
// decimal power of ten, correctly rounded: into SI by the unit's factor (the `to_si` of the unit
// table below, so from_um(x) == x * find_unit("um", ...).to_si), out of SI by the reciprocal
// power written as its own decimal constant (1 / 1e-9 is not the double 1e9). A round trip may
// therefore move a value by an ulp, as any decimal scaling does.
namespace unit_factor {
// Unit -> SI.
inline constexpr double mm = 1e-3;
inline constexpr double um = 1e-6;
inline constexpr double nm = 1e-9;
inline constexpr double kPa = 1e3;
inline constexpr double MPa = 1e6;
inline constexpr double uN = 1e-6;  // force, micronewton (force curves, set points)
inline constexpr double um_per_s = 1e-6;
inline constexpr double nm_per_s = 1e-9;
// Growth rates as labs time them: the decimal expansions of 1e-6 / 60 and 1e-6 / 3600, which
// the compiler rounds once to the nearest double (1e-6 / 60.0 rounds twice, and only happens to
// agree).
inline constexpr double um_per_min = 1.6666666666666666666666666666666667e-8;
inline constexpr double um_per_h = 2.7777777777777777777777777777777778e-10;
inline constexpr double MPa_s = 1e6;
inline constexpr double pct = 1e-2;
// SI -> unit.
inline constexpr double per_um = 1e6;
inline constexpr double per_nm = 1e9;
inline constexpr double per_MPa = 1e-6;
inline constexpr double per_uN = 1e6;
inline constexpr double per_um_per_s = 1e6;
inline constexpr double per_MPa_s = 1e-6;
inline constexpr double per_pct = 1e2;
}  // namespace unit_factor

constexpr double from_um(double um) { return um * unit_factor::um; }
constexpr double from_nm(double nm) { return nm * unit_factor::nm; }
constexpr double from_MPa(double MPa) { return MPa * unit_factor::MPa; }
constexpr double from_uN(double uN) { return uN * unit_factor::uN; }
constexpr double from_um_per_s(double um_per_s) { return um_per_s * unit_factor::um_per_s; }
constexpr double from_pct(double pct) { return pct * unit_factor::pct; }

constexpr double to_um(double m) { return m * unit_factor::per_um; }
constexpr double to_nm(double m) { return m * unit_factor::per_nm; }
constexpr double to_MPa(double Pa) { return Pa * unit_factor::per_MPa; }
constexpr double to_uN(double N) { return N * unit_factor::per_uN; }
constexpr double to_um_per_s(double m_per_s) { return m_per_s * unit_factor::per_um_per_s; }
constexpr double to_MPa_s(double Pa_s) { return Pa_s * unit_factor::per_MPa_s; }
constexpr double to_pct(double fraction) { return fraction * unit_factor::per_pct; }

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
// The micro sign (U+00B5) and the Greek mu (U+03BC), in UTF-8, are read as "u": "µm" is "um".
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

// The unit of the quantity's dimension that a column named "<name>_<suffix>" (column_name) gives
// `quantity` in, or nullptr when `column` is no such name. The one reader of such names, for
// every file of measurements (`growthuq eval --in`, `growthuq fit`).
const Unit* unit_of_column(const Quantity& quantity, std::string_view column);

// The column name of `quantity` in its default unit.
std::string default_column_name(const Quantity& quantity);

}  // namespace growthuq
