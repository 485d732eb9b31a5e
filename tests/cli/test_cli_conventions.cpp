// The conventions users expect of a command line: "-" for standard output (the result alone
// there, the report on stderr) or standard input, `growthuq help CMD` as `growthuq CMD --help`,
// --version on every command, and help text in one layout and width.
#include <doctest/doctest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_inputs.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> command_names{"sample", "fit",      "eval",  "correlate", "relax",    "curves", "run",
                                             "check",  "tradeoff", "synth", "fit-line",  "indent",   "report"};

}  // namespace

TEST_CASE("--out - prints the result alone on stdout, as the file would hold it; the report goes to stderr") {
  const ScratchDirectory scratch("cli_dash_out");
  write_cli_inputs(scratch.root);
  struct Case {
    std::string to_file;   // writes file.out
    std::string to_stdout;
  };
  const std::vector<Case> cases{
      {"eval --rho-um 0.5 --in tubes.csv --out file.out", "eval --rho-um 0.5 --in tubes.csv --out -"},
      {"sample --line line.ini --samples 50 --seed 7 --out file.out", "sample --line line.ini --samples 50 --seed 7 --out -"},
      {"fit-line raw/raw.ini --out file.out", "fit-line raw/raw.ini --out -"},
      {"correlate --rho-um 0.5 --samples 200 --seed 3 --out file.out", "correlate --rho-um 0.5 --samples 200 --seed 3 --out -"},
  };
  fs::create_directories(scratch.root / "raw");
  spit(scratch.root / "raw" / "k.csv", cli_stiffness_csv);
  spit(scratch.root / "raw" / "raw.ini", "[line]\nname = r\n[measurement k]\nfile = k.csv\ncolumn = k_N_per_m\nunit = N/m\n");
  for (const Case& c : cases) {
    CAPTURE(c.to_stdout);
    fs::remove(scratch.root / "file.out");
    const CliOutcome to_file = run_cli(c.to_file, scratch.root);
    REQUIRE(to_file.exit_code == 0);
    const CliOutcome to_stdout = run_cli(c.to_stdout, scratch.root);
    CHECK(to_stdout.exit_code == 0);
    CHECK(to_stdout.out == slurp(scratch.root / "file.out"));
    CHECK_FALSE(to_stdout.out.empty());
    // The report the file run printed on stdout went to stderr, naming stdout as the target.
    CHECK(to_stdout.err.find("wrote the result to standard output") != std::string::npos);
    CHECK_FALSE(fs::exists(scratch.root / "-"));
  }
  // relax: the fits table on stdout, the per-curve report on stderr.
  const std::string raw = std::string(GROWTHUQ_SOURCE_DIR) + "/distributions/example_raw/wild_type";
  const std::string relax = "relax " + raw + "/relaxation_curves.csv --meta " + raw + "/relaxation_meta.csv --out ";
  REQUIRE(run_cli(relax + "fits.csv", scratch.root).exit_code == 0);
  const CliOutcome relax_stdout = run_cli(relax + "-", scratch.root);
  CHECK(relax_stdout.exit_code == 0);
  CHECK(relax_stdout.out == slurp(scratch.root / "fits.csv"));
  CHECK(relax_stdout.err.find("fits in standard output\n") != std::string::npos);
  // fit --write -: the line file on stdout (named "fitted": there is no file name to take), the
  // AIC table on stderr.
  const CliOutcome fit = run_cli("fit k.csv --column k_N_per_m --write -", scratch.root);
  CHECK(fit.exit_code == 0);
  CHECK(fit.out.find("[line]\nname = fitted\n") != std::string::npos);
  CHECK(fit.out.find("\n[k]\nlaw = ") != std::string::npos);
  CHECK(fit.err.find("n = 10 values of k_N_per_m") == 0);
  CHECK_FALSE(fs::exists(scratch.root / "-"));
}

