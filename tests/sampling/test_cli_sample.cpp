// `growthuq sample` run as users run it: the design file, the printed summary, refusal to
// overwrite, and one-line errors for bad options and files.
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "growthuq/io/csv.hpp"
#include "growthuq/stats/sample_summary.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path directory = fs::temp_directory_path() / "growthuq_test_cli_sample";

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string write_text(const std::string& name, const std::string& text) {
  fs::create_directories(directory);
  std::ofstream(directory / name) << text;
  return (directory / name).string();
}

struct Run {
  int status;
  std::string out;
  std::string err;
};

Run run_sample(const std::string& arguments) {
  fs::create_directories(directory);
  const std::string out = (directory / "stdout.txt").string();
  const std::string err = (directory / "stderr.txt").string();
  const std::string command = std::string(GROWTHUQ_CLI) + " sample " + arguments + " >" + out + " 2>" + err;
  const int raw = std::system(command.c_str());
  return {WEXITSTATUS(raw), read_text(out), read_text(err)};
}

const char* const line_file =
    "[line]\n"
    "name = test_line\n"
    "\n"
    "[k]\n"
    "law = lognormal\n"
    "median = 2.87\n"
    "iqr = 0.83\n"
    "unit = N/m\n"
    "source = published median and IQR\n"
    "\n"
    "[h]\n"
    "law = lognormal\n"
    "median = 145\n"
    "iqr = 31\n"
    "unit = nm\n"
    "source = published median and IQR\n"
    "\n"
    "[d]\n"
    "law = lognormal\n"
    "median = 6.56\n"
    "iqr = 1.19\n"
    "unit = um\n"
    "source = published median and IQR\n";

}  // namespace

TEST_CASE("growthuq sample writes the design and prints medians and rank correlations") {
  const std::string line = write_text("line.ini", line_file);
  const std::string matrix = write_text("matrix.csv", "k,d\n1,0.5\n0.5,1\n");
  const std::string design = (directory / "design.csv").string();
  fs::remove(design);
  const Run run = run_sample("--line " + line + " --samples 2000 --seed 2022 --rank-correlation " + matrix + " --out " + design);
  INFO(run.err);
  REQUIRE(run.status == 0);
  const growthuq::CsvTable table = growthuq::read_csv(design);
  CHECK(table.header == std::vector<std::string>{"k_N_per_m", "h_nm", "d_um"});
  CHECK(table.rows.size() == 2000);
  // The sample median of a 2000-point LHS is within a fraction of a percent of the law's
  // (stratification leaves only the within-stratum jitter): checked to 0.5 %.
  const growthuq::SampleSummary k = growthuq::summarize(table.numeric_column("k_N_per_m"));
  CHECK(k.median == doctest::Approx(2.87).epsilon(0.005));
  CHECK(k.iqr() == doctest::Approx(0.83).epsilon(0.01));
  // The printed median and IQR (taken from the strata, without sorting) are the written
  // column's, summarized by sorting: "k  N/m  <law>  median  (law)  IQR  (law)", 4 digits.
  char median_text[32], iqr_text[32];
  std::snprintf(median_text, sizeof median_text, "%.4g", k.median);
  std::snprintf(iqr_text, sizeof iqr_text, "%.4g", k.iqr());
  const std::size_t k_row = run.out.find("\nk ");
  REQUIRE(k_row != std::string::npos);
  std::istringstream fields(run.out.substr(k_row + 1, run.out.find('\n', k_row + 1) - k_row - 1));
  std::vector<std::string> words;
  for (std::string word; fields >> word;) words.push_back(word);
  REQUIRE(words.size() >= 4);
  CHECK(words[words.size() - 4] == median_text);
  CHECK(words[words.size() - 2] == iqr_text);
  CHECK(run.out.find("rank correlation (Spearman)") != std::string::npos);
  CHECK(run.out.find("k, d") != std::string::npos);
  CHECK(run.err.empty());

  const Run again = run_sample("--line " + line + " --samples 10 --seed 1 --out " + design);
  CHECK(again.status == 2);
  CHECK(again.err.find("--force") != std::string::npos);
  CHECK(growthuq::read_csv(design).rows.size() == 2000);
  CHECK(run_sample("--line " + line + " --samples 10 --seed 1 --out " + design + " --force").status == 0);
  CHECK(growthuq::read_csv(design).rows.size() == 10);
}

TEST_CASE("growthuq sample: bad input gives one line naming the problem") {
  const std::string line = write_text("line.ini", line_file);
  const std::string design = (directory / "bad_design.csv").string();
  fs::remove(design);
  Run run = run_sample("--line " + line + " --samples 0 --seed 1 --out " + design);
  CHECK(run.status == 2);
  CHECK(run.err == "growthuq sample: error: --samples = '0': expected a whole number from 1 to 4294967295\n");
  run = run_sample("--line " + line + " --samples 10 --seed -3 --out " + design);
  CHECK(run.status == 2);
  CHECK(run.err.find("--seed = '-3'") != std::string::npos);

  const std::string unknown = write_text("unknown.csv", "k,tau\n1,0.5\n0.5,1\n");
  run = run_sample("--line " + line + " --samples 10 --seed 1 --rank-correlation " + unknown + " --out " + design);
  CHECK(run.status == 2);
  CHECK(run.err.find("variable 'tau' is not in line 'test_line'") != std::string::npos);

  const std::string impossible = write_text("impossible.csv", "k,h,d\n1,0.9,-0.9\n0.9,1,0.9\n-0.9,0.9,1\n");
  run = run_sample("--line " + line + " --samples 100 --seed 1 --rank-correlation " + impossible + " --out " + design);
  CHECK(run.status == 0);
  CHECK(run.err.find("warning: the rank correlation target is not attainable") != std::string::npos);

  run = run_sample("--line " + line + " --samples 3 --seed 1 --rank-correlation " + impossible + " --out " + design + " --force");
  CHECK(run.status == 0);
  CHECK(run.err.find("cannot be imposed on 3 samples") != std::string::npos);
  CHECK_FALSE(fs::exists(design + ".partial"));
}

TEST_CASE("growthuq sample: a law that would draw inf or 0 is refused before any file is written") {
  const struct {
    const char* law;
    const char* problem;
  } cases[] = {
      {"law = gamma\nshape = 1e-300\nscale = 1\n", "its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is inf"},
      {"law = weibull\nshape = 1e-3\nscale = 1\n", "its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is inf"},
      {"law = gamma\nshape = 0.05\nscale = 1\n", "its quantile at probability 2^-86 (1.3e-26) is 0"},
      {"law = lognormal\nmu = 800\nsigma = 0.2\n", "its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is inf"},
  };
  for (const auto& c : cases) {
    CAPTURE(c.law);
    const std::string line = write_text("overflow.ini", std::string("[line]\nname = overflow\n\n[k]\n") + c.law +
                                                            "unit = N/m\nsource = illustrative\nnote = test\n");
    const std::string design = (directory / "overflow.csv").string();
    fs::remove(design);
    const Run run = run_sample("--line " + line + " --samples 100 --seed 1 --out " + design);
    CHECK(run.status == 2);
    CHECK(run.err.rfind("growthuq sample: error: " + line + ":4: [k] law ", 0) == 0);
    CHECK(run.err.find(std::string(" in N/m: ") + c.problem + ": expected a law whose values are finite") != std::string::npos);
    CHECK(run.out.find("wrote") == std::string::npos);
    CHECK_FALSE(fs::exists(design));
    CHECK_FALSE(fs::exists(design + ".partial"));
  }
}
