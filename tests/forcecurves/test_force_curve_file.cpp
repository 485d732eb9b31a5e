// Reading raw force curves: the writers' output read back to the same numbers, the European
// dialect, one file per curve with nN or a voltage and its gain, and one-line errors naming file,
// line, column, value and what was expected.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/forcecurves/force_curve.hpp"
#include "growthuq/synthetic/indentation_curve.hpp"
#include "support/scratch_directory.hpp"

using namespace growthuq;
using growthuq::testing::ScratchDirectory;

namespace {

std::string write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path.string();
}

// A curve file of n approach samples z = 0.01 j um, F = max(0, z - 0.1) uN (and 3 retract rows),
// in `separator` dialect.
std::string curve_text(int n, const std::string& force_column = "F_uN", double scale = 1.0, char separator = ',') {
  std::string text = std::string("t_s") + separator + "z_um" + separator + force_column + "\n";
  auto number = [&](double x) {
    std::string s = std::to_string(x);
    if (separator == ';') s[s.find('.')] = ',';
    return s;
  };
  for (int j = 0; j < n + 3; ++j) {
    const int i = j < n ? j : 2 * n - 2 - j;
    const double z = 0.01 * i;
    text += number(0.1 * j) + separator + number(z) + separator + number(scale * std::max(0.0, z - 0.1)) + "\n";
  }
  return text;
}

const std::string sheet_header = "curve,tube,repetition,rho_um,k_sys_N_per_m\n";