TEST_CASE("- as an input reads standard input; commands that cannot print a result there refuse -") {
  const ScratchDirectory scratch("cli_dash_in");
  write_cli_inputs(scratch.root);
  REQUIRE(run_cli("eval --rho-um 0.5 --in tubes.csv --out from_file.csv", scratch.root).exit_code == 0);
  const CliOutcome piped = run_cli("eval --rho-um 0.5 --in - --out from_stdin.csv <tubes.csv", scratch.root);
  CHECK(piped.exit_code == 0);
  CHECK(slurp(scratch.root / "from_stdin.csv") == slurp(scratch.root / "from_file.csv"));
  CHECK(piped.out.find("2 tubes from standard input") == 0);
  // A bad table on stdin is named as such.
  spit(scratch.root / "bad.csv", "k_N_per_m,d_um,d0_um\n2.87,x,5.35\n");
  const CliOutcome bad = run_cli("eval --rho-um 0.5 --in - --out bad_out.csv <bad.csv", scratch.root);
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("standard input:2: column d_um = 'x'") != std::string::npos);
  CHECK_FALSE(fs::exists(scratch.root / "bad_out.csv"));
  // fit reads its data from stdin the same way.
  const CliOutcome fit_file = run_cli("fit k.csv --column k_N_per_m", scratch.root);
  const CliOutcome fit_stdin = run_cli("fit - --column k_N_per_m <k.csv", scratch.root);
  CHECK(fit_stdin.exit_code == 0);
  CHECK(fit_stdin.out.substr(fit_stdin.out.find('\n')) == fit_file.out.substr(fit_file.out.find('\n')));
  // Both ends piped: the line file it writes names where the data came from.
  const CliOutcome fit_pipe = run_cli("fit - --column k_N_per_m --write - <k.csv", scratch.root);
  CHECK(fit_pipe.exit_code == 0);
  CHECK(fit_pipe.out.find("description = k fitted from standard input\n") != std::string::npos);

  // Results that are folders or several files cannot go to stdout: - is refused in one line
  // before any work, and no file or folder "-" appears.
  const std::string small = std::string(GROWTHUQ_SOURCE_DIR) + "/tests/campaign/data/small_campaign.ini";
  for (const std::string& command : {"run " + small + " --out -", "tradeoff " + small + " --samples-list 20,40 --out -",
                                    "synth " + std::string(GROWTHUQ_SOURCE_DIR) + "/distributions/wild_type.ini --out -",
                                    std::string("indent --p-MPa 0.3 --E-MPa 100 --h-nm 150 --d0-um 5 --rho-um 0.5 --out -")}) {
    CAPTURE(command);
    const CliOutcome refused = run_cli(command, scratch.root);
    CHECK(refused.exit_code == 2);
    CHECK(refused.err.find(": error: -: standard output cannot take ") != std::string::npos);
    CHECK(refused.err.find('\n') == refused.err.size() - 1);
    CHECK_FALSE(fs::exists(scratch.root / "-"));
  }
}

TEST_CASE("growthuq help CMD is growthuq CMD --help; --version works on every command") {
  const ScratchDirectory scratch("cli_help");
  const CliOutcome version = run_cli("--version", scratch.root);
  REQUIRE(version.exit_code == 0);
  CHECK(version.out.rfind("growthuq ", 0) == 0);
  for (const std::string& name : command_names) {
    CAPTURE(name);
    const CliOutcome help = run_cli("help " + name, scratch.root);
    const CliOutcome option = run_cli(name + " --help", scratch.root);
    CHECK(help.exit_code == 0);
    CHECK(help.out == option.out);
    CHECK(help.out.rfind("usage: growthuq " + name + " ", 0) == 0);
    const CliOutcome command_version = run_cli(name + " --version", scratch.root);
    CHECK(command_version.exit_code == 0);
    CHECK(command_version.out == version.out);
    // One layout and width: usage, a blank line, the description, "options:" and the option
    // list, no line wider than 80 columns.
    CHECK(help.out.find("\n\noptions:\n") != std::string::npos);
    std::istringstream lines(help.out);
    for (std::string line; std::getline(lines, line);) {
      CAPTURE(line);
      CHECK(line.size() <= 80);
    }
  }
  const CliOutcome unknown = run_cli("help nonsense", scratch.root);
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.err.rfind("growthuq: unknown command 'nonsense'", 0) == 0);
  const CliOutcome general = run_cli("help", scratch.root);
  CHECK(general.exit_code == 0);
  CHECK(general.out == run_cli("--help", scratch.root).out);
  CHECK(general.out.find("\n  check ") != std::string::npos);
  std::istringstream lines(general.out);
  for (std::string line; std::getline(lines, line);) {
    CAPTURE(line);
    CHECK(line.size() <= 80);
  }
}
