// A campaign line whose k comes from raw force curves, run as a user runs it: the curve report
// is printed with the fits, k is not corrected twice for the sensor, and a model's force window
// that differs from the data's is refused before any sampling.
#include <doctest/doctest.h>

#include <fstream>
#include <string>
#include <vector>

#include "growthuq/forcecurves/force_curve.hpp"
#include "growthuq/synthetic/indentation_curve.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"

using namespace growthuq;
using namespace growthuq::testing;

namespace {

void write(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

// Ten tubes of two curves each (k 2.0-3.8 N/m, k_sys 100 N/m), their d, d0 and h, and raw.ini.
void write_line(const std::filesystem::path& folder, const std::string& force_curves_keys) {
  std::vector<ForceCurve> curves;
  std::string tubes = "tube,d_um,d0_um,h_nm\n";
  for (int t = 0; t < 10; ++t) {
    IndentationTruth truth;
    truth.stiffness = 2.0 + 0.2 * t;
    truth.sensor_stiffness = 100.0;
    truth.approach_samples = 400;
    truth.end = truth.contact + 6e-6 / truth.stiffness;
    for (int r = 1; r <= 2; ++r) {
      const std::string tube = "T" + std::to_string(t);
      curves.push_back(simulate_indentation_curve(truth, static_cast<std::uint64_t>(10 * t + r), tube + "r" + std::to_string(r), tube, r));
    }
    tubes += "T" + std::to_string(t) + "," + std::to_string(6.3 + 0.05 * t) + "," + std::to_string(5.2 + 0.03 * t) + "," +
             std::to_string(140 + t) + "\n";
  }
  write(folder / "curves.csv", force_curves_csv(curves));
  write(folder / "sheet.csv", curve_sheet_csv(curves));
  write(folder / "tubes.csv", tubes);
  std::string raw = "[line]\nname = curved\n\n[force_curves]\ncurves = curves.csv\nsheet = sheet.csv\n" + force_curves_keys;
  for (const char* variable : {"d", "d0", "h"}) {
    const std::string unit = std::string(variable) == "h" ? "nm" : "um";
    raw += "\n[measurement " + std::string(variable) + "]\nfile = tubes.csv\ncolumn = " + variable + "_" + unit + "\nunit = " + unit + "\n";
  }
  write(folder / "raw.ini", raw);
}

std::string campaign(const std::string& instrument_extra, const std::string& line_extra) {
  return "[campaign]\nname = curved\nseed = 3\nsamples = 100\noutputs = p\noutput_dir = out\nformats = csv\n\n"
         "[instrument]\nprobe_radius_um = 0.5\n" + instrument_extra + "\n[line curved]\nraw = raw.ini\nrank_correlation = none\n" +
         line_extra;
}

}  // namespace

TEST_CASE("a campaign from force curves: the curve report, and refusals of a double sensor correction and of another window") {
  ScratchDirectory scratch("campaign_force_curves");
  write_line(scratch.root, "");
  write(scratch.root / "run.ini", campaign("", ""));
  const CliOutcome run = run_cli("run run.ini --quiet", scratch.root);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(run.out.find("force curves: 20 of 10 tubes (ok 20); k of 10 tubes, the mean of their ok curves") != std::string::npos);

  write(scratch.root / "twice.ini", campaign("sensor_stiffness_N_per_m = 100\n", ""));
  const CliOutcome twice = run_cli("run twice.ini --quiet --out out_twice", scratch.root);
  INFO(twice.err);
  CHECK(twice.exit_code == 2);
  CHECK(twice.err.find("twice.ini:") != std::string::npos);
  CHECK(twice.err.find("so k is not corrected twice") != std::string::npos);

  // Fidelity corrected fits the model's k over [0.4, 4] uN from contact: the default relative
  // window is refused, the same absolute window is taken.
  write(scratch.root / "corrected.ini", campaign("", "fidelity = corrected\n"));
  const CliOutcome relative = run_cli("run corrected.ini --quiet --out out_relative", scratch.root);
  INFO(relative.err);
  CHECK(relative.exit_code == 2);
  CHECK(relative.err.find("fits the data's over [F_max - 4, F_max - 0.5] uN: expected window = absolute, window_uN = 0.4,4") !=
        std::string::npos);
  write_line(scratch.root, "window = absolute\nwindow_uN = 0.4,4\n");
  const CliOutcome same = run_cli("run corrected.ini --quiet --out out_same", scratch.root);
  INFO(same.err);
  CHECK(same.exit_code == 0);
}
