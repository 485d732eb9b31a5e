// The raw-data curve fits a campaign shares out over its processes (shared_raw_fits.hpp): a fit
// survives the trip between processes bit for bit, every field of it, and a raw line fitted
// through the shared fitter equals the line fitted alone. (That the processes of mpirun give
// the same campaign as one process is checked end to end by test_raw_campaign_mpi_* and
// test_from_raw_mpi_3, tests/campaign/CMakeLists.txt.) And the progress of such steps.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "growthuq/campaign/progress.hpp"
#include "campaign/shared_raw_fits.hpp"
#include "growthuq/pool/pool.hpp"
#include "growthuq/rawdata/raw_line_file.hpp"
#include "growthuq/rawdata/raw_line_fit.hpp"
#include "growthuq/relaxation/curves.hpp"

using namespace growthuq;

namespace {

const std::string wild_type_dir = std::string(GROWTHUQ_SOURCE_DIR) + "/distributions/example_raw/wild_type";

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

void require_same_fit(const CurveFit& a, const CurveFit& b) {
  CHECK(a.curve == b.curve);
  CHECK(a.ok == b.ok);
  CHECK(a.extrapolated == b.extrapolated);
  CHECK(a.reason == b.reason);
  CHECK(same_bits(a.tau, b.tau));
  CHECK(same_bits(a.amplitude, b.amplitude));
  CHECK(same_bits(a.einf, b.einf));
  CHECK(same_bits(a.modulus0, b.modulus0));
  CHECK(same_bits(a.relaxing_modulus, b.relaxing_modulus));
  CHECK(same_bits(a.viscosity, b.viscosity));
  CHECK(same_bits(a.tau_slow_relative_se, b.tau_slow_relative_se));
  CHECK(same_bits(a.tau_slow_low, b.tau_slow_low));
  CHECK(same_bits(a.tau_slow_high, b.tau_slow_high));
  CHECK(same_bits(a.rms, b.rms));
  CHECK(same_bits(a.aic, b.aic));
  CHECK(same_bits(a.ramp_time, b.ramp_time));
  CHECK(a.points == b.points);
  CHECK(same_bits(a.springs.k_inf, b.springs.k_inf));
  CHECK(same_bits(a.springs.k, b.springs.k));
  CHECK(same_bits(a.springs.tau, b.springs.tau));
}

std::vector<RelaxationCurve> wild_type_curves() {
  return read_relaxation_curves(wild_type_dir + "/relaxation_curves.csv", wild_type_dir + "/relaxation_meta.csv", 0.5e-6);
}

}  // namespace

TEST_CASE("a curve fit survives the trip between processes bit for bit") {
  std::vector<RelaxationCurve> curves = wild_type_curves();
  REQUIRE(curves.size() >= 2);
  // A curve cut to its first samples has no hold to fit: a failed fit with its reason.
  RelaxationCurve cut = curves[0];
  cut.name = "cut short";
  cut.t.resize(minimum_curve_samples);
  cut.force.resize(minimum_curve_samples);

  RelaxationOptions step;
  RelaxationOptions ramp_aware;
  ramp_aware.ramp_aware = true;
  ramp_aware.terms = 2;
  std::vector<CurveFit> fits{analyze_relaxation_curve(curves[0], step), analyze_relaxation_curve(curves[1], ramp_aware),
                             analyze_relaxation_curve(cut, step)};
  REQUIRE(fits[0].ok);
  REQUIRE(fits[1].ok);
  REQUIRE_FALSE(fits[1].springs.k.empty());  // the ramp-aware fit's springs travel too
  REQUIRE_FALSE(fits[2].ok);
  REQUIRE_FALSE(fits[2].reason.empty());
  fits[2].reason += " (\xc2\xb5m, non-ASCII)";  // every byte of a text travels

  for (const CurveFit& fit : fits) {
    CAPTURE(fit.curve);
    const std::vector<double> numbers = curve_fit_numbers(fit);
    require_same_fit(curve_fit_from_numbers(numbers), fit);
    // A record cut short or followed by more numbers is refused, not misread.
    CHECK_THROWS_AS(curve_fit_from_numbers(std::span<const double>(numbers).first(numbers.size() - 1)), std::invalid_argument);
    std::vector<double> longer = numbers;
    longer.push_back(0.0);
    CHECK_THROWS_AS(curve_fit_from_numbers(longer), std::invalid_argument);
  }
}

TEST_CASE("a raw line fitted through the shared curve fitter equals the line fitted alone") {
  const RawLineFile raw = read_raw_line_file(wild_type_dir + "/raw.ini");
  RawFitSettings alone;
  alone.instrument.probe_radius_m = 0.5e-6;
  const RawLineFit expected = fit_raw_line(raw, alone);

  const std::unique_ptr<Pool> pool = make_serial_pool();
  std::ostringstream log;
  RawFitSettings shared = alone;
  shared.fit_curves = shared_curve_fitter(*pool, "wt", ProgressMode::lines, log);
  const RawLineFit fit = fit_raw_line(raw, shared);

  REQUIRE(fit.relaxation.has_value());
  REQUIRE(fit.relaxation->fits.size() == expected.relaxation->fits.size());
  for (std::size_t c = 0; c < fit.relaxation->fits.size(); ++c) require_same_fit(fit.relaxation->fits[c], expected.relaxation->fits[c]);
  REQUIRE(fit.variables.size() == expected.variables.size());
  for (std::size_t v = 0; v < fit.variables.size(); ++v) {
    CAPTURE(fit.variables[v].variable);
    CHECK(same_bits(fit.variables[v].values, expected.variables[v].values));
    CHECK(describe(fit.variables[v].best().distribution) == describe(expected.variables[v].best().distribution));
  }
  // Without a terminal: one closing line when the line's curves are done, after a progress line
  // every 5 s if they take that long (about a second in a release build; longer under the
  // sanitizers).
  const std::string closing =
      "fitting relaxation curves of line wt: " + std::to_string(fit.relaxation->curves.size()) + " curves in ";
  std::vector<std::string> lines;
  std::istringstream logged(log.str());
  for (std::string line; std::getline(logged, line);) lines.push_back(line);
  REQUIRE(!lines.empty());
  CHECK(lines.back().rfind(closing, 0) == 0);
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
    CAPTURE(lines[i]);
    CHECK(lines[i].rfind("fitting relaxation curves of line wt: curve ", 0) == 0);
  }
}

TEST_CASE("step progress: nothing when quiet, a closing line without a terminal, a bar on one") {
  for (const ProgressMode mode : {ProgressMode::none, ProgressMode::lines, ProgressMode::bar}) {
    std::ostringstream out;
    StepProgress progress(mode, out, "data uncertainty", "replicate", 3);
    for (int i = 0; i < 3; ++i) progress.advance();
    progress.finish();
    const std::string text = out.str();
    CAPTURE(text);
    if (mode == ProgressMode::none) {
      CHECK(text.empty());
      continue;
    }
    // The closing line ends the output, after the bar is cleared on a terminal.
    const std::string closing = "data uncertainty: 3 replicates in ";
    const std::size_t at = text.rfind(closing);
    REQUIRE(at != std::string::npos);
    CHECK(text.back() == '\n');
    CHECK(std::count(text.begin(), text.end(), '\n') == 1);
    if (mode == ProgressMode::bar) {
      CHECK(text.rfind("\r\033[K[", 0) == 0);
      CHECK(text.find("data uncertainty: replicate 0/3, 0 s") != std::string::npos);
      CHECK(text.substr(at - 4, 4) == "\r\033[K");
    } else {
      CHECK(at == 0);  // a fast step prints no line before its closing one
    }
  }
}
