// Where results go, for every command that writes them: an output path that is a device node
// (or a FIFO, when this process may not make devices) is refused with one line naming it and
// what was expected, even with --force, and is left as it was; and a result printed on a
// stdout that cannot take it (a full device) makes the command fail instead of exiting 0.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/cli_inputs.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/special_files.hpp"
#include "support/text_file.hpp"

using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::string source = GROWTHUQ_SOURCE_DIR;

// Every .partial file under `root`: none may be left behind.
std::vector<std::string> partial_files(const fs::path& root) {
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() == ".partial") found.push_back(entry.path().string());
  }
  return found;
}

struct Case {
  std::string command;    // with OUT where the output path goes
  std::string out;        // the output path, relative to the scratch folder
  std::string directory;  // a folder to create first, relative to the scratch folder ("" none)
};

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

// `growthuq <arguments>` in `directory` with stdout to `stdout_path` (stderr to stderr.txt).
CliOutcome run_with_stdout(const std::string& arguments, const fs::path& directory, const fs::path& stdout_path) {
  const std::string command = "cd '" + directory.string() + "' && '" + std::string(GROWTHUQ_CLI) + "' " + arguments +
                              " >'" + stdout_path.string() + "' 2>stderr.txt";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, "", slurp(directory / "stderr.txt")};
}

}  // namespace

TEST_CASE("--force never replaces a device: every command that writes files refuses it and leaves it") {
  const std::string quick = source + "/campaigns/quick.ini";
  const std::string raw = source + "/distributions/example_raw/wild_type";
  const std::vector<Case> cases{
      {"sample --line line.ini --samples 10 --seed 1 --out OUT --force", "design.csv", ""},
      {"fit k.csv --column k_N_per_m --write OUT --force", "k.ini", ""},
      {"eval --rho-um 0.5 --in tubes.csv --out OUT --force", "results.csv", ""},
      {"correlate --rho-um 0.5 --samples 200 --seed 3 --out OUT --force", "matrix.csv", ""},
      {"relax " + raw + "/relaxation_curves.csv --meta " + raw + "/relaxation_meta.csv --out OUT --force", "fits.csv", ""},
      {"fit-line " + raw + "/raw.ini --out OUT --force", "fitted.ini", ""},
      {"synth " + source + "/distributions/wild_type.ini --tubes 5:5 --curves 2:2 --out data --force",
       "data/wild_type/raw.ini", "data/wild_type"},
      {"run " + quick + " --out out --samples 20 --quiet --force", "out/summary.csv", "out"},
      {"run " + quick + " --out out --samples 20 --quiet --force --formats csv", "out/results.h5", "out"},
      {"tradeoff " + quick + " --samples-list 20,40 --quiet --out OUT --force", "trade.csv", ""},
  };
  for (const Case& c : cases) {
    CAPTURE(c.command);
    const ScratchDirectory scratch("cli_device");
    write_cli_inputs(scratch.root);
    if (!c.directory.empty()) fs::create_directories(scratch.root / c.directory);
    const fs::path target = scratch.root / c.out;
    SpecialKind kind = SpecialKind::null_device;
    if (!make_special_file(target, kind)) {
      kind = SpecialKind::fifo;  // not root: a FIFO is replaced all the same by a rename
      REQUIRE(make_special_file(target, kind));
    }
    const CliOutcome run = run_cli(replaced(c.command, "OUT", c.out), scratch.root);
    CHECK(run.exit_code == 2);
    CHECK(run.err.find(c.out + ": is " + std::string(kind_name(kind)) + ": expected a regular file or a path that does not exist") !=
          std::string::npos);
    CHECK(run.err.find('\n') == run.err.size() - 1);  // one line
    CHECK(is_special_file(target, kind));
    CHECK(partial_files(scratch.root) == std::vector<std::string>{});
  }
}

TEST_CASE("a result printed on a full stdout is an error, not exit status 0") {
  const ScratchDirectory scratch("cli_full");
  write_cli_inputs(scratch.root);
  const fs::path full = scratch.root / "full";
  if (!make_special_file(full, SpecialKind::full_device)) {
    MESSAGE("not root: no full device can be made here, so a full stdout is not checked");
    return;
  }
  for (const std::string command : {"eval --rho-um 0.5 --k 2.87 --d-um 6.56 --d0-um 5.35 --h-nm 145",
                                    "fit k.csv --column k_N_per_m", "sample --line line.ini --samples 10 --seed 1 --out d.csv",
                                    "--version"}) {
    CAPTURE(command);
    const CliOutcome run = run_with_stdout(command, scratch.root, full);
    CHECK(run.exit_code == 2);
    CHECK(run.err.find(": error: standard output: write failed: No space left on device (what was printed there is "
                       "incomplete)\n") != std::string::npos);
  }
  // The same commands on a stdout that takes everything succeed.
  const fs::path null = scratch.root / "null";
  REQUIRE(make_special_file(null, SpecialKind::null_device));
  fs::remove(scratch.root / "d.csv");
  const CliOutcome run = run_with_stdout("sample --line line.ini --samples 10 --seed 1 --out d.csv", scratch.root, null);
  CHECK(run.exit_code == 0);
  CHECK(run.err.empty());
}
