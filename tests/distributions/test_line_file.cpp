// Line files: the five shipped files parse and reproduce the published table
// (distributions/README.md); every kind of mistake is one InputError naming file and line.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/distributions/sampled_range.hpp"

using namespace growthuq;

namespace {

std::string shipped(const std::string& stem) { return std::string(GROWTHUQ_SOURCE_DIR) + "/distributions/" + stem + ".ini"; }

std::string temporary_file(const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / "growthuq_test_line.ini").string();
  std::ofstream(path) << text;
  return path;
}

const std::string header = "[line]\nname = test\n";  // lines 1-2

// The error message of reading `body` after the [line] header, with the path stripped.
std::string error_of(const std::string& body) {
  const std::string path = temporary_file(header + body);
  try {
    read_line_file(path);
  } catch (const InputError& error) {
    const std::string message = error.what();
    return message.rfind(path, 0) == 0 ? message.substr(path.size()) : message;
  }
  return "no error";
}

const std::string k_ok = "[k]\nlaw = lognormal\nmedian = 2.87\niqr = 0.83\nunit = N/m\nsource = table\n";

}  // namespace

TEST_CASE("the five shipped line files parse and reproduce the published medians and IQRs") {
  constexpr double none = -1;  // "--" in the published table
  struct Published {
    const char* variable;
    double median;
    double iqr;
  };
  const std::vector<std::pair<std::string, std::vector<Published>>> table{
      {"wild_type", {{"k", 2.87, 0.83}, {"h", 145, 31}, {"d", 6.56, 1.19}, {"d0", 5.35, 1.15}, {"tau", 6.81, 3.61}, {"einf", 65.0, 18.2}, {"v_exp", 0.028, 0.011}}},
      {"xxt1_xxt2", {{"k", none, none}, {"h", 194, none}, {"d", 6.70, none}, {"d0", 5.06, 0.75}, {"tau", 4.38, 3.12}, {"einf", 66.0, 7.4}, {"v_exp", 0.036, 0.008}}},
      {"xeg113", {{"k", none, 2.53}, {"h", none, 28}, {"d", none, 1.14}, {"d0", 5.51, 1.67}, {"tau", 5.36, 2.56}, {"einf", 59.0, 4.3}, {"v_exp", 0.036, 0.007}}},
      {"xxt1_xxt2_xeg113", {{"k", none, 2.15}, {"h", none, 48}, {"d", none, 2.16}, {"d0", 6.14, 1.84}, {"tau", 6.09, 0.56}, {"einf", 62.0, 8.4}, {"v_exp", 0.042, 0.007}}},
      {"pme48", {{"k", 1.95, 0.39}, {"h", 199, 44}, {"d", 5.32, 1.03}, {"d0", 4.51, 1.16}, {"tau", 4.84, 1.63}, {"einf", 66.0, 4.5}, {"v_exp", 0.031, 0.021}}},
  };
  for (const auto& [stem, rows] : table) {
    CAPTURE(stem);
    const LineDistributions line = read_line_file(shipped(stem));
    CHECK(line.name == stem);
    REQUIRE(line.variables.size() == 7);
    for (const Published& row : rows) {
      CAPTURE(row.variable);
      const LineVariable* variable = line.find(row.variable);
      REQUIRE(variable != nullptr);
      CHECK(variable->unit->symbol == (std::string(row.variable) == "einf" ? "%" : find_quantity(row.variable)->default_unit));
      const double median = quantile(variable->distribution, 0.5);
      const double iqr = quantile(variable->distribution, 0.75) - quantile(variable->distribution, 0.25);
      // 1e-12 relative: the exact round trip m -> (mu, sigma) -> quantiles loses a few eps,
      // the IQR as a difference of quartiles ~ eps * m / r more (m / r < 50 here).
      if (row.median != none) CHECK(std::fabs(median - row.median) <= 1e-12 * row.median);
      if (row.iqr != none) CHECK(std::fabs(iqr - row.iqr) <= 1e-12 * row.iqr);
      // The study's only tube count: more than 20 indented tubes per line (stated as 21).
      CHECK(variable->tubes == (std::string(row.variable) == "k" ? 21U : 0U));
      const bool gap = row.median == none || row.iqr == none;
      CHECK((variable->source == "illustrative") == gap);
      if (gap) CHECK(!variable->note.empty());
    }
    // Every line keeps the turgid diameter above the plasmolysed one (lambda > 1).
    CHECK(quantile(line.find("d")->distribution, 0.5) > quantile(line.find("d0")->distribution, 0.5));
  }
}

