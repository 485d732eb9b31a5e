// growthuq synth: the synthetic relaxation experiment against its stated truth (the hold is the
// exact step response, a fit of a noise-free record returns the drawn tau_slow and einf), the
// raw data set's determinism and SYNTHETIC headers, and its per-tube values against the true
// laws (distribution-free order-statistic intervals for quartiles, and a pooled check of the
// fraction below the true median).
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "growthuq/core/units.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/rawdata/raw_line_file.hpp"
#include "growthuq/rawdata/raw_line_fit.hpp"
#include "growthuq/relaxation/analysis.hpp"
#include "growthuq/relaxation/modulus.hpp"
#include "growthuq/synthetic/relaxation_tube.hpp"
#include "growthuq/synthetic/synthetic_line.hpp"
#include "support/relaxation_curve.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> shipped_lines{"wild_type", "xxt1_xxt2", "xeg113", "xxt1_xxt2_xeg113", "pme48"};

LineDistributions truth_of(const std::string& line) {
  return read_line_file(std::string(GROWTHUQ_SOURCE_DIR) + "/distributions/" + line + ".ini");
}

// A wild-type-like tube (published data, distributions/README.md): p from k = 2.87, d = 6.56,
// d0 = 5.35 um at rho 0.5 um is 0.2528 MPa.
RelaxationTube wild_type_tube() {
  RelaxationTube tube;
  tube.turgor = 0.2528e6;
  tube.diameter = 6.56e-6;
  tube.thickness = 145e-9;
  tube.instrument.probe_radius_m = 0.5e-6;
  tube.stiffness0 = 2.87;
  tube.tau_slow = 6.81;
  tube.tau_fast = 0.25;
  tube.einf = 0.65;
  tube.fast_share = 0.3;
  return tube;
}

// E_r(t) / E_r(0) of the tube's stated truth.
double relative_modulus(const RelaxationTube& tube, double t) {
  return tube.einf + (1.0 - tube.einf) * (tube.fast_share * std::exp(-t / tube.tau_fast) +
                                          (1.0 - tube.fast_share) * std::exp(-t / tube.tau_slow));
}

// log P(B = k), B ~ binomial(n, p).
double log_binomial_pmf(std::size_t n, std::size_t k, double p) {
  const auto nn = static_cast<double>(n), kk = static_cast<double>(k);
  return std::lgamma(nn + 1) - std::lgamma(kk + 1) - std::lgamma(nn - kk + 1) + kk * std::log(p) + (nn - kk) * std::log1p(-p);
}

// 1-based ranks [r, s] with P(X(r) <= q_p <= X(s)) >= 1 - alpha for n draws of a continuous law:
// B = #{X_i < q_p} ~ binomial(n, p), and X(r) <= q_p <= X(s) iff r <= B + ... i.e. r - 1 < B + 1
// and B < s, so the coverage is P(r <= B + 1 <= s) = P(r - 1 <= B <= s - 1); the tails are cut
// at alpha / 2 each (Conover 1999, section 3.2).
std::pair<std::size_t, std::size_t> quantile_ranks(std::size_t n, double p, double alpha) {
  std::vector<double> cdf(n + 1);
  double sum = 0.0;
  for (std::size_t k = 0; k <= n; ++k) {
    sum += std::exp(log_binomial_pmf(n, k, p));
    cdf[k] = sum;
  }
  std::size_t low = 0;  // largest b with P(B < b) <= alpha / 2
  while (low + 1 <= n && cdf[low] <= alpha / 2) ++low;
  std::size_t high = n;  // smallest b with P(B > b) <= alpha / 2
  while (high > 0 && 1.0 - cdf[high - 1] <= alpha / 2) --high;
  return {low + 1, std::min(n, high + 1)};  // r - 1 = low, s - 1 = high
}

std::map<std::string, std::string> files_of(const std::vector<SynthFile>& files) {
  std::map<std::string, std::string> result;
  for (const SynthFile& file : files) result[file.name] = file.text;
  return result;
}

CsvTable parse_table(const std::string& text) {
  const std::string path = (fs::temp_directory_path() / ("growthuq_test_synth_table_" + std::to_string(::getpid()) + ".csv")).string();
  std::ofstream(path) << text;
  CsvTable table = read_csv(path);
  fs::remove(path);
  return table;
}

