// Strict number parsing, shortest round-trip formatting, units and error messages.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/printable.hpp"
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

TEST_CASE("named unit conversions are the unit table's factors and their decimal reciprocals") {
  // Into SI: the same multiplication as find_unit(...).to_si, so values read through a column's
  // unit and through a named helper are the same double.
  const auto to_si = [](const char* symbol) { return find_unit(symbol, "", "unit").to_si; };
  for (double x : {0.25, 0.5, 6.56, 145.0, 1.0 / 3.0, 1e-300, 1e300}) {
    CAPTURE(x);
    CHECK(from_um(x) == x * to_si("um"));
    CHECK(from_nm(x) == x * to_si("nm"));
    CHECK(from_MPa(x) == x * to_si("MPa"));
    CHECK(from_um_per_s(x) == x * to_si("um/s"));
    CHECK(from_pct(x) == x * to_si("%"));
  }
  // Out of SI: the reciprocal decimal power, within half an ulp of 1 / to_si (1 / 1e-9 is not
  // the double 1e9, so the reciprocal is a constant of its own).
  const struct {
    double to_si, from_si;
  } pairs[] = {{unit_factor::um, unit_factor::per_um},         {unit_factor::nm, unit_factor::per_nm},
               {unit_factor::MPa, unit_factor::per_MPa},       {unit_factor::uN, unit_factor::per_uN},
               {unit_factor::um_per_s, unit_factor::per_um_per_s}, {unit_factor::MPa_s, unit_factor::per_MPa_s},
               {unit_factor::pct, unit_factor::per_pct}};
  for (const auto& [into, out_of] : pairs) {
    CAPTURE(into);
    CHECK(std::fabs(into * out_of - 1.0) <= 2.3e-16);  // two roundings, each <= 2^-53 relative
  }
  CHECK(to_um(6.56e-6) == 6.56e-6 * 1e6);
  CHECK(to_nm(145e-9) == 145e-9 * 1e9);
  CHECK(to_MPa(0.3e6) == 0.3e6 * 1e-6);
  CHECK(to_uN(5e-6) == 5e-6 * 1e6);
  CHECK(to_pct(0.002) == 0.002 * 100.0);
  // A round trip through the two decimal constants moves a value by at most an ulp.
  for (double x : {0.25, 0.5, 6.56, 0.1, 0.7}) {
    CHECK(std::fabs(to_um(from_um(x)) - x) <= std::nextafter(x, 2 * x) - x);
    CHECK(std::fabs(to_nm(from_nm(x)) - x) <= std::nextafter(x, 2 * x) - x);
  }
}

TEST_CASE("printable escapes every control character, and only those, once") {
  using growthuq::printable;
  CHECK(printable("plain text, 2.87 N/m") == "plain text, 2.87 N/m");
  CHECK(printable("red\x1b[31m.ini") == "red\\x1b[31m.ini");
  CHECK(printable(std::string_view("a\0b", 3)) == "a\\x00b");
  CHECK(printable("tab\tnew\nline\rbell\x07" "del\x7f") == "tab\\x09new\\x0aline\\x0dbell\\x07del\\x7f");
  // UTF-8 text stays; the C1 controls as UTF-8 (U+009B, a CSI) are escaped byte by byte.
  CHECK(printable("\xc3\xa9 \xce\xbcm") == "\xc3\xa9 \xce\xbcm");
  CHECK(printable("\xc2\x9b" "2J \xc2\xa0") == "\\xc2\\x9b2J \xc2\xa0");
  // Idempotent: a message built from an escaped one is not escaped twice.
  CHECK(printable(printable("a\x1b")) == "a\\x1b");
}

TEST_CASE("an InputError's message is printable whatever input it quotes") {
  const growthuq::InputError error("in\x1b[2J.ini:3", "law = 'x\ny': expected lognormal");
  CHECK(std::string(error.what()) == "in\\x1b[2J.ini:3: law = 'x\\x0ay': expected lognormal");
  CHECK(error.location() == "in\\x1b[2J.ini:3");
  CHECK(error.problem() == "law = 'x\\x0ay': expected lognormal");
}
