// What a run guarantees about its output directory (src/cli/README.md, "What a run guarantees"):
// one live run per directory (a second is refused naming the first, a dead one's lock taken
// over), results committed together only when all are complete (a stop during the final writes
// commits nothing), a full disk keeping the checkpoint for --resume, and writers killed by a
// signal leaving no partial file. The full-disk cases need a small tmpfs, so root: they are
// skipped, saying so, otherwise.
#include <doctest/doctest.h>

#include <sys/file.h>
#include <sys/mount.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include "campaign/campaign_outputs.hpp"
#include "campaign/checkpoint.hpp"
#include "campaign/checkpoint_manifest.hpp"
#include "campaign/output_lock.hpp"
#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/pool/pool.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/small_disk.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::string source = GROWTHUQ_SOURCE_DIR;
const std::string small_campaign = source + "/tests/campaign/data/small_campaign.ini";

std::set<std::string> entries(const fs::path& directory) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory)) names.insert(entry.path().filename().string());
  return names;
}

// A lock on DIR/run.lock as another live run holds it: an open file description of this process
// with an exclusive flock, its record written.
struct ForeignLock {
  int descriptor;
  explicit ForeignLock(const fs::path& directory) {
    descriptor = ::open((directory / run_lock_name).c_str(), O_RDWR | O_CREAT, 0644);
    REQUIRE(descriptor >= 0);
    REQUIRE(::flock(descriptor, LOCK_EX | LOCK_NB) == 0);
    const std::string record = "pid 4242 on host elsewhere\n";
    REQUIRE(::write(descriptor, record.data(), record.size()) == static_cast<ssize_t>(record.size()));
  }
  ~ForeignLock() { ::close(descriptor); }
};

// Fills the file system at `directory` to the last byte with a file named `name`.
void fill(const fs::path& directory, const std::string& name) {
  std::FILE* file = std::fopen((directory / name).c_str(), "wb");
  REQUIRE(file != nullptr);
  const std::string block(4096, 'x');
  while (std::fwrite(block.data(), 1, block.size(), file) == block.size() && std::fflush(file) == 0) {
  }
  std::fclose(file);
  // What is left is smaller than a block: fill it byte by byte.
  file = std::fopen((directory / name).c_str(), "ab");
  while (std::fputc('x', file) != EOF && std::fflush(file) == 0) {
  }
  std::fclose(file);
}

}  // namespace

TEST_CASE("a second run into a directory a live run holds is refused naming it; a dead run's lock is taken over") {
  const ScratchDirectory scratch("output_lock");
  const fs::path out = scratch.root / "out";
  const CliOutcome first = run_in(scratch.root, cli({"run", small_campaign, "--quiet", "--out", "out"}));
  REQUIRE_MESSAGE(first.exit_code == 0, first.err);
  CHECK(entries(out) == std::set<std::string>{"provenance.json", "samples.csv", "sensitivity.csv", "summary.csv"});  // no lock file left
  const std::string results = slurp(out / "samples.csv");
  // The live run's checkpoint: without the lock this directory reads as an interrupted run.
  fs::create_directories(out / "checkpoint");
  spit(out / "checkpoint" / "manifest.txt", "as a live run has it\n");
  {
    const ForeignLock live(out);
    const std::string in_use = "growthuq run: error: out: is in use by another growthuq run (pid 4242 on host elsewhere, "
                               "lock file out/run.lock): wait for it to end or stop it; two runs in one output directory "
                               "would mix their files\n";
    for (const std::vector<std::string>& arguments :
         {std::vector<std::string>{"run", small_campaign, "--quiet", "--out", "out"},
          std::vector<std::string>{"run", small_campaign, "--quiet", "--out", "out", "--force"}}) {
      const CliOutcome second = run_in(scratch.root, cli(arguments));
      CHECK(second.exit_code == 2);
      CHECK(second.err == in_use);  // not "holds an interrupted run; finish it with --resume"
    }
    CHECK(slurp(out / "samples.csv") == results);
    CHECK(slurp(out / run_lock_name) == "pid 4242 on host elsewhere\n");
  }
  // The holder gone (its lock released as a killed process's is), its file and record left: the
  // next run takes the lock over and removes the file when done.
  fs::remove_all(out / "checkpoint");
  REQUIRE(fs::exists(out / run_lock_name));
  const CliOutcome rerun = run_in(scratch.root, cli({"run", small_campaign, "--quiet", "--out", "out", "--force"}));
  CHECK_MESSAGE(rerun.exit_code == 0, rerun.err);
  CHECK(entries(out) == std::set<std::string>{"provenance.json", "samples.csv", "sensitivity.csv", "summary.csv"});
  CHECK(slurp(out / "samples.csv") == results);
}