// A synthetic line drawn by `settings` from `truth`, written to a scratch folder, fitted by the
// raw-data path a campaign runs (fit_raw_line), with the per-curve truth synth wrote beside it.
struct FittedSynthLine {
  RawLineFit fit;
  CsvTable relaxation_truth;
};

FittedSynthLine fit_synthesized_line(const LineDistributions& truth, const SynthSettings& settings, const std::string& tag) {
  const auto files = synthesize_line(truth, settings, "test");
  const fs::path folder = fs::temp_directory_path() / ("growthuq_test_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  for (const SynthFile& file : files) std::ofstream(folder / file.name) << file.text;
  RawFitSettings fit_settings;
  fit_settings.instrument.probe_radius_m = settings.instrument.probe_radius_m;
  FittedSynthLine line{fit_raw_line(read_raw_line_file((folder / "raw.ini").string()), fit_settings),
                       read_csv((folder / "relaxation_truth.csv").string())};
  fs::remove_all(folder);
  return line;
}

}  // namespace

TEST_CASE("synthetic tube: the step stiffness is the forward image of the stated E_r(t)") {
  const RelaxationTube tube = wild_type_tube();
  const ShellGeometry shell{tube.turgor, tube.diameter, tube.thickness, tube.instrument};
  CHECK(tube_step_stiffness(tube, 0.0) == doctest::Approx(tube.stiffness0).epsilon(1e-12));
  const double modulus0 = relaxation_modulus(tube.stiffness0, shell);
  // Mapped back to E_r through the inverse Arnoldi relation, the stiffness gives the stated
  // series at every time (to the 1e-12 of the phi inversion, amplified 1.5x at this E_r).
  for (const double t : {0.01, 0.25, 1.0, 6.81, 30.0, 1e4}) {
    CAPTURE(t);
    CHECK(relaxation_modulus(tube_step_stiffness(tube, t), shell) / modulus0 ==
          doctest::Approx(relative_modulus(tube, t)).epsilon(1e-11));
  }
}

TEST_CASE("synthetic tube: the hold is delta k(E_r(t - t_ramp)) and a noise-free fit returns the truth") {
  const RelaxationTube tube = wild_type_tube();
  RampHoldProtocol protocol;
  protocol.rate = 1.0;  // 1 m/s: a ramp of ~2 us, a step for every purpose here
  protocol.hold = 30.0;
  protocol.sample_interval = 0.005;
  const SimulatedCurve simulated = simulate_relaxation_tube(tube, protocol, 0.0, 1);
  REQUIRE(simulated.ramp_end < 1e-5);
  // Every hold sample is the exact step response; what the ramp leaves (a 2 us ramp against
  // tau_fast = 0.25 s) is below 1e-5 relative.
  for (std::size_t i = 1; i < simulated.t.size(); ++i) {
    const double exact = simulated.indentation * tube_step_stiffness(tube, simulated.t[i] - simulated.ramp_end);
    CHECK(simulated.force[i] == doctest::Approx(exact).epsilon(1e-5));
  }
  // The step fit takes t = 0 and E_r(0) at the first hold sample, t_1 = 5 ms after the step:
  // it sees E_r(t + t_1) / E_r(t_1), whose constant is einf / y(t_1) and whose taus are the
  // tube's. The fit resolves them to the simplex tolerance and the 1e-5 model error: 1e-4.
  const CurveFit fit = analyze_relaxation_curve(as_curve(simulated, tube, "synthetic"), RelaxationOptions{});
  REQUIRE(fit.ok);
  const double offset = simulated.t[1] - simulated.ramp_end;
  CHECK(fit.tau[0] == doctest::Approx(tube.tau_fast).epsilon(1e-4));
  CHECK(fit.tau[1] == doctest::Approx(tube.tau_slow).epsilon(1e-4));
  CHECK(fit.einf == doctest::Approx(tube.einf / relative_modulus(tube, offset)).epsilon(1e-4));
}