TEST_CASE("line file: every law and its keys") {
  const std::string path = temporary_file(header +
      "[k]\nlaw = lognormal\nmu = 1\nsigma = 0.25\nunit = N/m\nsource = s\n"
      "[h]\nlaw = normal\nmean = 150\nsd = 20\nunit = um\nsource = s\n"
      "[d]\nlaw = truncated_normal\nmean = 6\nsd = 1\nlower = 4\nupper = inf\nunit = um\nsource = s\n"
      "[d0]\nlaw = uniform\nlower = 4\nupper = 6\nunit = um\nsource = s\n"
      "[tau]\nlaw = gamma\nshape = 4\nscale = 1.5\nunit = s\nsource = s\n"
      "[einf]\nlaw = beta\nalpha = 8\nbeta = 4\nunit = %\nsource = illustrative\nnote = why\n"
      "[v_exp]\nlaw = empirical\nvalues = 0.03, 0.02,0.04 , 0.05\nunit = um/s\nsource = s\n");
  const LineDistributions line = read_line_file(path);
  REQUIRE(line.variables.size() == 7);
  CHECK(std::get<Lognormal>(line.variables[0].distribution).sigma() == 0.25);
  CHECK(line.variables[1].unit->symbol == "um");
  CHECK(std::get<TruncatedNormal>(line.variables[2].distribution).upper() == HUGE_VAL);
  CHECK(std::get<Uniform>(line.variables[3].distribution).upper() == 6);
  CHECK(std::get<Gamma>(line.variables[4].distribution).scale() == 1.5);
  CHECK(line.variables[5].note == "why");
  CHECK(std::get<Beta>(line.variables[5].distribution).upper() == 100.0);  // the unit's 100 %
  CHECK(std::get<Empirical>(line.variables[6].distribution).sorted_data() == std::vector<double>{0.02, 0.03, 0.04, 0.05});
  CHECK(line.variables[4].line == 29);

  // format_line_variable writes a section that reads back to the same law.
  for (const LineVariable& variable : line.variables) {
    CAPTURE(variable.name);
    const LineDistributions again = read_line_file(temporary_file(header + format_line_variable(variable)));
    const Distribution& d = again.variables.at(0).distribution;
    CHECK(describe(d) == describe(variable.distribution));
    for (const double u : {0.1, 0.5, 0.9}) CHECK(quantile(d, u) == quantile(variable.distribution, u));
  }
}

TEST_CASE("line file: a fraction's law must keep every drawn value in [0, 100] %; beta is for fractions only") {
  // Weibull(8, 0.65): its quantile at 1 - 2^-53 is 0.65 (ln 2^53)^(1/8) = 0.65 x 1.5690 = 1.0199 > 1.
  const std::string weibull = error_of("[einf]\nlaw = weibull\nshape = 8\nscale = 0.65\nunit = frac\nsource = s\n");
  CAPTURE(weibull);
  CHECK(weibull.rfind(":3: [einf] law weibull(shape=8, scale=0.65) in frac: its quantile at probability 1 - 2^-53 "
                      "(1 - 1.1e-16) is 1.01988", 0) == 0);
  CHECK(weibull.find(", above 1 (a fraction of 1): expected a law of values in [0, 1] as a fraction") != std::string::npos);
  // A normal in % reaching below 0.
  CHECK(error_of("[einf]\nlaw = normal\nmean = 60\nsd = 10\nunit = %\nsource = s\n").find(
            "its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is 142.") != std::string::npos);
  // The shipped truncated normal on [0, 100] % and a beta stay inside.
  CHECK(error_of("[einf]\nlaw = truncated_normal\nmean = 65\nsd = 14\nlower = 0\nupper = 100\nunit = %\nsource = s\n") ==
        "no error");
  CHECK(error_of("[einf]\nlaw = beta\nalpha = 0.3\nbeta = 0.2\nunit = frac\nsource = s\n") == "no error");
  CHECK(error_of("[k]\nlaw = beta\nalpha = 2\nbeta = 3\nunit = N/m\nsource = s\n") ==
        ":4: law = 'beta': expected a law of k (apparent stiffness (CFM indentation)): beta is a law of fractions (einf)");
}

