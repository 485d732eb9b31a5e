// `growthuq fit` end to end: the built executable on small CSV files, good and bad.
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "growthuq/distributions/fit.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/io/csv.hpp"

using namespace growthuq;

namespace {

struct Run {
  int status;
  std::string output;  // stdout and stderr
};

Run run_fit(const std::string& arguments) {
  const std::string command = std::string(GROWTHUQ_CLI) + " fit " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string output;
  std::array<char, 4096> buffer{};
  while (const std::size_t read = std::fread(buffer.data(), 1, buffer.size(), pipe)) output.append(buffer.data(), read);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

std::string temporary(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("growthuq_test_fit_" + name)).string();
}

std::string write(const std::string& name, const std::string& text) {
  const std::string path = temporary(name);
  std::ofstream(path) << text;
  return path;
}

// 40 stiffness values (N/m) of a right-skewed sample.
const std::string stiffness_csv =
    "# synthetic per-tube stiffness\ntube,k_N_per_m\n"
    "1,2.41\n2,3.12\n3,2.05\n4,2.87\n5,4.40\n6,2.66\n7,3.35\n8,1.92\n9,2.71\n10,3.80\n"
    "11,2.22\n12,2.95\n13,5.10\n14,2.50\n15,3.05\n16,2.33\n17,2.78\n18,3.61\n19,1.75\n20,2.99\n"
    "21,2.58\n22,4.05\n23,2.14\n24,3.22\n25,2.69\n26,2.83\n27,6.02\n28,2.47\n29,3.44\n30,2.01\n"
    "31,2.90\n32,3.70\n33,2.37\n34,2.62\n35,3.15\n36,1.98\n37,4.71\n38,2.75\n39,3.28\n40,2.55\n";

}  // namespace

TEST_CASE("growthuq fit prints every family sorted by AIC and writes the best as a line file") {
  const std::string data = write("k.csv", stiffness_csv);
  const std::string out = temporary("k.ini");
  std::filesystem::remove(out);
  const Run run = run_fit(data + " --column k_N_per_m --write " + out);
  CAPTURE(run.output);
  REQUIRE(run.status == 0);
  CHECK(run.output.find("n = 40 values of k_N_per_m (k in N/m)") != std::string::npos);

  // The table lists the four families in AIC order, equal to the library's fits.
  const std::vector<double> values = read_csv(data).numeric_column("k_N_per_m");
  std::vector<FitResult> fits;
  for (const FitFamily family : all_fit_families) fits.push_back(fit_distribution(family, values));
  std::sort(fits.begin(), fits.end(), [](const FitResult& a, const FitResult& b) { return a.aic < b.aic; });
  std::size_t previous = 0;
  for (const FitResult& fit : fits) {
    const std::size_t at = run.output.find("\n" + std::string(to_string(fit.family)) + " ");
    REQUIRE(at != std::string::npos);
    CHECK(at > previous);
    previous = at;
  }

  // The written file is a valid line file holding the best family, parameters exact.
  const LineDistributions line = read_line_file(out);
  REQUIRE(line.variables.size() == 1);
  CHECK(line.variables[0].name == "k");
  CHECK(line.variables[0].unit->symbol == "N/m");
  CHECK(describe(line.variables[0].distribution) == describe(fits.front().distribution));
  CHECK(quantile(line.variables[0].distribution, 0.9) == quantile(fits.front().distribution, 0.9));
  CHECK(line.variables[0].tubes == values.size());  // the 40 values fitted, for the data interval

  // Never overwritten without --force; --family chooses what is written.
  const Run again = run_fit(data + " --column k_N_per_m --write " + out);
  CHECK(again.status == 2);
  CHECK(again.output.find("--force") != std::string::npos);
  const Run forced = run_fit(data + " --column k_N_per_m --family weibull --write " + out + " --force");
  CHECK(forced.status == 0);
  CHECK(family_name(read_line_file(out).variables[0].distribution) == "weibull");
  std::filesystem::remove(out);
}

TEST_CASE("growthuq fit reports bad data with file and line, and exits 2") {
  struct Case {
    std::string csv;
    std::string arguments;
    std::string expected;  // after "<path>"
  };
  const std::vector<Case> cases{
      {"tube,k_N_per_m\n1,2.1\n2,abc\n3,2.5\n", "--column k_N_per_m", ":3: column k_N_per_m = 'abc': expected a finite number"},
      {"tube,k_N_per_m\n1,2.1\n2,\n3,2.5\n", "--column k_N_per_m", ":3: column k_N_per_m = '': expected a finite number"},
      {"tube,k_N_per_m\n1,2.1\n2,nan\n", "--column k_N_per_m", ":3: column k_N_per_m = 'nan': expected a finite number"},
      {"tube,k_N_per_m\n", "--column k_N_per_m", ": column k_N_per_m is empty (no data rows): expected at least two measurements"},
      {"tube,k_N_per_m\n1,2.1\n2,-0.4\n3,2.5\n", "--column k_N_per_m --family lognormal",
       ":3: column k_N_per_m = '-0.4': expected a positive number: the lognormal law lives on x > 0"},
      {"tube,k_N_per_m\n1,2.1\n2,2.5\n", "--column h_nm", ": no column 'h_nm' (the columns are: tube, k_N_per_m)"},
  };
  for (const Case& c : cases) {
    const std::string path = write("bad.csv", c.csv);
    const Run run = run_fit(path + " " + c.arguments);
    CAPTURE(run.output);
    CHECK(run.status == 2);
    CHECK(run.output == "growthuq fit: error: " + path + c.expected + "\n");
  }
  const std::string path = write("named.csv", "tube,stiffness\n1,2.1\n2,2.5\n3,2.2\n");
  const Run unnamed = run_fit(path + " --column stiffness");
  CHECK(unnamed.status == 2);
  CHECK(unnamed.output.find("give --variable and --unit") != std::string::npos);
  const Run wrong_unit = run_fit(path + " --column stiffness --variable k --unit MPa");
  CHECK(wrong_unit.output == "growthuq fit: error: --unit = 'MPa': expected a unit of stiffness for k\n");
  CHECK(run_fit(path + " --column stiffness --variable k --unit N/m").status == 0);
  // beta is a family of raw-data fits of einf (fit-line, campaigns), not of this command: it used
  // to leave no family to fit and no table to print.
  const Run beta = run_fit(path + " --column stiffness --variable k --unit N/m --family beta");
  CHECK(beta.status == 2);
  CHECK(beta.output == "growthuq fit: error: --family = 'beta': expected lognormal, normal, gamma or weibull\n");
}

TEST_CASE("growthuq fit skips positive laws with a note when a value is not positive") {
  const std::string path = write("negative.csv", "tube,d_um\n1,6.1\n2,-0.5\n3,7.0\n4,6.4\n");
  const Run run = run_fit(path + " --column d_um");
  CAPTURE(run.output);
  CHECK(run.status == 0);
  CHECK(run.output.find("\nnormal ") != std::string::npos);
  CHECK(run.output.find("\nlognormal ") == std::string::npos);
  CHECK(run.output.find("note: skipped lognormal, gamma, weibull (they need values > 0): " + path + ":3 has d_um = -0.5") !=
        std::string::npos);
}