// The error message of reading, or "" when it reads.
std::string error_of(const std::string& curves, const std::string& sheet) {
  try {
    read_force_curves(curves, sheet);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("synthetic curves written and read back: the same doubles, approach and retract apart") {
  ScratchDirectory scratch("forcecurves_roundtrip");
  std::vector<ForceCurve> curves;
  IndentationTruth truth;
  truth.approach_samples = 50;
  truth.sensor_stiffness = 100.0;
  curves.push_back(simulate_indentation_curve(truth, 1, "a1", "a", 1));
  curves.push_back(simulate_indentation_curve(truth, 2, "a2", "a", 2));
  const std::string file = write(scratch.root / "curves.csv", force_curves_csv(curves));
  const std::string sheet = write(scratch.root / "sheet.csv", curve_sheet_csv(curves));
  const std::vector<ForceCurve> read = read_force_curves(file, sheet);
  REQUIRE(read.size() == 2);
  for (std::size_t c = 0; c < 2; ++c) {
    CHECK(read[c].name == curves[c].name);
    CHECK(read[c].tube == "a");
    CHECK(read[c].repetition == static_cast<int>(c + 1));
    CHECK(read[c].approach_end == 50);
    CHECK(read[c].position.size() == 100);
    CHECK(read[c].sensor_stiffness_N_per_m == 100.0);
    CHECK(read[c].probe_radius_m == doctest::Approx(0.25e-6).epsilon(1e-15));
    for (std::size_t i = 0; i < 100; ++i) {
      // um and uN text scaled back to SI: one rounding of a decimal scaling each way.
      CHECK(read[c].position[i] == doctest::Approx(curves[c].position[i]).epsilon(4e-16));
      CHECK(read[c].force[i] == doctest::Approx(curves[c].force[i]).epsilon(4e-16));
      CHECK(read[c].time[i] == curves[c].time[i]);
    }
  }
}

TEST_CASE("a folder of one file per curve: nN, the European dialect, a voltage with its gain") {
  ScratchDirectory scratch("forcecurves_folder");
  write(scratch.root / "b1.csv", curve_text(30, "F_nN", 1000.0));
  write(scratch.root / "b2.csv", curve_text(30, "F_uN", 1.0, ';'));
  write(scratch.root / "b3.csv", curve_text(30, "V_V", 0.5));
  write(scratch.root / "sheet.csv", "curve,tube,repetition,rho_um,k_sys_N_per_m,gain_uN_per_V\n"
                                    "b1,b,1,0.25,inf,\nb2,b,2,0.25,100,\nb3,b,3,0.25,100,2\n");
  const std::vector<ForceCurve> curves = read_force_curves(scratch.root.string(), "");
  REQUIRE(curves.size() == 3);
  for (const ForceCurve& curve : curves) {
    INFO(curve.name);
    CHECK(curve.approach_end == 30);  // the position's maximum, no segment column
    CHECK(curve.force[29] == doctest::Approx(0.19e-6).epsilon(1e-12));  // z = 0.29 um: 0.19 uN however written
  }
  CHECK(std::isinf(curves[0].sensor_stiffness_N_per_m));
}

TEST_CASE("bad input: one line naming file, line, column, value and what was expected") {
  ScratchDirectory scratch("forcecurves_bad");
  const std::string sheet = write(scratch.root / "sheet.csv", sheet_header + "c,t,1,0.25,100\n");
  const std::string good = curve_text(30);
  auto curves_with = [&](const std::string& text) { return write(scratch.root / "c.csv", text); };
  REQUIRE(error_of(curves_with(good), sheet).empty());

  SUBCASE("a non-numeric force") {
    std::string text = good;
    text.replace(text.find("0.000000\n", text.find('\n', 40)), 8, "0.0x0000");
    const std::string message = error_of(curves_with(text), sheet);
    CHECK(message.find("c.csv:") != std::string::npos);
    CHECK(message.find("column F_uN") != std::string::npos);
    CHECK(message.find("0.0x0000") != std::string::npos);
    CHECK(message.find("expected") != std::string::npos);
  }
  SUBCASE("the position going back during the approach") {
    std::string text = "z_um,F_uN,segment\n";
    for (int j = 0; j < 30; ++j) text += std::to_string(j == 12 ? 0.05 : 0.01 * j) + ",0,approach\n";
    const std::string message = error_of(curves_with(text), sheet);
    CHECK(message.find("c.csv:14: column z_um = '0.050000'") != std::string::npos);
    CHECK(message.find("a position beyond the previous sample's (0.110000)") != std::string::npos);
  }
  SUBCASE("a segment that is neither approach nor retract, or an approach after a retract") {
    std::string text = "z_um,F_uN,segment\n";
    for (int j = 0; j < 30; ++j) text += std::to_string(0.01 * j) + ",0," + (j == 3 ? "approachh" : "approach") + "\n";
    CHECK(error_of(curves_with(text), sheet).find("c.csv:5: column segment = 'approachh': expected approach or retract") !=
          std::string::npos);
    text = "z_um,F_uN,segment\n";
    for (int j = 0; j < 30; ++j) text += std::to_string(0.01 * j) + ",0," + (j == 3 ? "retract" : "approach") + "\n";
    CHECK(error_of(curves_with(text), sheet).find("c.csv:6: column segment = 'approach'") != std::string::npos);
  }
  SUBCASE("two force columns, or none") {
    CHECK(error_of(curves_with("z_um,F_uN,F_nN\n0,0,0\n"), sheet).find("columns F_uN and F_nN: expected one force") !=
          std::string::npos);
    CHECK(error_of(curves_with("z_um,force\n0,0\n"), sheet).find("expected one of F_uN, F_nN, V_V") != std::string::npos);
  }
  SUBCASE("too short an approach") {
    CHECK(error_of(curves_with(curve_text(10)), sheet).find("10 approach samples: expected at least 20") != std::string::npos);
  }
  SUBCASE("the sheet: a missing row, a row of no curve, a repeated repetition, a bad k_sys, a voltage without gain") {
    const std::string curves = curves_with(good);
    CHECK(error_of(curves, write(scratch.root / "s1.csv", sheet_header + "d,t,1,0.25,100\n"))
              .find("s1.csv:2: curve = 'd': expected a curve of") != std::string::npos);
    CHECK(error_of(curves, write(scratch.root / "s2.csv", sheet_header + "c,t,1,0.25,100\nc,t,1,0.25,100\n"))
              .find("s2.csv:3: repetition = '1': expected one curve per repetition of tube 't'") != std::string::npos);
    CHECK(error_of(curves, write(scratch.root / "s3.csv", sheet_header + "c,t,1,0.25,-5\n"))
              .find("s3.csv:2: k_sys_N_per_m = '-5': expected a sensor stiffness") != std::string::npos);
    CHECK(error_of(curves, write(scratch.root / "s4.csv", sheet_header))
              .find("curve 'c' has no row in") != std::string::npos);
    const std::string volts = write(scratch.root / "v.csv", curve_text(30, "V_V"));
    CHECK(error_of(volts, write(scratch.root / "s5.csv", sheet_header + "v,t,1,0.25,100\n"))
              .find("s5.csv:2: curve 'v' is recorded as V_V: expected a positive gain_uN_per_V") != std::string::npos);
  }
  SUBCASE("a file without a sheet") {
    CHECK(error_of(curves_with(good), "").find("no curve sheet") != std::string::npos);
  }
}