TEST_CASE("synth: the same seed gives the same files, every file is marked SYNTHETIC") {
  const LineDistributions truth = truth_of("wild_type");
  SynthSettings settings;
  settings.seed = 5;
  settings.curves = {3, 4};
  const std::string command = "growthuq synth distributions/wild_type.ini --seed 5 --out somewhere";
  const auto first = files_of(synthesize_line(truth, settings, command));
  const auto again = files_of(synthesize_line(truth, settings, command));
  CHECK(first == again);
  settings.seed = 6;
  const auto other = files_of(synthesize_line(truth, settings, command));
  const std::vector<std::string> names{"raw.ini", "indentation.csv", "plasmolysis.csv", "tem_sections.csv", "growth.csv",
                                       "relaxation_curves.csv", "relaxation_meta.csv", "relaxation_truth.csv"};
  REQUIRE(first.size() == names.size());
  for (const std::string& name : names) {
    CAPTURE(name);
    REQUIRE(first.count(name) == 1);
    const std::string& text = first.at(name);
    CHECK(text.rfind("# SYNTHETIC DATA, not measurements", 0) == 0);
    CHECK(text.find("TRUE distributions in " + truth.path) != std::string::npos);
    CHECK(text.find("# Regenerate: " + command + "\n") != std::string::npos);
    if (name != "raw.ini") CHECK(other.at(name) != text);  // raw.ini names files, it holds no data
  }
  // Counts within the ranges asked for.
  for (const char* table : {"indentation.csv", "plasmolysis.csv", "tem_sections.csv", "growth.csv"}) {
    const std::size_t rows = parse_table(first.at(table)).rows.size();
    CHECK(rows >= 20);
    CHECK(rows <= 60);
  }
  const std::size_t curves = parse_table(first.at("relaxation_meta.csv")).rows.size();
  CHECK(curves >= 3);
  CHECK(curves <= 4);
}

TEST_CASE("synth: per-tube values follow the true laws within the sampling error of n tubes") {
  // Each table column of each shipped line under 4 seeds: the true quartiles and median inside
  // the distribution-free order-statistic intervals at level 1 - 1e-5 (300 intervals: a false
  // alarm with probability <= 0.3 %), widened by half the rounding resolution. Pooled over the
  // 20 data sets of a variable (~800 values), the fraction below the true median is within 4.5
  // standard errors of 1/2: an unbiased generator passes with probability 1 - 7e-6 per variable.
  struct Column {
    const char* table;
    const char* column;
    const char* variable;
    double resolution;
  };
  const std::vector<Column> columns{{"indentation.csv", "k_N_per_m", "k", 0.01}, {"indentation.csv", "d_um", "d", 0.01},
                                    {"plasmolysis.csv", "d0_um", "d0", 0.01},   {"tem_sections.csv", "h_nm", "h", 1.0},
                                    {"growth.csv", "v_exp_um_per_s", "v_exp", 1e-4}};
  std::map<std::string, std::pair<std::size_t, std::size_t>> below_median;  // variable -> (below, total)
  for (const std::string& line : shipped_lines) {
    const LineDistributions truth = truth_of(line);
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      SynthSettings settings;
      settings.seed = seed;
      settings.curves = {2, 2};
      const auto files = files_of(synthesize_line(truth, settings, "test"));
      for (const Column& column : columns) {
        CAPTURE(line);
        CAPTURE(seed);
        CAPTURE(column.column);
        std::vector<double> values = parse_table(files.at(column.table)).numeric_column(column.column);
        std::sort(values.begin(), values.end());
        const LineVariable& variable = *truth.find(column.variable);
        const Unit& table_unit = find_unit(find_quantity(column.variable)->default_unit, "test", "unit");
        const double to_table = variable.unit->to_si / table_unit.to_si;
        for (const double p : {0.25, 0.5, 0.75}) {
          const double true_quantile = quantile(variable.distribution, p) * to_table;
          const auto [r, s] = quantile_ranks(values.size(), p, 1e-5);
          CHECK(values[r - 1] - column.resolution / 2 <= true_quantile);
          CHECK(true_quantile <= values[s - 1] + column.resolution / 2);
        }
        const double median = quantile(variable.distribution, 0.5) * to_table;
        auto& [below, total] = below_median[column.variable];
        below += static_cast<std::size_t>(std::count_if(values.begin(), values.end(), [&](double v) { return v < median; }));
        total += values.size();
      }
    }
  }
  for (const auto& [variable, count] : below_median) {
    CAPTURE(variable);
    const double fraction = static_cast<double>(count.first) / static_cast<double>(count.second);
    MESSAGE(variable << ": " << count.first << " of " << count.second << " values below the true median");
    CHECK(std::abs(fraction - 0.5) <= 4.5 * std::sqrt(0.25 / static_cast<double>(count.second)));
  }
}

