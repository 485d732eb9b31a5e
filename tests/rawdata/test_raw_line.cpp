// Raw line files: strict reading (every mistake one InputError naming file and line) and the
// fits behind a raw-data line: the chosen family is the least-AIC one, the lognormal estimate is
// the closed-form ML one recomputed here, blank cells are skipped, impossible values are named by
// row, and the fitted line file reads back as the same laws.
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/distributions/sampled_range.hpp"
#include "growthuq/rawdata/raw_line_file.hpp"
#include "growthuq/rawdata/raw_line_fit.hpp"

using namespace growthuq;
namespace fs = std::filesystem;

namespace {

struct Folder {
  fs::path root;
  Folder() : root(fs::temp_directory_path() / ("growthuq_test_raw_" + std::to_string(::getpid()))) {
    fs::remove_all(root);
    fs::create_directories(root);
  }
  ~Folder() { fs::remove_all(root); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(root / name) << text;
    return (root / name).string();
  }
};

const std::vector<double> stiffness{2.1, 2.9, 3.4, 2.5, 3.8, 2.2, 2.7, 3.1, 2.4, 4.6, 2.8, 3.0};

std::string table_text() {
  std::string text = "# a comment line\ntube,k_N_per_m,d_um\n";
  for (std::size_t i = 0; i < stiffness.size(); ++i) {
    // Tube 3 has no diameter (a blank cell: not measured).
    text += "T" + std::to_string(i) + "," + std::to_string(stiffness[i]) + "," + (i == 3 ? "" : std::to_string(6.0 + 0.1 * static_cast<double>(i))) + "\n";
  }
  return text;
}

const std::string line_header = "[line]\nname = test\n";                                       // lines 1-2
const std::string k_section = "[measurement k]\nfile = t.csv\ncolumn = k_N_per_m\nunit = N/m\n";  // lines 3-6

// The message of reading `text` as raw.ini in `folder` (which holds t.csv), without the path.
std::string error_of(const Folder& folder, const std::string& text) {
  const std::string path = folder.write("raw.ini", text);
  try {
    read_raw_line_file(path);
  } catch (const InputError& error) {
    const std::string message = error.what();
    return message.rfind(path, 0) == 0 ? message.substr(path.size()) : message;
  }
  return "no error";
}

std::string fit_error_of(const Folder& folder, const std::string& table) {
  folder.write("t.csv", table);
  const std::string path = folder.write("raw.ini", line_header + k_section);
  try {
    fit_raw_line(read_raw_line_file(path), RawFitSettings{});
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("raw line file: a valid file is read with paths relative to its folder") {
  Folder folder;
  folder.write("t.csv", table_text());
  folder.write("curves.csv", "curve,t_s,F_uN\n");
  const std::string path = folder.write(
      "raw.ini", line_header + "description = a test line\n" + k_section +
                     "families = lognormal, gamma\n\n[measurement d]\nfile = t.csv\ncolumn = d_um\nunit = um\n\n"
                     "[relaxation]\ncurves = curves.csv\nterms = 3\nfit = ramp_aware\n");
  const RawLineFile raw = read_raw_line_file(path);
  CHECK(raw.name == "test");
  CHECK(raw.description == "a test line");
  REQUIRE(raw.measurements.size() == 2);
  CHECK(fs::equivalent(raw.measurements[0].file, folder.root / "t.csv"));
  CHECK(raw.measurements[0].unit->symbol == "N/m");
  CHECK(raw.measurements[0].families == std::vector<FitFamily>{FitFamily::lognormal, FitFamily::gamma});
  CHECK(raw.measurements[1].families.size() == 4);
  CHECK(raw.has_relaxation);
  CHECK(raw.relaxation.terms == 3);
  CHECK(raw.relaxation.ramp_aware);
  CHECK(raw.relaxation.meta.empty());
  CHECK(raw.variables() == std::vector<std::string>{"k", "d", "tau", "einf"});
}

TEST_CASE("raw line file: every mistake names the file, the line and what was expected") {
  Folder folder;
  folder.write("t.csv", table_text());
  const auto check = [&](const std::string& text, const std::string& expected) {
    const std::string message = error_of(folder, text);
    CAPTURE(message);
    CHECK(message.find(expected) != std::string::npos);
  };
  check(line_header + k_section + "colour = red\n", ":7: unknown key 'colour' in [measurement k]");
  check(line_header + "[measurement x]\nfile = t.csv\n", ":3: [measurement x]: expected [measurement V] with V one of k, h, d, d0");
  check(line_header + "[measurements]\n", ":3: unknown section [measurements]");
  check(line_header + "[measurement k]\nfile = nothere.csv\ncolumn = k\nunit = N/m\n", ":4: file = 'nothere.csv': expected an existing file");
  check(line_header + "[measurement k]\nfile = t.csv\ncolumn = k\nunit = um\n", ":6: unit = 'um': expected a unit of stiffness for k (N/m)");
  check(line_header + "[measurement k]\nfile = t.csv\nunit = N/m\n", ":3: [measurement k] has no 'column'");
  check(line_header + k_section + "families = lognormal, cauchy\n", ":7: families = 'cauchy': expected lognormal, normal, gamma, weibull or beta (for einf)");
  check(line_header + k_section + "\n[measurement k]\nfile = t.csv\ncolumn = k_N_per_m\nunit = N/m\n",
        ":8: section [measurement k] repeats the one on line 3");
  check(line_header + k_section + "\n[measurement  k]\nfile = t.csv\ncolumn = k_N_per_m\nunit = N/m\n",
        ":8: variable k is measured twice (first at line 3)");
  check(line_header + "[measurement tau]\nfile = t.csv\ncolumn = k_N_per_m\nunit = s\n\n[relaxation]\ncurves = t.csv\n",
        ":3: [measurement tau] and [relaxation] (line 8) both give tau");
  check(line_header + "[relaxation]\ncurves = t.csv\nterms = 4\n", ":5: terms = '4'");
  check(line_header + "[relaxation]\ncurves = t.csv\nfit = exact\n", ":5: fit = 'exact': expected step or ramp_aware");
  check("[line]\ndescription = no name\n" + k_section, ":1: [line] has no 'name'");
  check(line_header, "nothing to fit");
}

TEST_CASE("raw line fit: least AIC, the closed-form lognormal ML, blank cells skipped") {
  Folder folder;
  folder.write("t.csv", table_text());
  const std::string path = folder.write("raw.ini", line_header + k_section + "\n[measurement d]\nfile = t.csv\ncolumn = d_um\nunit = um\n");
  const RawLineFit fit = fit_raw_line(read_raw_line_file(path), RawFitSettings{});
  REQUIRE(fit.variables.size() == 2);
  const VariableFit& k = fit.variables[0];
  CHECK(k.values == stiffness);
  CHECK(fit.variables[1].values.size() == stiffness.size() - 1);  // the blank cell
  REQUIRE(k.candidates.size() == 4);
  // The chosen family has the least AIC among those that fitted.
  for (const FamilyFit& candidate : k.candidates) {
    REQUIRE(candidate.result.has_value());
    CHECK(k.best().aic <= candidate.result->aic);
  }
  // Lognormal ML in closed form: mu = mean ln x, sigma^2 = mean (ln x - mu)^2 (divisor n).
  double mu = 0.0;
  for (const double x : stiffness) mu += std::log(x);
  mu /= static_cast<double>(stiffness.size());
  double variance = 0.0;
  for (const double x : stiffness) variance += (std::log(x) - mu) * (std::log(x) - mu);
  const double sigma = std::sqrt(variance / static_cast<double>(stiffness.size()));
  const auto& lognormal = std::get<Lognormal>(k.candidates[0].result->distribution);
  CHECK(lognormal.mu() == doctest::Approx(mu).epsilon(1e-14));
  CHECK(lognormal.sigma() == doctest::Approx(sigma).epsilon(1e-13));
  // The line's law is the chosen fit, in the table's unit, with a source naming the file.
  const LineVariable* variable = fit.distributions.find("k");
  REQUIRE(variable != nullptr);
  CHECK(variable->unit->symbol == "N/m");
  CHECK(quantile(variable->distribution, 0.3) == quantile(k.best().distribution, 0.3));
  CHECK(variable->source.find("t.csv, column k_N_per_m") != std::string::npos);
  // The report names every variable with its n and family.
  const std::string report = format_raw_fit_report(fit);
  CHECK(report.find(std::string(to_string(k.best().family))) != std::string::npos);
  CHECK(report.find("  d ") != std::string::npos);

  // The fitted line file reads back as the same laws.
  const std::string written = folder.write("fitted.ini", fitted_line_file_text(fit));
  const LineDistributions back = read_line_file(written);
  REQUIRE(back.variables.size() == 2);
  // ... and states the tubes it was fitted to, so a campaign on it has a data interval.
  CHECK(back.find("k")->tubes == k.values.size());
  CHECK(back.find("k")->tubes == k.best().sample_size);
  for (const double u : {0.01, 0.25, 0.5, 0.9}) {
    CHECK(quantile(back.find("k")->distribution, u) == doctest::Approx(quantile(variable->distribution, u)).epsilon(1e-14));
    CHECK(quantile(back.find("d")->distribution, u) ==
          doctest::Approx(quantile(fit.distributions.find("d")->distribution, u)).epsilon(1e-14));
  }
}

TEST_CASE("raw line fit: impossible values are named by row, failed families are reported") {
  Folder folder;
  const std::string negative = fit_error_of(folder, "tube,k_N_per_m\nA,2.5\nB,-1.2\nC,3.0\n");
  CHECK(negative.find("t.csv:3: k_N_per_m = '-1.2': expected a positive apparent stiffness") != std::string::npos);
  const std::string text = fit_error_of(folder, "tube,k_N_per_m\nA,2.5\nB,soft\n");
  CHECK(text.find("t.csv:3") != std::string::npos);
  const std::string column = fit_error_of(folder, "tube,stiffness\nA,2.5\n");
  CHECK(column.find("no column 'k_N_per_m' (the columns are: tube, stiffness)") != std::string::npos);
  // All values equal: no family fits, and each one's reason is reported.
  const std::string equal = fit_error_of(folder, "tube,k_N_per_m\nA,2.5\nB,2.5\nC,2.5\n");
  CAPTURE(equal);
  CHECK(equal.find("raw.ini:3: k (") != std::string::npos);
  CHECK(equal.find("no family could be fitted (lognormal: all 3 values equal 2.5") != std::string::npos);
  // einf as a percentage must lie in [0, 100).
  folder.write("e.csv", "tube,einf_pct\nA,65\nB,104\n");
  const std::string path = folder.write("raw.ini", line_header + "[measurement einf]\nfile = e.csv\ncolumn = einf_pct\nunit = %\n");
  try {
    fit_raw_line(read_raw_line_file(path), RawFitSettings{});
    FAIL("no error");
  } catch (const InputError& error) {
    CHECK(std::string(error.what()).find("e.csv:3: einf_pct = '104': expected a rescaled equilibrium modulus in [0, 1)") != std::string::npos);
  }
}

TEST_CASE("fit_variable_by_aic: a family that cannot fit is kept as a failure, the others compete") {
  // A value of 0 rules out the positive families; the normal law remains and is chosen.
  const VariableFit fit = fit_variable_by_aic("k", find_unit("N/m", "test", "unit"), {0.0, 0.6, 0.7, 0.65, 0.62},
                                              {std::begin(all_fit_families), std::end(all_fit_families)}, "test", "test");
  CHECK(fit.best().family == FitFamily::normal);
  for (const FamilyFit& candidate : fit.candidates) {
    CHECK(candidate.result.has_value() == (candidate.family == FitFamily::normal));
    if (!candidate.result) CHECK(candidate.failure.find("positive") != std::string::npos);
  }
}

TEST_CASE("fit_variable_by_aic on einf: the beta law is a candidate and no law that draws above 100 % can win") {
  // 40 e_inf values in % from Beta(12, 2) (mean 86 %, sd 9 %), inverted at the midpoints of 40
  // strata. Normal, lognormal, gamma and Weibull fits reach past 100 % in the upper tail a design
  // draws (the normal's at 1 - 1.1e-16 is about 86 + 8.2 x 9 = 160 %): they fail, and beta wins.
  const Beta truth(12.0, 2.0, 100.0);
  std::vector<double> values;
  for (int i = 0; i < 40; ++i) values.push_back(quantile(truth, (i + 0.5) / 40.0));
  const Unit& percent = find_unit("%", "test", "unit");
  const VariableFit fit = fit_variable_by_aic("einf", percent, values,
                                              {std::begin(fraction_fit_families), std::end(fraction_fit_families)},
                                              "test", "test");
  REQUIRE(fit.best().family == FitFamily::beta);
  CHECK(std::get<Beta>(fit.best().distribution).upper() == 100.0);
  for (const FamilyFit& candidate : fit.candidates) {
    CAPTURE(to_string(candidate.family));
    if (candidate.family == FitFamily::beta) continue;
    CHECK(!candidate.result);
    CHECK(candidate.failure.find("would draw fractions outside [0, 1]") != std::string::npos);
  }
  // Property: no value the chosen law gives a design, 10^5 strata and both extreme drawn
  // probabilities included, is above 100 % or below 0.
  const std::size_t n = 100000;
  std::vector<double> u(n), x(n);
  for (std::size_t i = 0; i < n; ++i) u[i] = (static_cast<double>(i) + 0.5) / static_cast<double>(n);
  u.front() = lowest_drawn_probability;
  u.back() = highest_drawn_probability;
  quantiles(fit.best().distribution, u, x);
  CHECK(*std::max_element(x.begin(), x.end()) <= 100.0);
  CHECK(*std::min_element(x.begin(), x.end()) >= 0.0);
  // The beta estimate is near the truth (40 values: alpha within a factor 2).
  CHECK(std::get<Beta>(fit.best().distribution).alpha() == doctest::Approx(12.0).epsilon(0.5));

  // The beta law is a law of fractions only.
  const VariableFit stiffness_fit = fit_variable_by_aic("k", find_unit("N/m", "test", "unit"), stiffness,
                                                        {FitFamily::beta, FitFamily::lognormal}, "test", "test");
  CHECK(stiffness_fit.best().family == FitFamily::lognormal);
  CHECK(stiffness_fit.candidates[0].failure == "the beta law is a law of fractions (einf); k is in N/m");
}

TEST_CASE("fit_variable_by_aic: a fitted law that would draw inf or 0 is a failed family, not a fit") {
  // 40 stiffnesses and one mistyped 1e300: every family's fit stretches past double precision
  // (the lognormal's sigma ~ 100 reaches inf, the gamma's and Weibull's tiny shapes reach 0, the
  // normal's sd is inf), so none is kept and the error names the data and each reason.
  std::vector<double> values;
  for (int i = 0; i < 40; ++i) values.push_back(2.0 + 0.05 * i);
  values.push_back(1e300);
  try {
    (void)fit_variable_by_aic("k", find_unit("N/m", "test", "unit"), values,
                              {std::begin(all_fit_families), std::end(all_fit_families)}, "k.csv, column k_N_per_m",
                              "raw.ini:7");
    FAIL("expected no family to be kept");
  } catch (const InputError& error) {
    const std::string message = error.what();
    CAPTURE(message);
    CHECK(message.rfind("raw.ini:7: k (k.csv, column k_N_per_m): no family could be fitted (", 0) == 0);
    CHECK(message.find("lognormal: lognormal(") != std::string::npos);
    CHECK(message.find("cannot be sampled: its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is inf") != std::string::npos);
    CHECK(message.find("cannot be sampled: its quantile at probability 2^-86 (1.3e-26) is 0") != std::string::npos);
  }

  // A wide but representable spread keeps its fit.
  std::vector<double> wide;
  for (int i = 0; i < 40; ++i) wide.push_back(std::exp(0.5 * i));
  const VariableFit fit = fit_variable_by_aic("k", find_unit("N/m", "test", "unit"), wide,
                                              {std::begin(all_fit_families), std::end(all_fit_families)}, "test", "test");
  CHECK(fit.candidates[fit.chosen].result.has_value());
}

TEST_CASE("raw line fit: a value more than a factor 1000 from its column's median is named as a likely typo") {
  Folder folder;
  // One stiffness typed 1e300 for 3.0: it gave a median turgor of 6e4 MPa without a word.
  const std::string typo = fit_error_of(folder, "tube,k_N_per_m\nA,2.5\nB,1e300\nC,3.0\nD,2.8\n");
  CHECK(typo.find("t.csv:3: k_N_per_m = '1e300': expected a value within a factor 1000 of the column's median 2.9 "
                  "(a typo, or a value in another unit?)") != std::string::npos);
  // Too small as well (a value in mN/m among N/m): median of 2.5, 3.0, 0.002, 2.8 is 2.65.
  CHECK(fit_error_of(folder, "tube,k_N_per_m\nA,2.5\nB,3.0\nC,0.002\nD,2.8\n")
            .find("t.csv:4: k_N_per_m = '0.002': expected a value within a factor 1000 of the column's median 2.65") !=
        std::string::npos);
  // A spread of a factor 100 is data, not a typo.
  CHECK(fit_error_of(folder, "tube,k_N_per_m\nA,0.1\nB,3.0\nC,10\nD,2.8\n").find("within a factor") == std::string::npos);
}
