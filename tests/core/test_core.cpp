// Strict number parsing, shortest round-trip formatting, units and error messages.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"

using namespace growthuq;

TEST_CASE("parse_double accepts whole finite numbers only") {
  CHECK(try_parse_double(" 2.87 ") == 2.87);
  CHECK(try_parse_double("+1e-3") == 1e-3);
  CHECK(try_parse_double("-0.5") == -0.5);
  CHECK_FALSE(try_parse_double("2.87x"));
  CHECK_FALSE(try_parse_double(""));
  CHECK_FALSE(try_parse_double("nan"));
  CHECK_FALSE(try_parse_double("inf"));
  CHECK_FALSE(try_parse_double("1e400"));
  CHECK_THROWS_WITH_AS(parse_double("abc", "f.csv:3", "column k"),
                       "f.csv:3: column k = 'abc': expected a finite number", InputError);
}

TEST_CASE("parse_count checks range and integrality") {
  CHECK(parse_count("1000", "", "--samples") == 1000);
  CHECK(parse_count("1e6", "", "--samples") == 1000000);
  CHECK_THROWS_AS(parse_count("2.5", "", "--samples"), InputError);
  CHECK_THROWS_AS(parse_count("-1", "", "--samples"), InputError);
  CHECK_THROWS_AS(parse_count("5", "", "--samples", 10, 20), InputError);
  // Digits are exact over the whole uint64 range (2^53 + 1 has no double).
  CHECK(parse_count("9007199254740993", "", "--seed") == 9007199254740993ULL);
  CHECK(parse_count(" 18446744073709551615 ", "", "--seed") == 18446744073709551615ULL);
  CHECK_THROWS_AS(parse_count("18446744073709551616", "", "--seed"), InputError);
}

TEST_CASE("format_double round-trips exactly") {
  for (double value : {0.1, 1.0 / 3.0, 6.02214076e23, 5e-324, -2.5, std::numeric_limits<double>::max()}) {
    CHECK(try_parse_double(format_double(value)) == value);
  }
  CHECK(format_double(0.5) == "0.5");
}

TEST_CASE("units convert to SI and name columns") {
  const Unit& nm = find_unit("nm", "", "unit");
  CHECK(nm.to_si == 1e-9);
  CHECK(column_name("h", nm) == "h_nm");
  CHECK(column_name("k", find_unit("N/m", "", "unit")) == "k_N_per_m");
  CHECK(column_name("eta", find_unit("MPa s", "", "unit")) == "eta_MPa_s");
  CHECK(column_name("phi", find_unit("1", "", "unit")) == "phi");
  CHECK_THROWS_AS(find_unit("furlong", "x.ini:4", "unit"), InputError);
  for (const Quantity& quantity : known_quantities()) {
    CHECK(find_unit(quantity.default_unit, "", "unit").dimension == quantity.dimension);
  }
  CHECK(default_column_name(*find_quantity("v")) == "v_um_per_s");
}
