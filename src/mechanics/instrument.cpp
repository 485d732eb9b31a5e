// The instrument's ranges, its one check and its one parser (see the header for the physical
// reasons of each range).
#include "growthuq/mechanics/instrument.hpp"

#include <cmath>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"

namespace growthuq {
namespace {

// 1 mm: far above any indenting probe (tens of um at most), far below radii whose results
// underflow.
constexpr double max_probe_radius_m = 1e-3;

// The number spelled by `entry`'s text, "inf" allowed when `infinite_allowed`; the field's
// range message otherwise, so a typo and an out-of-range value read alike.
double number_of(const InstrumentEntry& entry, InstrumentField field, bool infinite_allowed) {
  const std::string_view text = trim(*entry.text);
  if (infinite_allowed && text == "inf") return std::numeric_limits<double>::infinity();
  if (const std::optional<double> value = try_parse_double(text)) return *value;
  throw_bad_value(entry.location, entry.key, *entry.text, instrument_range(field));
}

}  // namespace

std::string_view instrument_range(InstrumentField field) {
  switch (field) {
    case InstrumentField::probe_radius: return "a probe radius in um, > 0 and at most 1000";
    case InstrumentField::poisson_ratio: return "a Poisson ratio in [0, 0.5)";
    case InstrumentField::sensor_stiffness: return "a sensor stiffness in N/m, a number > 0 or inf (an ideal sensor)";
  }
  return "";
}

bool in_instrument_range(InstrumentField field, double value) noexcept {
  switch (field) {
    case InstrumentField::probe_radius: return value > 0.0 && value <= max_probe_radius_m;
    case InstrumentField::poisson_ratio: return value >= 0.0 && value < 0.5;
    case InstrumentField::sensor_stiffness: return value > 0.0;  // false for NaN, true for +inf
  }
  return false;
}

void check_instrument_value(InstrumentField field, double value, std::string_view location, std::string_view key,
                            std::string_view text) {
  if (!in_instrument_range(field, value)) throw_bad_value(location, key, text, instrument_range(field));
}

void validate(const Instrument& instrument, std::string_view location, ProbeRadius probe_radius) {
  if (probe_radius == ProbeRadius::required || !std::isnan(instrument.probe_radius_m)) {
    const double rho_um = to_um(instrument.probe_radius_m);
    check_instrument_value(InstrumentField::probe_radius, instrument.probe_radius_m, location, "probe_radius_um",
                           std::isnan(rho_um) ? "" : format_double(rho_um));
  }
  check_instrument_value(InstrumentField::poisson_ratio, instrument.poisson_ratio, location, "poisson_ratio",
                         format_double(instrument.poisson_ratio));
  const double k_sys = instrument.sensor_stiffness_N_per_m;
  check_instrument_value(InstrumentField::sensor_stiffness, k_sys, location, "sensor_stiffness_N_per_m",
                         std::isinf(k_sys) && k_sys > 0 ? "inf" : format_double(k_sys));
}

std::optional<double> given_probe_radius_m(const Instrument& instrument) {
  if (std::isnan(instrument.probe_radius_m)) return std::nullopt;
  return instrument.probe_radius_m;
}

Instrument parse_instrument(const InstrumentEntries& entries, ProbeRadius probe_radius) {
  Instrument instrument;
  if (const InstrumentEntry& rho = entries.probe_radius_um; rho.text) {
    // Checked in metres: a radius in um that underflows to 0 m (below ~1e-318 um) is rejected too.
    instrument.probe_radius_m = from_um(number_of(rho, InstrumentField::probe_radius, false));
    check_instrument_value(InstrumentField::probe_radius, instrument.probe_radius_m, rho.location, rho.key, *rho.text);
  } else if (probe_radius == ProbeRadius::required) {
    throw InputError(rho.location, rho.key + " is required: the probe radius dominates the turgor (p falls ~2x "
                                             "from 0.25 to 1 um) and has no default");
  }
  if (const InstrumentEntry& nu = entries.poisson_ratio; nu.text) {
    instrument.poisson_ratio = number_of(nu, InstrumentField::poisson_ratio, false);
    check_instrument_value(InstrumentField::poisson_ratio, instrument.poisson_ratio, nu.location, nu.key, *nu.text);
  }
  if (const InstrumentEntry& k_sys = entries.sensor_stiffness_N_per_m; k_sys.text) {
    instrument.sensor_stiffness_N_per_m = number_of(k_sys, InstrumentField::sensor_stiffness, true);
    check_instrument_value(InstrumentField::sensor_stiffness, instrument.sensor_stiffness_N_per_m, k_sys.location,
                           k_sys.key, *k_sys.text);
  }
  return instrument;
}

InstrumentEntries instrument_flags(std::string_view command, const std::string& rho_um, const std::string& nu,
                                   const std::string& k_sys) {
  const auto entry = [command](const std::string& text, std::string key) {
    return InstrumentEntry{text.empty() ? std::nullopt : std::optional<std::string>(text), std::string(command),
                           std::move(key)};
  };
  return {entry(rho_um, "--rho-um"), entry(nu, "--nu"), entry(k_sys, "--k-sys")};
}

}  // namespace growthuq