TEST_CASE("the lock is taken by one OutputDirectoryLock at a time and its file goes with the last") {
  const ScratchDirectory scratch("output_lock_object");
  {
    const OutputDirectoryLock held(scratch.root.string());
    const std::string record = slurp(scratch.root / run_lock_name);
    CHECK(record.starts_with("pid " + std::to_string(::getpid()) + " on host "));
    CHECK_THROWS_WITH_AS(OutputDirectoryLock(scratch.root.string()),
                         (scratch.root.string() + ": is in use by another growthuq run (" + record.substr(0, record.size() - 1) +
                          ", lock file " + (scratch.root / run_lock_name).string() +
                          "): wait for it to end or stop it; two runs in one output directory would mix their files")
                             .c_str(),
                         InputError);
  }
  CHECK(!fs::exists(scratch.root / run_lock_name));
  const OutputDirectoryLock again(scratch.root.string());  // free again
  CHECK(fs::exists(scratch.root / run_lock_name));
}

TEST_CASE("a stop during the final writes commits nothing and keeps the checkpoint; --resume then commits the set") {
  const ScratchDirectory scratch("final_stop");
  Campaign campaign = read_campaign(small_campaign);
  campaign.output_dir = (scratch.root / "out").string();
  const PreparedCampaign prepared(campaign);
  const std::unique_ptr<Pool> pool = make_serial_pool();
  // SIGTERM arrives once the results are being written: summary.csv is staged just before the
  // last check (the chunks and the bootstrap saw no request).
  const fs::path staged_summary = scratch.root / "out" / staging_name / summary_csv_name;
  pool->stop_when([&] { return fs::exists(staged_summary) ? SIGTERM : 0; });
  OutputSettings settings;
  settings.checkpointing = Checkpointing::start;
  settings.manifest = make_checkpoint_manifest(campaign, CampaignOverrides{}, "growthuq run");
  std::ostringstream report, log;
  try {
    run_campaign_with_outputs(prepared, *pool, settings, report, log);
    FAIL("the stop during the final writes was ignored");
  } catch (const RunInterrupted& interrupted) {
    CHECK(interrupted.reason() == SIGTERM);
    CHECK(std::string(interrupted.what()) == "interrupted after 400 of 400 samples; finish with: growthuq run --resume " +
                                                 campaign.output_dir);
  }
  CHECK(entries(scratch.root / "out") == std::set<std::string>{"checkpoint"});
  CHECK(report.str().empty());

  pool->stop_when([] { return 0; });
  settings.checkpointing = Checkpointing::resume;
  run_campaign_with_outputs(prepared, *pool, settings, report, log);
  CHECK(entries(scratch.root / "out") == std::set<std::string>{"provenance.json", "samples.csv", "sensitivity.csv", "summary.csv"});
  CHECK(report.str().find("campaign 'small': 2 lines x 200 samples") != std::string::npos);
}

