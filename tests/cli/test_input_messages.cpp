// Input that used to end in an unclear message, for every command that reads it: a directory
// given as an input file, an input without end, an empty word, an option where its value
// should be, control characters quoted back, a pseudo file system as the output's place, a
// sensor softer than the tubes, a synthetic curve set without bound. Each is one line naming
// what was given and what was expected, exit status 2, and nothing written.
#include <doctest/doctest.h>

#include <sys/statvfs.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "support/cli_inputs.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::string source = GROWTHUQ_SOURCE_DIR;

// One line on stderr, ending in a newline, and no other control character in it: nothing of
// the input acts on the terminal.
void check_one_printable_line(const std::string& err) {
  REQUIRE(!err.empty());
  CHECK(err.find('\n') == err.size() - 1);
  for (const char c : err.substr(0, err.size() - 1)) {
    CAPTURE(static_cast<int>(static_cast<unsigned char>(c)));
    CHECK(static_cast<unsigned char>(c) >= 0x20);
    CHECK(c != '\x7f');
  }
}

// Every file under `root` other than the captured streams and the given inputs.
std::vector<std::string> files_written(const fs::path& root, const std::vector<std::string>& inputs) {
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string name = fs::relative(entry.path(), root).string();
    if (name == "stdout.txt" || name == "stderr.txt" || entry.is_directory()) continue;
    if (std::find(inputs.begin(), inputs.end(), name) == inputs.end()) found.push_back(name);
  }
  return found;
}

}  // namespace

TEST_CASE("a directory given as an input file is named as one, by every command that reads files") {
  const std::string raw = source + "/distributions/example_raw/wild_type";
  // DIR is a folder in the scratch directory; each command is given it where a file belongs.
  const std::vector<std::string> commands{
      "sample --line DIR --samples 10 --seed 1 --out d.csv",
      "sample --line line.ini --samples 10 --seed 1 --rank-correlation DIR --out d.csv",
      "fit DIR --column k_N_per_m",
      "eval --rho-um 0.5 --in DIR --out r.csv",
      "correlate --rho-um 0.5 --samples 200 --seed 3 --config DIR",
      "relax DIR --meta " + raw + "/relaxation_meta.csv --out f.csv",
      "relax " + raw + "/relaxation_curves.csv --meta DIR --out f.csv",
      "fit-line DIR --out fitted.ini",
      "synth DIR --tubes 5:5 --curves 2:2 --out data",
      "run DIR",
      "tradeoff DIR --samples-list 20,40 --out t.csv",
  };
  for (const std::string& command : commands) {
    CAPTURE(command);
    const ScratchDirectory scratch("cli_directory_input");
    spit(scratch.root / "line.ini", cli_line_file);
    fs::create_directories(scratch.root / "DIR");
    const CliOutcome run = run_cli(command, scratch.root);
    CAPTURE(run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.err.find("DIR: is a directory: expected a file") != std::string::npos);
    CHECK(run.err.find("internal error") == std::string::npos);
    check_one_printable_line(run.err);
    CHECK(files_written(scratch.root, {"line.ini"}).empty());
  }
}

TEST_CASE("an input without end (/dev/zero) is refused at the stated limit instead of filling memory") {
  const ScratchDirectory scratch("cli_endless_input");
  const CliOutcome run = run_cli("sample --line /dev/zero --samples 10 --seed 1 --out d.csv", scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err == "growthuq sample: error: /dev/zero: is larger than 256 MiB, the limit of an input file: expected a "
                   "text file (is it the file you meant?)\n");
  CHECK(files_written(scratch.root, {}).empty());
}

TEST_CASE("an empty word as an option's value is refused naming the option") {
  const ScratchDirectory scratch("cli_empty_word");
  spit(scratch.root / "line.ini", cli_line_file);
  const CliOutcome out = run_cli("sample --line line.ini --samples 10 --seed 1 --out ''", scratch.root);
  CHECK(out.exit_code == 2);
  CHECK(out.err == "growthuq sample: error: --out = '': expected a non-empty value\n");
  // A positional argument is named by what it is.
  const CliOutcome campaign = run_cli("run ''", scratch.root);
  CHECK(campaign.exit_code == 2);
  CHECK(campaign.err == "growthuq run: error: campaign file = '': expected a non-empty value\n");
  // One of several words (synth takes any number of line files).
  const CliOutcome synth = run_cli("synth line.ini '' --out data", scratch.root);
  CHECK(synth.exit_code == 2);
  CHECK(synth.err == "growthuq synth: error: line files of the TRUE distributions = '': expected a non-empty value\n");
  CHECK(files_written(scratch.root, {"line.ini"}).empty());
  // A switch that takes no value is no empty value (relax declares --force without a type).
  const std::string raw = source + "/distributions/example_raw/wild_type";
  const CliOutcome relax = run_cli("relax " + raw + "/relaxation_curves.csv --meta " + raw + "/relaxation_meta.csv --out f.csv --force",
                                   scratch.root);
  CHECK(relax.exit_code == 0);
}

TEST_CASE("an option where a value belongs is named, not reported as too many positional options") {
  const ScratchDirectory scratch("cli_option_as_value");
  spit(scratch.root / "line.ini", cli_line_file);
  const CliOutcome run = run_cli("sample --line line.ini --samples --seed 1 --out d.csv", scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err == "growthuq sample: error: --samples needs a value, but the next word is the option --seed (see "
                   "growthuq sample --help)\n");
  // A negative number is a value, not an option: its own message.
  const CliOutcome negative = run_cli("sample --line line.ini --samples 10 --seed -1 --out d.csv", scratch.root);
  CHECK(negative.exit_code == 2);
  CHECK(negative.err.find("--seed = '-1': expected a whole number") != std::string::npos);
  CHECK(files_written(scratch.root, {"line.ini"}).empty());
}

