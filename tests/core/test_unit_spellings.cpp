// Unit spellings as lab files carry them: the micro sign and the Greek mu for "u", and growth
// rates timed per minute or per hour, converted by factors checked against a wider computation.
#include <doctest/doctest.h>

#include <cmath>

#include "growthuq/core/error.hpp"
#include "growthuq/core/units.hpp"

using namespace growthuq;

namespace {

const Unit& unit(const char* symbol) { return find_unit(symbol, "raw.ini:7", "unit"); }

// The spacing of doubles at `x` (x > 0), as a long double.
long double ulp_at(double x) { return static_cast<long double>(std::nextafter(x, HUGE_VAL)) - x; }

}  // namespace

TEST_CASE("the micro sign and the Greek mu are read as u") {
  // U+00B5 MICRO SIGN and U+03BC GREEK SMALL LETTER MU, as UTF-8 bytes.
  CHECK(&unit("\xC2\xB5m") == &unit("um"));
  CHECK(&unit("\xCE\xBCm") == &unit("um"));
  CHECK(&unit("\xC2\xB5m/s") == &unit("um/s"));
  CHECK(&unit("\xCE\xBCm/min") == &unit("um/min"));
  CHECK(&unit("\xC2\xB5m/h") == &unit("um/h"));
  // The symbol a file writes back is the table's: a fitted line file says "um".
  CHECK(unit("\xC2\xB5m").symbol == "um");
  // A lone micro sign, or one before a unit that has no micro form, is still refused, naming
  // what was written.
  CHECK_THROWS_WITH_AS(unit("\xC2\xB5"), doctest::Contains("raw.ini:7: unit = '\xC2\xB5': expected one of the units"),
                       InputError);
  CHECK_THROWS_AS(unit("\xC2\xB5Pa"), InputError);
}

TEST_CASE("growth rates per minute and per hour convert to m/s by the nearest doubles of 1e-6/60 and 1e-6/3600") {
  const Unit& per_min = unit("um/min");
  const Unit& per_h = unit("um/h");
  CHECK(per_min.dimension == Dimension::velocity);
  CHECK(per_h.dimension == Dimension::velocity);
  CHECK(column_name("v_exp", per_min) == "v_exp_um_per_min");
  CHECK(column_name("v_exp", per_h) == "v_exp_um_per_h");
  // Each factor is within half an ulp of the exact quotient, computed here in long double
  // (64-bit significand: its own error is 2^-11 of a double's half ulp).
  CHECK(std::fabs(static_cast<long double>(per_min.to_si) - 1e-6L / 60.0L) <= 0.5L * ulp_at(per_min.to_si));
  CHECK(std::fabs(static_cast<long double>(per_h.to_si) - 1e-6L / 3600.0L) <= 0.5L * ulp_at(per_h.to_si));
  // Hand computations: 60 um/min = 1 um/s, 90 um/min = 1.5 um/s, 5400 um/h = 1.5 um/s. Each
  // product lands on the double of the rate in m/s exactly (checked in exact rational arithmetic
  // when this test was written; a rounding either way would make these fail).
  CHECK(60.0 * per_min.to_si == unit("um/s").to_si);
  CHECK(90.0 * per_min.to_si == 1.5e-6);
  CHECK(5400.0 * per_h.to_si == 1.5e-6);
  CHECK(3600.0 * per_h.to_si == 1e-6);
}
