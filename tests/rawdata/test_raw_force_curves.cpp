// A raw line whose k comes from raw force-indentation curves ([force_curves] in raw.ini): each
// tube's k is the mean of its ok curves, it lies within its uncertainty of the tube's truth, the
// report names the curves and how they were rated, and the section is read as strictly as the rest.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/forcecurves/force_curve.hpp"
#include "growthuq/rawdata/raw_line_file.hpp"
#include "growthuq/rawdata/raw_line_fit.hpp"
#include "growthuq/synthetic/indentation_curve.hpp"
#include "support/scratch_directory.hpp"

using namespace growthuq;

namespace {

const std::vector<double> tube_k{2.1, 2.9, 3.4, 2.5, 3.8, 2.2, 2.7, 3.1};

void write(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

// Three curves per tube of tube_k, the last tube's third one clipped (saturated).
void write_curves(const std::filesystem::path& folder) {
  std::vector<ForceCurve> curves;
  for (std::size_t t = 0; t < tube_k.size(); ++t) {
    IndentationTruth truth;
    truth.stiffness = tube_k[t];
    truth.sensor_stiffness = 100.0;
    truth.approach_samples = 500;
    truth.end = truth.contact + 6e-6 / tube_k[t];
    for (int r = 1; r <= 3; ++r) {
      const std::string tube = "T" + std::to_string(t);
      curves.push_back(simulate_indentation_curve(truth, 10 * t + static_cast<std::size_t>(r), tube + "_" + std::to_string(r), tube, r));
    }
  }
  for (double& f : curves.back().force) f = std::min(f, 3e-6);
  write(folder / "curves.csv", force_curves_csv(curves));
  write(folder / "sheet.csv", curve_sheet_csv(curves));
}

std::string error_of(const std::filesystem::path& folder, const std::string& text) {
  write(folder / "raw.ini", text);
  try {
    read_raw_line_file((folder / "raw.ini").string());
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("[force_curves]: k per tube from its curves, within the uncertainty of its truth") {
  testing::ScratchDirectory scratch("raw_force_curves");
  write_curves(scratch.root);
  write(scratch.root / "raw.ini", "[line]\nname = test\n\n[force_curves]\ncurves = curves.csv\nsheet = sheet.csv\n");
  const RawLineFile raw = read_raw_line_file((scratch.root / "raw.ini").string());
  REQUIRE(raw.has_force_curves);
  CHECK(raw.variables() == std::vector<std::string>{"k"});
  const RawLineFit fit = fit_raw_line(raw, RawFitSettings{});
  REQUIRE(fit.variables.size() == 1);
  REQUIRE(fit.force_curves);
  const VariableFit& k = fit.variables[0];
  CHECK(k.variable == "k");
  REQUIRE(k.values.size() == tube_k.size());
  for (std::size_t t = 0; t < tube_k.size(); ++t) {
    CAPTURE(t);
    const TubeStiffness& tube = fit.force_curves->tubes[t];
    CHECK(tube.ok == (t + 1 == tube_k.size() ? 2 : 3));
    CHECK(k.values[t] == tube.stiffness);  // N/m, the unit of the fit
    // Within 4 of its uncertainties (a Gaussian misses that with 6e-5 probability).
    CHECK(std::abs(k.values[t] - tube_k[t]) <= 4.0 * tube.uncertainty);
  }
  const std::string report = format_raw_fit_report(fit);
  CHECK(report.find("force curves: 24 of 8 tubes (ok 23, saturated 1); k of 8 tubes") != std::string::npos);
  CHECK(report.find("T7_3: saturated: ") != std::string::npos);
}

TEST_CASE("[force_curves] is read strictly") {
  testing::ScratchDirectory scratch("raw_force_curves_bad");
  write_curves(scratch.root);
  write(scratch.root / "t.csv", "tube,k_N_per_m\nA,2\nB,3\n");
  const std::string head = "[line]\nname = test\n";  // lines 1-2
  const std::string section = "[force_curves]\ncurves = curves.csv\nsheet = sheet.csv\n";  // lines 3-5
  CHECK(error_of(scratch.root, head + section + "window = sideways\n").find("raw.ini:6: window = 'sideways': expected relative or absolute") !=
        std::string::npos);
  CHECK(error_of(scratch.root, head + section + "window_uN = 0.5,4\n").find("raw.ini:6: [force_curves]: --window-uN") !=
        std::string::npos);
  CHECK(error_of(scratch.root, head + section + "contact = guess\n").find("raw.ini:6: contact = 'guess'") != std::string::npos);
  CHECK(error_of(scratch.root, head + "[force_curves]\ncurves = none.csv\nsheet = sheet.csv\n").find("raw.ini:4: curves = 'none.csv'") !=
        std::string::npos);
  CHECK(error_of(scratch.root, head + "[measurement k]\nfile = t.csv\ncolumn = k_N_per_m\nunit = N/m\n" + section)
            .find("both give k") != std::string::npos);
  CHECK(error_of(scratch.root, head + section + "window = absolute\n").empty());
}
