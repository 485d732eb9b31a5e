// The up-front memory and disk estimate of a run (run_footprint.hpp): it must not be below the
// peak resident memory a real run reaches (measured here by the kernel, wait4's ru_maxrss, for
// three campaign shapes), nor far above it; the largest count it offers must fit and one more
// must not; and a run too large for this machine is refused in one line before any work.
#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/campaign/run_footprint.hpp"
#include "growthuq/core/error.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::string source_dir = GROWTHUQ_SOURCE_DIR;

struct MeasuredRun {
  int exit_code = -1;
  std::uint64_t peak_bytes = 0;  // the child's peak resident set, from the kernel
  std::string err;
};

// Runs `growthuq <arguments>` in `directory` and reads its peak resident memory from wait4.
MeasuredRun run_measured(const std::vector<std::string>& arguments, const fs::path& directory) {
  std::vector<std::string> words{GROWTHUQ_CLI};
  words.insert(words.end(), arguments.begin(), arguments.end());
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    if (chdir(directory.c_str()) != 0) _exit(127);
    const int err = open("stderr.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int out = open("/dev/null", O_WRONLY);
    if (err < 0 || out < 0 || dup2(err, 2) < 0 || dup2(out, 1) < 0) _exit(127);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  REQUIRE(wait4(pid, &status, 0, &usage) == pid);
  MeasuredRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.peak_bytes = static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;  // Linux reports KiB
  run.err = slurp(directory / "stderr.txt");
  return run;
}

// The next count of two significant digits above `count` (the offers are rounded down to two).
std::uint64_t next_two_digit(std::uint64_t count) {
  std::uint64_t step = 1;
  while (count / step >= 100) step *= 10;
  return count + step;
}

// The shape the CLI sees for `campaign` with these overrides.
RunShape shape_of(const std::string& campaign_path, const CampaignOverrides& overrides) {
  Campaign campaign = read_campaign(campaign_path);
  apply_overrides(campaign, overrides);
  const PreparedCampaign prepared(std::move(campaign));
  return run_shape(prepared, true);
}

std::uint64_t largest_offered(const std::string& message) {
  std::smatch match;
  REQUIRE_MESSAGE(std::regex_search(message, match, std::regex("at most ([0-9]+) samples per line fit")), message);
  return std::stoull(match[1].str());
}

}  // namespace

TEST_CASE("the memory estimate is never below a real run's peak, and within 1.3x + the block pool of it") {
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer's shadow memory and quarantine multiply every process's resident memory:
  // the peak it would measure is the sanitizer's, not the engine's (the release build checks it).
  MESSAGE("skipped under AddressSanitizer");
  return;
#endif
  const ScratchDirectory scratch("footprint_peak");
  struct Case {
    const char* campaign;
    std::size_t samples;
    const char* lines;    // empty: all
    const char* formats;
  };
  // Shapes measured for the model: 3 inputs and 1 output over 5 lines; 6 and 4 on one line
  // with the most samples; 7 and 5 over 5 lines writing samples.csv too.
  const Case cases[] = {{"turgor_only", 2'000'000, "", "hdf5"},
                        {"arabidopsis_2022", 4'000'000, "wild_type", "hdf5"},
                        {"quick", 1'000'000, "", "csv,hdf5"}};
  for (const Case& c : cases) {
    CAPTURE(c.campaign);
    const std::string campaign = source_dir + "/campaigns/" + c.campaign + ".ini";
    CampaignOverrides overrides;
    overrides.samples = c.samples;
    overrides.formats = c.formats;
    std::vector<std::string> arguments{"run", campaign, "--samples", std::to_string(c.samples), "--formats", c.formats,
                                       "--quiet", "--out", std::string("out_") + c.campaign};
    if (*c.lines != '\0') {
      overrides.lines = c.lines;
      arguments.insert(arguments.end(), {"--lines", c.lines});
    }
    const MeasuredRun run = run_measured(arguments, scratch.root);
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    const RunFootprint estimate = estimate_run_footprint(shape_of(campaign, overrides));
    CAPTURE(run.peak_bytes);
    CAPTURE(estimate.memory_bytes);
    CHECK(estimate.memory_bytes >= run.peak_bytes);
    CHECK(static_cast<double>(estimate.memory_bytes) <= 1.3 * static_cast<double>(run.peak_bytes) + double(1u << 29));
    fs::remove_all(scratch.root / (std::string("out_") + c.campaign));
  }
  // growthuq sample keeps the design and its CSV text in memory: 7 variables of the wild type.
  const MeasuredRun sample = run_measured({"sample", "--line", source_dir + "/distributions/wild_type.ini", "--samples",
                                           "2000000", "--seed", "1", "--out", "design.csv"},
                                          scratch.root);
  REQUIRE_MESSAGE(sample.exit_code == 0, sample.err);
  const RunFootprint design = estimate_design_footprint(2'000'000, 7);
  CAPTURE(sample.peak_bytes);
  CAPTURE(design.memory_bytes);
  CHECK(design.memory_bytes >= sample.peak_bytes);
  CHECK(static_cast<double>(design.memory_bytes) <= 1.3 * static_cast<double>(sample.peak_bytes) + double(1u << 29));
}

