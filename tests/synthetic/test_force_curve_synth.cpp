// synth's raw force curves (force_curve_repetitions > 0): written as `growthuq curves` reads
// them, and processed back to every tube's true k within the stated uncertainty.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string>

#include "growthuq/distributions/line_file.hpp"
#include "growthuq/forcecurves/curve_processing.hpp"
#include "growthuq/forcecurves/force_curve.hpp"
#include "growthuq/forcecurves/tube_stiffness.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/rawdata/raw_line_file.hpp"
#include "growthuq/rawdata/raw_line_fit.hpp"
#include "growthuq/synthetic/synthetic_line.hpp"
#include "support/scratch_directory.hpp"

using namespace growthuq;

TEST_CASE("synth's force curves read back and give each tube's true k within its uncertainty") {
  const LineDistributions truth = read_line_file(std::string(GROWTHUQ_SOURCE_DIR) + "/distributions/wild_type.ini");
  SynthSettings settings;
  settings.tubes = {20, 20};
  settings.force_curve_repetitions = 3;
  settings.force_curve.sensor_stiffness = 100.0;
  settings.force_curve.approach_samples = 1000;
  std::map<std::string, std::string> files;
  for (SynthFile& file : synthesize_line(truth, settings, "growthuq synth test")) files[file.name] = std::move(file.text);
  REQUIRE(files.count("force_curves.csv") == 1);
  REQUIRE(files.count("force_curves_sheet.csv") == 1);
  REQUIRE(files.count("force_curves_truth.csv") == 1);
  CHECK(files.at("force_curves.csv").rfind("# SYNTHETIC DATA, not measurements", 0) == 0);

  testing::ScratchDirectory scratch("synth_force_curves");
  for (const auto& [name, text] : files) std::ofstream(scratch.root / name) << text;
  const std::vector<ForceCurve> curves =
      read_force_curves((scratch.root / "force_curves.csv").string(), (scratch.root / "force_curves_sheet.csv").string());
  REQUIRE(curves.size() == 60);
  std::vector<CurveResult> results;
  for (const ForceCurve& curve : curves) results.push_back(process_force_curve(curve, CurveProcessingOptions{}));
  const std::vector<TubeStiffness> tubes = tube_stiffness(results);
  REQUIRE(tubes.size() == 20);

  const CsvTable table = read_csv((scratch.root / "force_curves_truth.csv").string());
  const std::vector<double> k_true = table.numeric_column("k_N_per_m");
  std::map<std::string, double> truth_of_tube;
  for (std::size_t row = 0; row < table.rows.size(); ++row) truth_of_tube[table.rows[row][1]] = k_true[row];
  // 20 tubes, each within 4 of its uncertainties (a Gaussian misses that with 6e-5 probability;
  // the coverage at 1.96 is measured in tests/forcecurves).
  for (const TubeStiffness& tube : tubes) {
    CAPTURE(tube.tube);
    REQUIRE(tube.ok == 3);
    CHECK(std::abs(tube.stiffness - truth_of_tube.at(tube.tube)) <= 4.0 * tube.uncertainty);
  }

  // raw.ini takes k from the curves: the raw line's k values are the tubes' k.
  const RawLineFile raw = read_raw_line_file((scratch.root / "raw.ini").string());
  REQUIRE(raw.has_force_curves);
  for (const RawMeasurement& measurement : raw.measurements) CHECK(measurement.variable != "k");
  const RawLineFit fit = fit_raw_line(raw, RawFitSettings{});
  const auto k = std::find_if(fit.variables.begin(), fit.variables.end(), [](const VariableFit& v) { return v.variable == "k"; });
  REQUIRE(k != fit.variables.end());
  REQUIRE(k->values.size() == tubes.size());
  for (std::size_t t = 0; t < tubes.size(); ++t) CHECK(k->values[t] == tubes[t].stiffness);
}