TEST_CASE("line file: each mistake is one error naming file and line") {
  CHECK(error_of(k_ok) == "no error");
  CHECK(error_of(k_ok + "color = red\n") == ":9: unknown key 'color': expected law, unit, source, note, tubes or median and iqr, or mu and sigma");
  CHECK(error_of(k_ok + "sd = 1\n") == ":9: key 'sd' is not a parameter of law = lognormal (line 4): expected median and iqr, or mu and sigma");
  CHECK(error_of(k_ok + "mu = 1\n") == ":9: key 'mu' is not a parameter of law = lognormal (line 4): expected median and iqr, or mu and sigma");
  CHECK(error_of("[k]\nlaw = lognormal\nmedian = 2.87\niqr = -0.3\nunit = N/m\nsource = s\n") == ":6: iqr = '-0.3': expected a positive number");
  CHECK(error_of("[k]\nlaw = lognormal\nmedian = 2.87\niqr = 0.3x\nunit = N/m\nsource = s\n") == ":6: iqr = '0.3x': expected a finite number");
  CHECK(error_of("[k]\nlaw = lognormal\nmedian = 2.87\niqr = 0.3\nsource = s\n") == ":3: [k] has no 'unit': expected the unit of the values, e.g. unit = N/m");
  CHECK(error_of("[k]\nlaw = lognormal\nmedian = 2.87\niqr = 0.3\nunit = MPa\nsource = s\n") ==
        ":7: unit = 'MPa': expected a unit of stiffness for k (N/m)");
  CHECK(error_of("[einf]\nlaw = lognormal\nmedian = 65\niqr = 18\nunit = s\nsource = s\n") ==
        ":7: unit = 's': expected a unit of fraction for einf (frac, %)");
  CHECK(error_of("[k]\nlaw = lognormal\nmedian = 2.87\niqr = 0.3\nunit = furlong\nsource = s\n").find(":7: unit = 'furlong': expected one of the units") == 0);
  CHECK(error_of(k_ok + k_ok) == ":9: section [k] repeats the one on line 3");
  CHECK(error_of("[p]\nlaw = lognormal\nmedian = 0.3\niqr = 0.1\nunit = MPa\nsource = s\n") ==
        ":3: unknown variable [p]: expected [line] or one of the measured variables k, h, d, d0, tau, einf, v_exp");
  CHECK(error_of("[k]\nlaw = lognormal\nmedian = 2.87\niqr = 0.3\nunit = N/m\n") ==
        ":3: [k] has no 'source': expected source = <citation>, or source = illustrative with a note");
  CHECK(error_of("[k]\nlaw = lognormal\nmedian = 2.87\niqr = 0.3\nunit = N/m\nsource = illustrative\n") ==
        ":3: [k] source = illustrative needs a one-line 'note' saying why the value was chosen");
  CHECK(error_of("[k]\nlaw = cauchy\nmedian = 2.87\nunit = N/m\nsource = s\n") ==
        ":4: law = 'cauchy': expected one of lognormal, normal, truncated_normal, uniform, gamma, weibull, beta, empirical");
  CHECK(error_of("[k]\nlaw = normal\nmean = 2.87\nunit = N/m\nsource = s\n") ==
        ":3: [k] law = normal needs 'sd' (parameters: mean, sd)");
  CHECK(error_of("[k]\nlaw = uniform\nlower = 3\nupper = 2\nunit = N/m\nsource = s\n") ==
        ":3: [k] uniform: upper = '2': expected a number above lower = 3");
  CHECK(error_of("[k]\nlaw = empirical\nvalues = 1, x, 3\nunit = N/m\nsource = s\n") == ":5: values = ' x': expected a finite number");
  CHECK(error_of("[k]\nlaw = empirical\nvalues = 1\nunit = N/m\nsource = s\n") ==
        ":5: values: expected at least two distinct numbers, got 1 value(s)");
  CHECK(error_of("[line]\n") == ":3: section [line] repeats the one on line 1");

  const std::string no_name = temporary_file("[line]\ndescription = x\n" + k_ok);
  CHECK_THROWS_WITH_AS(read_line_file(no_name), (no_name + ":1: [line] has no 'name': expected name = <plant line>").c_str(), InputError);
  const std::string no_line = temporary_file(k_ok);
  CHECK_THROWS_WITH_AS(read_line_file(no_line), (no_line + ": no [line] section: expected [line] with name = <plant line>").c_str(), InputError);
  const std::string stray = temporary_file("name = x\n" + header + k_ok);
  CHECK_THROWS_WITH_AS(read_line_file(stray), (stray + ":1: 'name = x' comes before any [section]: expected [line] first").c_str(), InputError);
  const std::string unknown_header_key = temporary_file("[line]\nname = x\nowner = me\n" + k_ok);
  CHECK_THROWS_WITH_AS(read_line_file(unknown_header_key), (unknown_header_key + ":3: unknown key 'owner' in [line]: expected name or description").c_str(), InputError);
  CHECK_THROWS_AS(read_line_file("/nonexistent/line.ini"), InputError);
}

