// The instrument of a cellular force microscopy measurement: probe radius, the wall's Poisson
// ratio and the sensor stiffness in series with the tube. One type, one range per field,
// validated and parsed here for every command's flags and for the campaign file.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace growthuq {

struct Instrument {
  // Probe radius rho [m], > 0 and at most 1 mm (no indenting probe is larger; a radius of
  // 1e300 um gave statistics that underflowed, sd = 0 beside a positive IQR). Required wherever
  // turgor is computed: it dominates
  // the answer (p falls ~2x from rho = 0.25 to 1 um), so it has no default; NaN means "not
  // given" (the relaxation commands then read it per curve from the tube sheet).
  double probe_radius_m = std::numeric_limits<double>::quiet_NaN();
  // Poisson ratio nu of the wall, in [0, 0.5): an isotropic elastic solid has -1 < nu <= 0.5,
  // 0.5 being incompressible (bulk modulus E / (3 (1 - 2 nu)) infinite), and a plant cell wall
  // is neither auxetic (nu < 0) nor incompressible; the decay length (Eq. M3,
  // src/mechanics/README.md) needs 1 - nu^2 > 0, which the range keeps. 0.2 by default, the
  // value of the finite-element model of the published study (distributions/README.md).
  double poisson_ratio = 0.2;
  // Sensor stiffness k_sys [N/m] in series with the tube, > 0; +inf (an ideal sensor, no
  // series correction) by default and allowed.
  double sensor_stiffness_N_per_m = std::numeric_limits<double>::infinity();
  // Whether the models read rho per sample from the block's column "rho" (probe_radius_column.hpp)
  // rather than probe_radius_m: a campaign that gives a law of the probe radius ([probe_radius],
  // campaigns/README.md) samples it as an uncertain input, probe_radius_m then holding the law's
  // median for what needs one value (the mechanical rank correlation).
  bool probe_radius_per_sample = false;
};

// The fields, for messages and for the one range check below.
enum class InstrumentField { probe_radius, poisson_ratio, sensor_stiffness };

// What a field's range reads like in a message: "a probe radius in um, > 0 and at most 1000",
// "a Poisson ratio in [0, 0.5)", "a sensor stiffness in N/m, a number > 0 or inf (an ideal
// sensor)".
std::string_view instrument_range(InstrumentField field);

// Whether `value` (SI: m, 1, N/m) lies in the field's range. NaN never does; +inf only for the
// sensor stiffness.
bool in_instrument_range(InstrumentField field, double value) noexcept;

// The one check: InputError("<location>", "<key> = '<text>': expected <instrument_range>")
// unless `value` is in range. `text` is the value as the user wrote it.
void check_instrument_value(InstrumentField field, double value, std::string_view location, std::string_view key,
                            std::string_view text);

// Every field of `instrument` through check_instrument_value, named by its campaign-file key
// (probe_radius_um, poisson_ratio, sensor_stiffness_N_per_m) with the value in that unit. The
// probe radius is checked unless `probe_radius` is optional and it is NaN (not given).
enum class ProbeRadius { required, optional };
void validate(const Instrument& instrument, std::string_view location,
              ProbeRadius probe_radius = ProbeRadius::required);

// The probe radius [m] when given, nothing when NaN: the fallback of the relaxation readers for
// curves whose tube sheet has no rho_um column.
std::optional<double> given_probe_radius_m(const Instrument& instrument);

// The probe's sensor and the tube in series, 1/k_measured = 1/k_tube + 1/k_sys (Eq. (M8),
// src/mechanics/README.md); k_sys = inf leaves k unchanged. The first needs k_measured < k_sys.
inline double tube_stiffness(double k_measured, const Instrument& instrument) noexcept {
  return k_measured / (1.0 - k_measured / instrument.sensor_stiffness_N_per_m);
}
inline double measured_stiffness(double k_tube, const Instrument& instrument) noexcept {
  return k_tube / (1.0 + k_tube / instrument.sensor_stiffness_N_per_m);
}

// One setting as written: its text (nothing when absent), where it was written (a command,
// "file:line") and the key there ("--rho-um", "probe_radius_um").
struct InstrumentEntry {
  std::optional<std::string> text;
  std::string location;
  std::string key;
};

// The instrument settings of a command line or a campaign file section, in the units their
// keys name: probe radius in um, Poisson ratio, sensor stiffness in N/m ("inf" for an ideal
// sensor).
struct InstrumentEntries {
  InstrumentEntry probe_radius_um;
  InstrumentEntry poisson_ratio;
  InstrumentEntry sensor_stiffness_N_per_m;
};

// The one parser of the instrument, for every command and the campaign file. An absent entry
// keeps the default (probe radius: NaN, i.e. not given). Text that is not a finite number (or
// "inf" for the sensor stiffness) and values out of range give check_instrument_value's
// message; a required probe radius that is absent gives InputError("<location>", "<key> is
// required: the probe radius dominates the turgor (p falls ~2x from 0.25 to 1 um) and has no
// default").
Instrument parse_instrument(const InstrumentEntries& entries, ProbeRadius probe_radius);

// The entries of command-line flags --rho-um, --nu, --k-sys located at `command` (e.g.
// "growthuq eval"); empty text means the flag was not given.
InstrumentEntries instrument_flags(std::string_view command, const std::string& rho_um, const std::string& nu,
                                   const std::string& k_sys);

}  // namespace growthuq