TEST_CASE("the largest count offered (two significant digits) fits and the next one does not, memory and disk") {
  RunShape shape;
  shape.samples = 1'000'000'000;
  shape.lines = 5;
  shape.largest_inputs = 7;
  shape.largest_outputs = 5;
  shape.longest_line_name = 16;
  shape.csv = shape.hdf5 = shape.checkpoint = true;

  MachineRoom memory_only;
  memory_only.memory_bytes = 24'000'000'000ULL;
  memory_only.processes = 2;
  std::string message;
  try {
    require_room(estimate_run_footprint(shape), memory_only, "growthuq run", "--samples");
    FAIL("1e9 samples per line cannot fit in 24 GB");
  } catch (const InputError& error) {
    message = error.what();
  }
  CHECK(message.rfind("growthuq run: --samples = '1000000000': the run needs about ", 0) == 0);
  CHECK(message.find("for each of the 2 processes on this machine") != std::string::npos);
  const std::uint64_t fitting = largest_offered(message);
  shape.samples = fitting;
  CHECK_NOTHROW(require_room(estimate_run_footprint(shape), memory_only, "growthuq run", "--samples"));
  shape.samples = next_two_digit(fitting);
  CHECK_THROWS_AS(require_room(estimate_run_footprint(shape), memory_only, "growthuq run", "--samples"), InputError);
  // Twice the processes on the machine, about half the samples each.
  memory_only.processes = 4;
  shape.samples = 1'000'000'000;
  try {
    require_room(estimate_run_footprint(shape), memory_only, "growthuq run", "--samples");
  } catch (const InputError& error) {
    CHECK(static_cast<double>(largest_offered(error.what())) < 0.55 * static_cast<double>(fitting));
  }

  MachineRoom disk_only;
  disk_only.disk_bytes = 50'000'000'000ULL;
  shape.samples = 100'000'000;
  try {
    require_room(estimate_run_footprint(shape), disk_only, "study.ini", "[campaign] samples");
    FAIL("5 lines x 1e8 samples of csv, hdf5 and checkpoint cannot fit in 50 GB");
  } catch (const InputError& error) {
    message = error.what();
  }
  CHECK(message.rfind("study.ini: [campaign] samples = '100000000': the run writes about ", 0) == 0);
  CHECK(message.find("the file system it writes to has 50.0 GB free") != std::string::npos);
  shape.samples = largest_offered(message);
  CHECK_NOTHROW(require_room(estimate_run_footprint(shape), disk_only, "study.ini", "[campaign] samples"));
  shape.samples = next_two_digit(shape.samples);
  CHECK_THROWS_AS(require_room(estimate_run_footprint(shape), disk_only, "study.ini", "[campaign] samples"), InputError);
}

TEST_CASE("the machine's figures: memory below the total, disk of a folder not made yet is its parent's") {
  const std::optional<std::uint64_t> memory = available_memory_bytes();
  REQUIRE(memory.has_value());
  CHECK(*memory > 0);
  CHECK(*memory <= static_cast<std::uint64_t>(sysconf(_SC_PHYS_PAGES)) * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE)));
  const ScratchDirectory scratch("footprint_disk");
  const std::optional<std::uint64_t> here = available_disk_bytes(scratch.root.string());
  const std::optional<std::uint64_t> below = available_disk_bytes((scratch.root / "not" / "yet").string());
  REQUIRE(here.has_value());
  REQUIRE(below.has_value());
  // The same file system; other programs may write in between, so within 1 GB.
  CHECK((*here > *below ? *here - *below : *below - *here) < 1'000'000'000ULL);
}

TEST_CASE("a run or trade-off too large for this machine is refused in one line, before any work") {
  const ScratchDirectory scratch("footprint_cli");
  const std::string quick = source_dir + "/campaigns/quick.ini";
  // 4e9 samples per line need about 1 TB: no machine that runs these tests has that much.
  CliOutcome run = run_cli("run " + quick + " --samples 4000000000 --out big", scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err.rfind("growthuq run: error: --samples = '4000000000': the run needs about ", 0) == 0);
  CHECK(run.err.find("samples per line fit") != std::string::npos);
  CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(scratch.root / "big"));

  const CliOutcome tradeoff = run_cli("tradeoff " + quick + " --samples-list 100,4000000000 --out t.csv", scratch.root);
  CHECK(tradeoff.exit_code == 2);
  CHECK(tradeoff.err.rfind("growthuq tradeoff: error: --samples-list = '4000000000': the run needs about ", 0) == 0);
  CHECK_FALSE(fs::exists(scratch.root / "t.csv"));

  const CliOutcome sample = run_cli("sample --line " + source_dir + "/distributions/wild_type.ini --samples 4000000000 --seed 1 --out d.csv",
                                    scratch.root);
  CHECK(sample.exit_code == 2);
  CHECK(sample.err.rfind("growthuq sample: error: --samples = '4000000000': the run needs about ", 0) == 0);
  CHECK_FALSE(fs::exists(scratch.root / "d.csv"));

  // Under mpirun every process on the machine holds a whole line: the estimate counts them.
  const std::string mpi = "cd '" + scratch.root.string() + "' && env " + GROWTHUQ_MPI_ENVIRONMENT + " '" + GROWTHUQ_MPIEXEC +
                          "' -np 2 --oversubscribe '" + GROWTHUQ_CLI + "' run " + quick +
                          " --samples 4000000000 --out big >stdout.txt 2>stderr.txt";
  run = outcome_in(scratch.root, std::system(mpi.c_str()));
  CHECK(run.exit_code == 2);
  CHECK(run.err.find("for each of the 2 processes on this machine") != std::string::npos);
  CHECK_FALSE(fs::exists(scratch.root / "big"));
}