TEST_CASE("line file: tubes = N states the count behind a law, a whole number of at least 2, for a refittable law") {
  // Absent: 0, the law stays fixed in the data-uncertainty bootstrap.
  const std::string path = temporary_file(header + k_ok + "[h]\nlaw = gamma\nshape = 20\nscale = 7\nunit = nm\nsource = s\ntubes = 34\n"
                                          "[einf]\nlaw = beta\nalpha = 8\nbeta = 4\nunit = %\nsource = s\ntubes = 2\n"
                                          "[d]\nlaw = normal\nmean = 6.5\nsd = 1\nunit = um\nsource = s\ntubes = 1e2\n");
  const LineDistributions line = read_line_file(path);
  CHECK(line.find("k")->tubes == 0);
  CHECK(line.find("h")->tubes == 34);
  CHECK(line.find("einf")->tubes == 2);
  CHECK(line.find("d")->tubes == 100);
  // format_line_variable keeps it (and writes none when absent).
  const LineDistributions again = read_line_file(temporary_file(header + format_line_variable(*line.find("h")) +
                                                                format_line_variable(*line.find("k"))));
  CHECK(again.find("h")->tubes == 34);
  CHECK(again.find("k")->tubes == 0);
  CHECK(format_line_variable(*line.find("k")).find("tubes") == std::string::npos);

  // Bad values: line 9 is the tubes line after k_ok's six.
  CHECK(error_of(k_ok + "tubes = 0\n") == ":9: tubes = '0': expected a whole number from 2 to 100000");
  CHECK(error_of(k_ok + "tubes = 1\n") == ":9: tubes = '1': expected a whole number from 2 to 100000");
  CHECK(error_of(k_ok + "tubes = -5\n") == ":9: tubes = '-5': expected a whole number from 2 to 100000");
  CHECK(error_of(k_ok + "tubes = 20.5\n") == ":9: tubes = '20.5': expected a whole number from 2 to 100000");
  CHECK(error_of(k_ok + "tubes = many\n") == ":9: tubes = 'many': expected a whole number from 2 to 100000");
  CHECK(error_of(k_ok + "tubes = 1000000\n") == ":9: tubes = '1000000': expected a whole number from 2 to 100000");
  CHECK(error_of(k_ok + "tubes = 20\ntubes = 30\n").find(":10: ") == 0);  // a key given twice, at its second line
  // A law without a maximum-likelihood fit cannot be refitted, so it cannot state tubes.
  CHECK(error_of("[einf]\nlaw = truncated_normal\nmean = 65\nsd = 14\nlower = 0\nupper = 100\nunit = %\nsource = s\ntubes = 34\n") ==
        ":11: tubes = 34 with law = truncated_normal (line 4): the data-uncertainty bootstrap refits the stated law's family by "
        "maximum likelihood, which exists for lognormal, normal, gamma, weibull and beta only: expected one of those laws, or no "
        "tubes (the law then stays fixed)");
  CHECK(error_of("[k]\nlaw = empirical\nvalues = 1, 2, 3\nunit = N/m\nsource = s\ntubes = 3\n").find(":8: tubes = 3 with law = empirical") == 0);
  CHECK(error_of("[k]\nlaw = uniform\nlower = 1\nupper = 3\nunit = N/m\nsource = s\ntubes = 3\n").find(":9: tubes = 3 with law = uniform") == 0);
}