TEST_CASE("control characters of the input are quoted escaped, never sent to the terminal") {
  const ScratchDirectory scratch("cli_control_characters");
  // An escape sequence in a file name given on the command line ($(printf ...): sh has no $'').
  const CliOutcome name = run_cli("sample --line \"$(printf 'red\\033[31m.ini')\" --samples 10 --seed 1 --out d.csv", scratch.root);
  CHECK(name.exit_code == 2);
  CHECK(name.err.find("red\\x1b[31m.ini: cannot open") != std::string::npos);
  check_one_printable_line(name.err);
  // A NUL, a bell and an escape sequence in a value of a file.
  spit(scratch.root / "bad.ini", std::string("[line]\nname = test_line\n\n[k]\nlaw = log") + '\0' +
                                     "normal\x07\x1b[2J\nmedian = 2.87\niqr = 0.83\nunit = N/m\nsource = s\n");
  const CliOutcome value = run_cli("sample --line bad.ini --samples 10 --seed 1 --out d.csv", scratch.root);
  CAPTURE(value.err);
  CHECK(value.exit_code == 2);
  CHECK(value.err.find("law = 'log\\x00normal\\x07\\x1b[2J': expected one of lognormal") != std::string::npos);
  check_one_printable_line(value.err);
  // An unknown command is quoted the same way.
  const CliOutcome command = run_cli("\"$(printf 'x\\033]0;title\\007')\"", scratch.root);
  CHECK(command.exit_code == 2);
  CHECK(command.err.starts_with("growthuq: unknown command 'x\\x1b]0;title\\x07'\n"));
}

TEST_CASE("an output on a pseudo file system (/proc) is named as such, not as a full disk") {
  struct statvfs proc {};
  if (::statvfs("/proc", &proc) != 0 || proc.f_blocks != 0) {
    MESSAGE("no /proc without blocks here: not checked");
    return;
  }
  const ScratchDirectory scratch("cli_proc_output");
  spit(scratch.root / "line.ini", cli_line_file);
  const CliOutcome sample = run_cli("sample --line line.ini --samples 10 --seed 1 --out /proc/design.csv", scratch.root);
  CHECK(sample.exit_code == 2);
  CHECK(sample.err == "growthuq sample: error: /proc/design.csv: is on a pseudo file system that stores no files (such as "
                      "/proc or /sys): expected a place on a disk\n");
  const CliOutcome run = run_cli("run " + source + "/campaigns/quick.ini --samples 20 --quiet --out /proc/growthuq_out", scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err.find("/proc/growthuq_out: is on a pseudo file system that stores no files") != std::string::npos);
  CHECK(run.err.find("0.0 GB") == std::string::npos);
}

TEST_CASE("synth refuses a curve set without bound, stating the limit") {
  const ScratchDirectory scratch("cli_synth_bound");
  const CliOutcome run = run_cli("synth " + source + "/distributions/wild_type.ini --sample-hz 1e9 --out data", scratch.root);
  CHECK(run.exit_code == 2);
  // 2e6 samples / (30 s x 40 curves) = 1666.7 Hz.
  CHECK(run.err == "growthuq synth: error: --sample-hz = '1e+09': expected at most 1666 Hz with --hold-s 30 and up "
                   "to 40 curves: a line's curves hold at most 2000000 samples (hold x rate x curves)\n");
  CHECK(!fs::exists(scratch.root / "data"));
}

TEST_CASE("a sensor softer than the line's tubes is named with both stiffnesses, not as a nan kappa") {
  const ScratchDirectory scratch("cli_soft_sensor");
  const std::string campaign =
      "[campaign]\nname = soft\nseed = 5\nsamples = 50\noutputs = p\noutput_dir = out\nformats = csv\n\n"
      "[instrument]\nprobe_radius_um = 0.5\nsensor_stiffness_N_per_m = SENSOR\n\n"
      "[line turgor_line]\ndistributions = " + source + "/tests/campaign/data/turgor_line.ini\n";
  const auto with_sensor = [&](const std::string& k_sys) {
    std::string text = campaign;
    text.replace(text.find("SENSOR"), 6, k_sys);
    return text;
  };
  // The line's median k is 2.87 N/m: a 2 N/m sensor cannot show it.
  spit(scratch.root / "soft.ini", with_sensor("2"));
  const CliOutcome soft = run_cli("run soft.ini --quiet", scratch.root);
  CHECK(soft.exit_code == 2);
  CHECK(soft.err == "growthuq run: error: soft.ini:13: line 'turgor_line' (" + source +
                        "/tests/campaign/data/turgor_line.ini): median measured stiffness k = 2.87 N/m is not below "
                        "[instrument] sensor_stiffness_N_per_m = 2: expected a sensor stiffer than the tubes it measures "
                        "(k_sys in N/m, or the line's k unit?)\n");
  CHECK(!fs::exists(scratch.root / "out"));
  // A stiffer sensor runs.
  spit(scratch.root / "stiff.ini", with_sensor("50"));
  const CliOutcome stiff = run_cli("run stiff.ini --quiet", scratch.root);
  CHECK(stiff.exit_code == 0);
  CHECK(fs::exists(scratch.root / "out" / "summary.csv"));
}