TEST_CASE("synth: the raw data set reads back as a raw line, its curves fit to their stated truth") {
  const LineDistributions truth = truth_of("wild_type");
  SynthSettings settings;
  settings.seed = 11;
  const FittedSynthLine line = fit_synthesized_line(truth, settings, "synth");
  const RawLineFit& fit = line.fit;
  CHECK(fit.raw.name == "wild_type");
  CHECK(fit.raw.variables() == std::vector<std::string>{"k", "d", "d0", "h", "v_exp", "tau", "einf"});
  REQUIRE(fit.relaxation.has_value());
  const CsvTable& truth_table = line.relaxation_truth;
  const std::vector<double> tau = truth_table.numeric_column("tau_slow_s");
  const std::vector<double> einf = truth_table.numeric_column("einf_frac");
  REQUIRE(tau.size() == fit.relaxation->fits.size());
  // Per curve against its truth: tau_slow within 4 of its own reported standard errors plus
  // 0.5 %; einf within 0.03. The step fit's einf is biased high by the first hold sample
  // falling after the ramp's end (up to one 20 ms sample of the fast phase): +0.005 on average,
  // measured over the shipped set (distributions/README.md); 0.03 is 5 standard deviations of its
  // scatter.
  std::size_t ok = 0;
  double einf_bias = 0.0;
  for (std::size_t c = 0; c < tau.size(); ++c) {
    const CurveFit& curve = fit.relaxation->fits[c];
    CAPTURE(curve.curve);
    CAPTURE(curve.reason);
    if (!curve.ok) {
      // A fit is allowed to fail only where the data hold little relaxation (einf near 1)
      // and the fast phase is then undetermined: reported, not hidden.
      CHECK(einf[c] > 0.85);
      continue;
    }
    ++ok;
    CHECK(std::abs(curve.tau.back() / tau[c] - 1.0) <= 4.0 * curve.tau_slow_relative_se + 0.005);
    CHECK(std::abs(curve.einf - einf[c]) <= 0.03);
    einf_bias += curve.einf - einf[c];
  }
  CHECK(ok >= tau.size() * 3 / 4);
  MESSAGE(ok << " of " << tau.size() << " curves fitted; mean einf error " << einf_bias / static_cast<double>(ok));
}