TEST_CASE("a full disk fails the run without touching the old results, keeps the checkpoint, and --resume finishes") {
  const ScratchDirectory scratch("full_disk");
  SmallDisk disk(scratch.root / "disk", 48 * 1024);
  if (!disk.mounted()) {
    MESSAGE("cannot mount a tmpfs here (needs root): the full-disk run is not checked");
    return;
  }
  const std::vector<std::string> run = {"run", small_campaign, "--samples", "30000", "--formats", "csv,hdf5",
                                        "--quiet", "--out", "out", "--force"};
  // The reference: the same command on a disk with room.
  const fs::path reference = scratch.root / "reference";
  fs::create_directories(reference);
  const CliOutcome finished = run_in(reference, cli(run));
  REQUIRE_MESSAGE(finished.exit_code == 0, finished.err);
  // Old results in the directory on the small disk: a smaller run's.
  const CliOutcome old = run_in(disk.where, cli({"run", small_campaign, "--quiet", "--out", "out", "--formats", "csv,hdf5"}));
  REQUIRE_MESSAGE(old.exit_code == 0, old.err);
  const std::string old_samples = slurp(disk.where / "out" / "samples.csv");
  const std::string old_h5 = slurp(disk.where / "out" / "results.h5");

  // The --force rerun; the disk fills once its checkpoint holds chunks.
  const pid_t pid = start(cli(run), disk.where);
  const fs::path log = disk.where / "out" / "checkpoint" / "chunks.bin";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  std::error_code error;
  while (!(fs::file_size(log, error) > 100000 && !error)) {
    int status = 0;
    REQUIRE_MESSAGE(::waitpid(pid, &status, WNOHANG) == 0, "the run ended before the disk could be filled");
    REQUIRE(std::chrono::steady_clock::now() < deadline);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  fill(disk.where, "filler");
  const CliOutcome failed = outcome_in(disk.where, wait_for(pid));
  CHECK(failed.exit_code == 2);
  CAPTURE(failed.err);
  CHECK(failed.err.find("No space left on device") != std::string::npos);
  CHECK(failed.err.ends_with("; the checkpoint keeps the finished chunks: make room, then finish with: growthuq run "
                             "--resume out\n"));
  // The old results as they were, nothing new beside them, the checkpoint kept.
  CHECK(entries(disk.where / "out") == std::set<std::string>{"checkpoint", "provenance.json", "results.h5", "samples.csv", "sensitivity.csv", "summary.csv"});
  CHECK(slurp(disk.where / "out" / "samples.csv") == old_samples);
  CHECK(slurp(disk.where / "out" / "results.h5") == old_h5);
  CHECK(has_checkpoint((disk.where / "out").string()));

  // Room made, the resume finishes the run as the reference did.
  fs::remove(disk.where / "filler");
  const CliOutcome resumed = run_in(disk.where, cli({"run", "--resume", "out", "--quiet"}));
  REQUIRE_MESSAGE(resumed.exit_code == 0, resumed.err);
  CHECK(entries(disk.where / "out") == std::set<std::string>{"provenance.json", "results.h5", "samples.csv", "sensitivity.csv", "summary.csv"});
  for (const char* name : {"samples.csv", "summary.csv", "results.h5"}) {
    CAPTURE(name);
    CHECK(slurp(disk.where / "out" / name) == slurp(reference / "out" / name));
  }
}

TEST_CASE("synth on a full disk leaves no raw.ini naming a missing file, and no partial file") {
  const ScratchDirectory scratch("synth_full_disk");
  SmallDisk disk(scratch.root / "disk", 64);
  if (!disk.mounted()) {
    MESSAGE("cannot mount a tmpfs here (needs root): synth on a full disk is not checked");
    return;
  }
  const CliOutcome run =
      run_in(disk.where, cli({"synth", source + "/distributions/wild_type.ini", "--tubes", "60:60", "--curves", "20:20", "--out", "data"}));
  CHECK(run.exit_code == 2);
  CHECK(run.err.find("No space left on device") != std::string::npos);
  const fs::path folder = disk.where / "data" / "wild_type";
  CHECK(!fs::exists(folder / "raw.ini"));
  for (const auto& entry : fs::recursive_directory_iterator(disk.where)) {
    CHECK(entry.path().extension() != ".partial");
  }
}

TEST_CASE("SIGTERM to sample while it writes removes its partial file and ends it by the signal") {
  const ScratchDirectory scratch("sample_sigterm");
  spit(scratch.root / "line.ini", slurp(source + "/distributions/wild_type.ini"));
  const pid_t pid = start(cli({"sample", "--line", "line.ini", "--samples", "3000000", "--seed", "1", "--out", "design.csv"}),
                          scratch.root);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(scratch.root / "design.csv.partial")) {
    int status = 0;
    REQUIRE_MESSAGE(::waitpid(pid, &status, WNOHANG) == 0, "sample ended before it could be stopped");
    REQUIRE(std::chrono::steady_clock::now() < deadline);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ::kill(pid, SIGTERM);
  const int status = wait_for(pid);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  CHECK(!fs::exists(scratch.root / "design.csv.partial"));
  CHECK(!fs::exists(scratch.root / "design.csv"));
}