TEST_CASE("a law whose values overflow or underflow where a design draws is refused at its section") {
  // ": [k] law <describe> in N/m: <problem>: expected <...>" at the section's line (3).
  const auto refused = [](const std::string& law, const std::string& problem) {
    const std::string message = error_of("[k]\nlaw = " + law + "\nunit = N/m\nsource = table\n");
    CAPTURE(message);
    CHECK(message.rfind(":3: [k] law ", 0) == 0);
    CHECK(message.find(" in N/m: " + problem + ": expected " + std::string(sampled_range_expectation) +
                       ", in the file's unit and in SI units") != std::string::npos);
  };
  refused("lognormal\nmu = 800\nsigma = 0.2", "its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is inf");
  refused("lognormal\nmu = 0\nsigma = 100", "its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is inf");
  refused("weibull\nshape = 1e-3\nscale = 1", "its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is inf");
  // (Its true quantiles underflow to 0; the computed one at the upper end is inf.)
  refused("gamma\nshape = 1e-300\nscale = 1", "its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is inf");
  refused("normal\nmean = 0\nsd = 1e308", "its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is inf");
  refused("lognormal\nmu = 0\nsigma = 80", "its quantile at probability 2^-86 (1.3e-26) is 0");
  // A third of gamma(0.05)'s mass lies below 1e-10: its lowest drawn values underflow to 0.
  refused("gamma\nshape = 0.05\nscale = 1", "its quantile at probability 2^-86 (1.3e-26) is 0");

  // Wide but representable laws stay accepted.
  CHECK(error_of("[k]\nlaw = lognormal\nmu = 0\nsigma = 60\nunit = N/m\nsource = table\n") == "no error");
  CHECK(error_of("[k]\nlaw = weibull\nshape = 0.5\nscale = 1\nunit = N/m\nsource = table\n") == "no error");
  CHECK(error_of("[k]\nlaw = gamma\nshape = 0.2\nscale = 1\nunit = N/m\nsource = table\n") == "no error");
}

TEST_CASE("sampled_range_problem: the ends of the drawn range, in the law's unit and scaled to SI") {
  CHECK_FALSE(sampled_range_problem(Lognormal(1.05, 0.21)));
  CHECK_FALSE(sampled_range_problem(Gamma(50, 0.06)));
  CHECK_FALSE(sampled_range_problem(Weibull(5, 3)));
  CHECK_FALSE(sampled_range_problem(Normal(145, 30)));
  CHECK_FALSE(sampled_range_problem(Empirical({1.0, 2.0, 3.0})));
  CHECK(sampled_range_problem(Lognormal(710, 0.01)) == "its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is inf");
  // Finite in its unit, 0 in SI: about exp(-725) = 1.3e-315 nm (a subnormal double) is 0 m.
  CHECK(sampled_range_problem(Lognormal(-725, 0.01), 1e-9) ==
        "its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is " +
            format_double(quantile(Distribution(Lognormal(-725, 0.01)), highest_drawn_probability)) + " (0 in SI units)");
  CHECK_FALSE(sampled_range_problem(Lognormal(-725, 0.01)));
  // Finite in its unit, inf in SI.
  CHECK(sampled_range_problem(Lognormal(700, 0.01), 1e6)->find(" in SI units)") != std::string::npos);
  // The design's extremes are inside the range: the largest double below 1, and a point 2^-54 of
  // a stratum into the first of 2^32 - 1 strata.
  CHECK(highest_drawn_probability == std::nextafter(1.0, 0.0));
  CHECK(lowest_drawn_probability <= 0x1.0p-54 / 4294967295.0);
}

TEST_CASE("a law whose median is not positive is refused: most of its draws are impossible values") {
  // Every measured variable is positive; k = normal(-3, 1) draws no positive stiffness at all.
  const std::string none = error_of("[k]\nlaw = normal\nmean = -3\nsd = 1\nunit = N/m\nsource = table\n");
  CAPTURE(none);
  CHECK(none.rfind(":3: [k] law ", 0) == 0);
  CHECK(none.find(" in N/m: its median -3 is not positive: expected a law of positive values for k, the apparent "
                  "stiffness") != std::string::npos);
  CHECK(error_of("[d]\nlaw = uniform\nlower = -8\nupper = 0\nunit = um\nsource = table\n").find("its median -4 is not positive") !=
        std::string::npos);
  // Median exactly 0: half the draws impossible.
  CHECK(error_of("[h]\nlaw = normal\nmean = 0\nsd = 10\nunit = nm\nsource = table\n").find("its median 0 is not positive") !=
        std::string::npos);
  // A positive median with a tail below 0 (2 % here) stays accepted: those samples are flagged.
  CHECK(error_of("[k]\nlaw = normal\nmean = 2\nsd = 1\nunit = N/m\nsource = table\n") == "no error");
}
