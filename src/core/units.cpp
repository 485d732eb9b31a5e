#include "growthuq/core/units.hpp"

#include <array>

#include "growthuq/core/error.hpp"

namespace growthuq {
namespace {

constexpr std::array units{
    Unit{"1", "", Dimension::dimensionless, 1.0},
    Unit{"frac", "frac", Dimension::fraction, 1.0},
    Unit{"%", "pct", Dimension::fraction, unit_factor::pct},
    Unit{"m", "m", Dimension::length, 1.0},
    Unit{"mm", "mm", Dimension::length, unit_factor::mm},
    Unit{"um", "um", Dimension::length, unit_factor::um},
    Unit{"nm", "nm", Dimension::length, unit_factor::nm},
    Unit{"N/m", "N_per_m", Dimension::stiffness, 1.0},
    Unit{"Pa", "Pa", Dimension::pressure, 1.0},
    Unit{"kPa", "kPa", Dimension::pressure, unit_factor::kPa},
    Unit{"MPa", "MPa", Dimension::pressure, unit_factor::MPa},
    Unit{"s", "s", Dimension::time, 1.0},
    Unit{"m/s", "m_per_s", Dimension::velocity, 1.0},
    Unit{"um/s", "um_per_s", Dimension::velocity, unit_factor::um_per_s},
    Unit{"nm/s", "nm_per_s", Dimension::velocity, unit_factor::nm_per_s},
    Unit{"um/min", "um_per_min", Dimension::velocity, unit_factor::um_per_min},
    Unit{"um/h", "um_per_h", Dimension::velocity, unit_factor::um_per_h},
    Unit{"Pa s", "Pa_s", Dimension::viscosity, 1.0},
    Unit{"MPa s", "MPa_s", Dimension::viscosity, unit_factor::MPa_s},
};

constexpr std::array quantities{
    Quantity{"k", Dimension::stiffness, "N/m", "apparent stiffness (CFM indentation)"},
    Quantity{"h", Dimension::length, "nm", "wall thickness of the turgid tube"},
    Quantity{"d", Dimension::length, "um", "turgid diameter"},
    Quantity{"d0", Dimension::length, "um", "plasmolysed diameter"},
    Quantity{"tau", Dimension::time, "s", "slow relaxation time"},
    Quantity{"einf", Dimension::fraction, "frac", "rescaled equilibrium modulus E_inf/E_r(0)"},
    Quantity{"v_exp", Dimension::velocity, "um/s", "experimental growth rate"},
    Quantity{"rho", Dimension::length, "um", "probe radius"},
    Quantity{"p", Dimension::pressure, "MPa", "turgor pressure"},
    Quantity{"E", Dimension::pressure, "MPa", "wall elastic modulus"},
    Quantity{"eta", Dimension::viscosity, "MPa s", "wall viscosity"},
    Quantity{"v", Dimension::velocity, "um/s", "predicted growth rate"},
    Quantity{"lambda", Dimension::dimensionless, "1", "stretch ratio d/d0"},
    Quantity{"alpha", Dimension::length, "um", "Arnoldi decay length"},
    Quantity{"phi", Dimension::dimensionless, "1", "Arnoldi factor x K1(x)/K0(x), x = rho/alpha"},
    Quantity{"hoop_stress", Dimension::pressure, "MPa", "hoop stress p d / (2 h)"},
    Quantity{"wall_stiffness", Dimension::stiffness, "N/m", "wall stiffness E h"},
};

// `symbol` with the micro sign and the Greek mu (either may come from a keyboard, Excel or a
// lab's software) spelled "u", as the unit table does.
std::string with_ascii_micro(std::string_view symbol) {
  std::string ascii(symbol);
  for (const std::string_view micro : {std::string_view("\xC2\xB5"), std::string_view("\xCE\xBC")}) {
    for (std::size_t at = ascii.find(micro); at != std::string::npos; at = ascii.find(micro, at + 1)) {
      ascii.replace(at, micro.size(), "u");
    }
  }
  return ascii;
}

}  // namespace

std::string_view to_string(Dimension dimension) {
  switch (dimension) {
    case Dimension::dimensionless: return "dimensionless";
    case Dimension::fraction: return "fraction";
    case Dimension::length: return "length";
    case Dimension::stiffness: return "stiffness";
    case Dimension::pressure: return "pressure";
    case Dimension::time: return "time";
    case Dimension::velocity: return "velocity";
    case Dimension::viscosity: return "viscosity";
  }
  return "unknown";
}

std::span<const Unit> known_units() { return units; }

const Unit& find_unit(std::string_view symbol, std::string_view location, std::string_view key) {
  const std::string ascii = with_ascii_micro(symbol);
  for (const Unit& unit : units) {
    if (unit.symbol == ascii) return unit;
  }
  std::string accepted;
  for (const Unit& unit : units) {
    accepted += (accepted.empty() ? "" : ", ") + std::string(unit.symbol);
  }
  throw_bad_value(location, key, symbol, "one of the units " + accepted);
}

std::span<const Quantity> known_quantities() { return quantities; }

const Quantity* find_quantity(std::string_view name) {
  for (const Quantity& quantity : quantities) {
    if (quantity.name == name) return &quantity;
  }
  return nullptr;
}

std::string column_name(std::string_view quantity, const Unit& unit) {
  std::string name(quantity);
  if (!unit.column_suffix.empty()) name += "_" + std::string(unit.column_suffix);
  return name;
}

const Unit* unit_of_column(const Quantity& quantity, std::string_view column) {
  for (const Unit& unit : units) {
    if (unit.dimension == quantity.dimension && column_name(quantity.name, unit) == column) return &unit;
  }
  return nullptr;
}

std::string default_column_name(const Quantity& quantity) {
  return column_name(quantity.name, find_unit(quantity.default_unit, "", "unit"));
}

}  // namespace growthuq
