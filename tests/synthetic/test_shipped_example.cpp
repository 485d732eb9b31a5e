// The shipped example data, distributions/example_raw/, are what README's step 1 writes: every
// file of the five lines, apart from the '#' comment lines (they name the paths the command was
// given) and the last digit of derived numbers. A change to the generator, or to the numbers it is built from, that
// moves any digit shows here, and the shipped data are then regenerated with that command.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "support/cli_run.hpp"
#include "support/text_file.hpp"

using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

// `text` without its '#' lines and with `prefix` taken out of paths (raw.ini names the line
// file it was drawn from as given on the command line: relative in README's command).
std::string comparable(const std::string& text, const std::string& prefix) {
  std::istringstream lines(text);
  std::string line, kept;
  while (std::getline(lines, line)) {
    if (line.rfind('#', 0) == 0) continue;
    for (std::size_t at = line.find(prefix); at != std::string::npos; at = line.find(prefix)) line.erase(at, prefix.size());
    kept += line + "\n";
  }
  return kept;
}

// Whether two files' comparable texts agree: text cells exactly, numbers to 1e-12 relative (the
// last digit of a value computed from the drawn ones may move with the compiler's flags).
bool agree(const std::string& drawn, const std::string& shipped) {
  std::istringstream a(drawn), b(shipped);
  std::string line_a, line_b;
  while (std::getline(a, line_a)) {
    if (!std::getline(b, line_b)) return false;
    std::istringstream cells_a(line_a), cells_b(line_b);
    std::string cell_a, cell_b;
    while (std::getline(cells_a, cell_a, ',')) {
      if (!std::getline(cells_b, cell_b, ',')) return false;
      if (cell_a == cell_b) continue;
      char* end_a = nullptr;
      char* end_b = nullptr;
      const double x = std::strtod(cell_a.c_str(), &end_a), y = std::strtod(cell_b.c_str(), &end_b);
      if (cell_a.empty() || cell_b.empty() || *end_a != '\0' || *end_b != '\0') return false;
      if (!(std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y)))) return false;
    }
    if (std::getline(cells_b, cell_b, ',')) return false;
  }
  return !std::getline(b, line_b);
}

}  // namespace

TEST_CASE("distributions/example_raw is what `growthuq synth ... --seed 2022 --force-curves 2 --curve-samples 200` writes") {
  const fs::path source = GROWTHUQ_SOURCE_DIR;
  const fs::path directory = fs::temp_directory_path() / "growthuq_test_shipped_example";
  fs::remove_all(directory);
  fs::create_directories(directory);
  std::string arguments = "synth";
  for (const char* line : {"wild_type", "xxt1_xxt2", "xeg113", "xxt1_xxt2_xeg113", "pme48"}) {
    arguments += " '" + (source / "distributions" / (std::string(line) + ".ini")).string() + "'";
  }
  const CliOutcome outcome = run_cli(arguments + " --seed 2022 --force-curves 2 --curve-samples 200 --out drawn", directory);
  REQUIRE_MESSAGE(outcome.exit_code == 0, outcome.err);
  int files = 0;
  const std::string prefix = source.string() + "/";
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(source / "distributions" / "example_raw")) {
    if (!entry.is_regular_file() || entry.path().parent_path() == source / "distributions" / "example_raw") continue;  // README.md
    const fs::path relative = fs::relative(entry.path(), source / "distributions" / "example_raw");
    CAPTURE(relative.string());
    REQUIRE(fs::exists(directory / "drawn" / relative));
    CHECK(agree(comparable(slurp(directory / "drawn" / relative), prefix), comparable(slurp(entry.path()), prefix)));
    ++files;
  }
  CHECK(files == 5 * 11);  // 8 tables and curve files, and force_curves.csv, its sheet and its truth
  fs::remove_all(directory);
}