TEST_CASE("synth: the published 5 s hold: tau_slow beyond the record is fitted, extrapolated, its interval covers the truth") {
  // The study's protocol (5 uN set point, 5 s hold; synth's 100 um/s ramp, 50 Hz, 0.2 % force
  // noise) on wild-type tubes drawn from distributions/wild_type.ini, whose median tau_slow
  // (6.81 s) is longer than the hold. Each seed is one line's data set of 40 curves, fitted by
  // the raw-data path a campaign runs (fit_raw_line).
  const LineDistributions truth = truth_of("wild_type");
  const double true_median_tau = quantile(truth.find("tau")->distribution, 0.5) * truth.find("tau")->unit->to_si;
  const double true_median_einf = quantile(truth.find("einf")->distribution, 0.5) * truth.find("einf")->unit->to_si;
  const std::uint64_t seeds = 3;
  std::size_t curves = 0, fitted = 0, extrapolated = 0, covered = 0;
  for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
    SynthSettings settings;
    settings.seed = seed;
    settings.curves = {40, 40};
    settings.protocol.hold = 5.0;
    const FittedSynthLine line = fit_synthesized_line(truth, settings, "short_hold");
    const RawLineFit& fit = line.fit;
    const CsvTable& truth_table = line.relaxation_truth;
    REQUIRE(fit.relaxation.has_value());
    const std::vector<double> tau = truth_table.numeric_column("tau_slow_s");
    REQUIRE(tau.size() == fit.relaxation->fits.size());

    std::vector<double> fitted_tau, fitted_einf;
    const std::size_t extrapolated_before = extrapolated;
    for (std::size_t c = 0; c < tau.size(); ++c) {
      const CurveFit& curve = fit.relaxation->fits[c];
      CAPTURE(seed);
      CAPTURE(curve.curve);
      CAPTURE(curve.reason);
      ++curves;
      if (!curve.ok) continue;
      ++fitted;
      fitted_tau.push_back(curve.tau.back());
      fitted_einf.push_back(curve.einf);
      // The status says whether tau_slow is beyond the record, and the interval holds the estimate.
      const RelaxationCurve& record = fit.relaxation->curves[c];
      const auto peak = std::max_element(record.force.begin(), record.force.end()) - record.force.begin();
      const double hold = record.t.back() - record.t[static_cast<std::size_t>(peak)];
      // The hold runs from the force maximum, a noisy sample near the set point: up to a few
      // samples short of the protocol's 5 s.
      CHECK(hold == doctest::Approx(5.0).epsilon(0.03));
      CHECK(curve.extrapolated == (curve.tau.back() >= hold));
      CHECK(curve.tau_slow_low <= curve.tau.back());
      CHECK(curve.tau.back() <= curve.tau_slow_high);
      extrapolated += curve.extrapolated ? 1 : 0;
      covered += curve.tau_slow_low <= tau[c] && tau[c] <= curve.tau_slow_high ? 1 : 0;
    }
    // The campaign's fit report counts the extrapolated fits and names the widest interval.
    const std::string report = format_raw_fit_report(fit);
    CHECK(report.find(std::to_string(fitted_tau.size()) + " fitted (2-term step fit; " +
                      std::to_string(extrapolated - extrapolated_before) + " of them extrapolated") != std::string::npos);
    CHECK(report.find("widest 95 % interval of a fitted tau_slow: R") != std::string::npos);
    // The line: the true medians inside the distribution-free 95 % intervals of the median of
    // the curves' fitted values (Conover 1999, section 3.2), as is the fitted law's median.
    std::sort(fitted_tau.begin(), fitted_tau.end());
    std::sort(fitted_einf.begin(), fitted_einf.end());
    const auto [r, s] = quantile_ranks(fitted_tau.size(), 0.5, 0.05);
    MESSAGE("seed " << seed << ": median tau in [" << fitted_tau[r - 1] << ", " << fitted_tau[s - 1] << "] s, einf in ["
                    << fitted_einf[r - 1] << ", " << fitted_einf[s - 1] << "]");
    CHECK(fitted_tau[r - 1] <= true_median_tau);
    CHECK(true_median_tau <= fitted_tau[s - 1]);
    CHECK(fitted_einf[r - 1] <= true_median_einf);
    CHECK(true_median_einf <= fitted_einf[s - 1]);
    for (const VariableFit& variable : fit.variables) {
      if (variable.variable != "tau" && variable.variable != "einf") continue;
      const std::vector<double>& values = variable.variable == "tau" ? fitted_tau : fitted_einf;
      const double median = quantile(variable.best().distribution, 0.5);
      CHECK(values[r - 1] <= median);
      CHECK(median <= values[s - 1]);
    }
  }
  const double coverage = static_cast<double>(covered) / static_cast<double>(fitted);
  MESSAGE(fitted << " of " << curves << " curves fitted, " << extrapolated << " extrapolated; the 95 % profile interval "
                 << "of tau_slow covers the truth in " << covered << " (" << 100.0 * coverage << " %)");
  // Before, 5 of 21 such curves were fitted. Now nearly all are (93.5 % of 400 curves, seeds
  // 1-10), most beyond the record; what fails is a tau_slow at 10 holds or an undetermined fast phase.
  CHECK(fitted >= curves * 85 / 100);
  CHECK(extrapolated >= fitted / 3);
  // Coverage of a 95 % interval over `fitted` curves: binomial standard error ~2 % at 110 curves;
  // below 0.95 - 3 standard errors the intervals are too narrow.
  CHECK(coverage >= 0.95 - 3.0 * std::sqrt(0.95 * 0.05 / static_cast<double>(fitted)));
}
