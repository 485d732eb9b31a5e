// The instrument's one parser and range check: every field just inside and just outside its
// range, NaN, infinity and text, each refused with one message naming the key and the value as
// written; absent entries keep the documented defaults.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/mechanics/instrument.hpp"

using namespace growthuq;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

// The campaign-file spelling of one setting, the others absent.
InstrumentEntries only(const std::string& key, const std::string& text) {
  InstrumentEntries entries{{std::nullopt, "c.ini:3", "probe_radius_um"},
                            {std::nullopt, "c.ini:4", "poisson_ratio"},
                            {std::nullopt, "c.ini:5", "sensor_stiffness_N_per_m"}};
  for (InstrumentEntry* entry : {&entries.probe_radius_um, &entries.poisson_ratio, &entries.sensor_stiffness_N_per_m}) {
    if (entry->key == key) entry->text = text;
  }
  return entries;
}

Instrument parsed(const std::string& key, const std::string& text) {
  return parse_instrument(only(key, text), ProbeRadius::optional);
}

std::string error_of(const std::string& key, const std::string& text) {
  try {
    parsed(key, text);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

const std::string rho_range = "a probe radius in um, > 0 and at most 1000";
const std::string nu_range = "a Poisson ratio in [0, 0.5)";
const std::string k_sys_range = "a sensor stiffness in N/m, a number > 0 or inf (an ideal sensor)";

}  // namespace

TEST_CASE("instrument: absent entries keep the documented defaults") {
  const Instrument instrument = parse_instrument(only("none", ""), ProbeRadius::optional);
  CHECK(std::isnan(instrument.probe_radius_m));
  CHECK(instrument.poisson_ratio == 0.2);
  CHECK(instrument.sensor_stiffness_N_per_m == inf);
  CHECK_FALSE(given_probe_radius_m(instrument).has_value());
  CHECK_THROWS_WITH_AS(parse_instrument(only("none", ""), ProbeRadius::required),
                       "c.ini:3: probe_radius_um is required: the probe radius dominates the turgor (p falls ~2x from "
                       "0.25 to 1 um) and has no default",
                       InputError);
}

TEST_CASE("instrument: probe radius, > 0 and at most 1000 um, in um as written") {
  // The value in metres is the unit table's conversion of the number written: the same double.
  CHECK(parsed("probe_radius_um", "0.25").probe_radius_m == 0.25 * find_unit("um", "", "").to_si);
  CHECK(*given_probe_radius_m(parsed("probe_radius_um", "0.25")) == from_um(0.25));
  // Just inside: the smallest positive radius that survives the conversion, and the largest.
  CHECK(parsed("probe_radius_um", "1e-300").probe_radius_m == 1e-300 * 1e-6);
  CHECK(parsed("probe_radius_um", "1000").probe_radius_m == 1000 * 1e-6);
  // Just outside and non-numbers: one message naming the key and the text as written (1e300 um
  // gave statistics that underflowed).
  for (const char* text : {"0", "-0", "-1e-300", "nan", "inf", "-inf", "abc", "0.5um", "", "1e-320", "1000.001", "1e300"}) {
    CAPTURE(text);
    CHECK(error_of("probe_radius_um", text) == "c.ini:3: probe_radius_um = '" + std::string(text) + "': expected " + rho_range);
  }
}

TEST_CASE("instrument: Poisson ratio in [0, 0.5)") {
  CHECK(parsed("poisson_ratio", "0").poisson_ratio == 0.0);
  CHECK(parsed("poisson_ratio", "0.2").poisson_ratio == 0.2);
  // The largest double below 0.5 (0.5 - 2^-54) is inside; 0.5 itself is outside.
  CHECK(parsed("poisson_ratio", "0.49999999999999994").poisson_ratio == std::nextafter(0.5, 0.0));
  for (const char* text : {"0.5", "-1e-300", "-0.1", "0.7", "1", "nan", "inf", "-inf", "abc", "0.2 0.3"}) {
    CAPTURE(text);
    CHECK(error_of("poisson_ratio", text) == "c.ini:4: poisson_ratio = '" + std::string(text) + "': expected " + nu_range);
  }
}

TEST_CASE("instrument: sensor stiffness > 0 in N/m, inf for an ideal sensor") {
  CHECK(parsed("sensor_stiffness_N_per_m", "inf").sensor_stiffness_N_per_m == inf);
  CHECK(parsed("sensor_stiffness_N_per_m", " inf ").sensor_stiffness_N_per_m == inf);
  CHECK(parsed("sensor_stiffness_N_per_m", "4.9e-324").sensor_stiffness_N_per_m == std::numeric_limits<double>::denorm_min());
  CHECK(parsed("sensor_stiffness_N_per_m", "1e300").sensor_stiffness_N_per_m == 1e300);
  for (const char* text : {"0", "-0", "-1", "-inf", "nan", "infinity", "stiff", ""}) {
    CAPTURE(text);
    CHECK(error_of("sensor_stiffness_N_per_m", text) ==
          "c.ini:5: sensor_stiffness_N_per_m = '" + std::string(text) + "': expected " + k_sys_range);
  }
}

TEST_CASE("instrument: command-line flags are the same entries, located at the command") {
  const Instrument instrument = parse_instrument(instrument_flags("growthuq eval", "0.5", "0.3", "120"), ProbeRadius::required);
  CHECK(instrument.probe_radius_m == from_um(0.5));
  CHECK(instrument.poisson_ratio == 0.3);
  CHECK(instrument.sensor_stiffness_N_per_m == 120.0);
  CHECK_THROWS_WITH_AS(parse_instrument(instrument_flags("growthuq eval", "0.5", "0.5", ""), ProbeRadius::required),
                       ("growthuq eval: --nu = '0.5': expected " + nu_range).c_str(), InputError);
  CHECK_THROWS_WITH_AS(parse_instrument(instrument_flags("growthuq eval", "", "0.2", ""), ProbeRadius::required),
                       "growthuq eval: --rho-um is required: the probe radius dominates the turgor (p falls ~2x from "
                       "0.25 to 1 um) and has no default",
                       InputError);
}

TEST_CASE("instrument: validate() checks a built Instrument with the same ranges") {
  Instrument instrument;
  instrument.probe_radius_m = from_um(0.5);
  CHECK_NOTHROW(validate(instrument, "here"));
  instrument.sensor_stiffness_N_per_m = 50.0;
  CHECK_NOTHROW(validate(instrument, "here"));
  Instrument no_radius;
  CHECK_NOTHROW(validate(no_radius, "here", ProbeRadius::optional));
  CHECK_THROWS_WITH_AS(validate(no_radius, "here"), ("here: probe_radius_um = '': expected " + rho_range).c_str(), InputError);
  instrument.probe_radius_m = inf;
  CHECK_THROWS_WITH_AS(validate(instrument, "here", ProbeRadius::optional),
                       ("here: probe_radius_um = 'inf': expected " + rho_range).c_str(), InputError);
  instrument.probe_radius_m = from_um(0.5);
  instrument.poisson_ratio = not_a_number;
  CHECK_THROWS_WITH_AS(validate(instrument, "here"), ("here: poisson_ratio = 'nan': expected " + nu_range).c_str(), InputError);
  instrument.poisson_ratio = -0.1;
  CHECK_THROWS_WITH_AS(validate(instrument, "here"), ("here: poisson_ratio = '-0.1': expected " + nu_range).c_str(), InputError);
  instrument.poisson_ratio = 0.2;
  instrument.sensor_stiffness_N_per_m = -inf;
  CHECK_THROWS_WITH_AS(validate(instrument, "here"),
                       ("here: sensor_stiffness_N_per_m = '-inf': expected " + k_sys_range).c_str(), InputError);
  // The ranges themselves, at their edges.
  CHECK(in_instrument_range(InstrumentField::poisson_ratio, 0.0));
  CHECK_FALSE(in_instrument_range(InstrumentField::poisson_ratio, -0.0 - 1e-300));
  CHECK_FALSE(in_instrument_range(InstrumentField::poisson_ratio, 0.5));
  CHECK(in_instrument_range(InstrumentField::probe_radius, std::numeric_limits<double>::denorm_min()));
  CHECK_FALSE(in_instrument_range(InstrumentField::probe_radius, 0.0));
  CHECK(in_instrument_range(InstrumentField::probe_radius, 1e-3));
  CHECK_FALSE(in_instrument_range(InstrumentField::probe_radius, std::nextafter(1e-3, 1.0)));
  CHECK_FALSE(in_instrument_range(InstrumentField::sensor_stiffness, not_a_number));
}
