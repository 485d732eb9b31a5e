// Interrupting `growthuq run` for real and resuming it (issue 4, "Long runs"): SIGTERM stops it
// cleanly (exit 143, no result file, the checkpoint kept and the message saying how to finish),
// SIGKILL leaves a checkpoint that still resumes (a torn record at its end included), a resume
// under mpirun finishes a serial run, and every resumed output file and the stdout summary are
// byte-identical to an uninterrupted run's. Also the refusals: changed input, overrides, a
// completed directory, a new run into an interrupted one.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "campaign/chunk_log.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, separator);) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

// A copy of the small test campaign whose line files are copies too (so a test may change one),
// run with enough samples and small chunks (37) that a run lasts long enough to be interrupted.
struct Study {
  ScratchDirectory scratch;
  fs::path root;
  fs::path campaign;
  std::vector<std::string> run_arguments;

  explicit Study(const std::string& name) : scratch("resume_" + name), root(scratch.root) {
    fs::create_directories(root / "lines");
    const std::string source = std::string(GROWTHUQ_SOURCE_DIR);
    for (const char* line : {"wild_type.ini", "pme48.ini"}) fs::copy_file(source + "/distributions/" + line, root / "lines" / line);
    std::string text = slurp(source + "/tests/campaign/data/small_campaign.ini");
    for (std::size_t at; (at = text.find("../../../distributions/")) != std::string::npos;) text.replace(at, 23, "lines/");
    campaign = root / "small.ini";
    spit(campaign, text);
    run_arguments = {"run", campaign.string(), "--samples", "100000", "--formats", "csv,hdf5", "--quiet", "--out", "out"};
  }

  fs::path directory(const std::string& name) const {
    fs::create_directories(root / name);
    return root / name;
  }
};

const char* const result_files[] = {"samples.csv", "summary.csv", "results.h5"};

// The uninterrupted run, in its own directory with the same command line (results.h5 stores it).
CliOutcome reference_run(const Study& study) {
  const CliOutcome outcome = run_in(study.directory("reference"), cli(study.run_arguments));
  REQUIRE_MESSAGE(outcome.exit_code == 0, outcome.err);
  return outcome;
}

// Starts the run in `directory` and returns once its checkpoint holds at least 20 chunks.
pid_t start_and_wait_for_chunks(const Study& study, const fs::path& directory) {
  const pid_t pid = start(cli(study.run_arguments), directory);
  const fs::path log = directory / "out" / "checkpoint" / "chunks.bin";
  const std::uintmax_t enough = 16 + 20 * (40 + 5 * 37 * 8);  // header + 20 chunks of 5 values x 37 samples
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  for (;;) {
    std::error_code error;
    if (fs::file_size(log, error) >= enough && !error) return pid;
    int status = 0;
    REQUIRE_MESSAGE(waitpid(pid, &status, WNOHANG) == 0, "the run ended before it could be interrupted");
    REQUIRE_MESSAGE(std::chrono::steady_clock::now() < deadline, "no checkpoint after 120 s");
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

// Sends `signal` to the run in `directory` once its checkpoint holds 20 chunks; its wait status.
int interrupt_after_chunks(const Study& study, const fs::path& directory, int signal) {
  const pid_t pid = start_and_wait_for_chunks(study, directory);
  kill(pid, signal);
  return wait_for(pid);
}

// Interrupts the run in `directory` with `signal` as above: it must stop cleanly, exiting with
// `exit_code` (128 + the signal's number).
void interrupt_cleanly(const Study& study, const fs::path& directory, int signal, int exit_code) {
  const int status = interrupt_after_chunks(study, directory, signal);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == exit_code);
}

std::size_t samples_in_log(const fs::path& log) {
  std::size_t samples = 0;
  for (const ChunkRecord& record : scan_chunk_log(log.string()).records) samples += record.range.end - record.range.begin;
  return samples;
}

std::set<std::string> entries(const fs::path& directory) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory)) names.insert(entry.path().filename().string());
  return names;
}

void check_identical(const fs::path& resumed, const fs::path& reference) {
  for (const char* name : result_files) {
    CAPTURE(name);
    const std::string a = slurp(resumed / name);
    const std::string b = slurp(reference / name);
    CHECK(a.size() == b.size());
    CHECK_MESSAGE(a == b, "differs byte for byte");
  }
}

// Resumes the run in `work` with `command`: it must succeed and print, and write, byte for byte
// what the uninterrupted reference run did.
CliOutcome check_resumes_identically(const Study& study, const fs::path& work, const CliOutcome& reference,
                                     const std::vector<std::string>& command,
                                     const std::vector<std::string>& environment = {}) {
  const CliOutcome resumed = run_in(work, command, environment);
  REQUIRE_MESSAGE(resumed.exit_code == 0, resumed.err);
  CHECK(resumed.out == reference.out);
  check_identical(work / "out", study.root / "reference" / "out");
  return resumed;
}

}  // namespace

TEST_CASE("SIGTERM stops a run cleanly; --resume finishes it byte-identical to an uninterrupted run") {
  Study study("sigterm");
  const CliOutcome reference = reference_run(study);
  const fs::path work = study.directory("interrupted");
  interrupt_cleanly(study, work, SIGTERM, 143);

  // No result file and no partial one; only the checkpoint, holding what the message says.
  CHECK(entries(work / "out") == std::set<std::string>{"checkpoint"});
  const std::string err = slurp(work / "stderr.txt");
  const std::string prefix = "growthuq run: interrupted after ";
  REQUIRE_MESSAGE(err.rfind(prefix, 0) == 0, err);
  const std::size_t done = std::stoull(err.substr(prefix.size()));
  CHECK(err.substr(prefix.size() + std::to_string(done).size()) ==
        " of 200000 samples; finish with: growthuq run --resume out\n");
  CHECK(done == samples_in_log(work / "out" / "checkpoint" / "chunks.bin"));
  CHECK(done >= 20 * 37);
  CHECK(done < 200000);

  // A new run into the interrupted directory is refused with the way to finish it.
  const CliOutcome again = run_in(work, cli(study.run_arguments));
  CHECK(again.exit_code == 2);
  CHECK(again.err.find("out: holds an interrupted run; finish it with: growthuq run --resume out (or pass --force to start it again)") != std::string::npos);
  // Options that would change the result are refused with --resume.
  const CliOutcome more = run_in(work, cli({"run", "--resume", "out", "--samples", "200000"}));
  CHECK(more.exit_code == 2);
  CHECK(more.err.find("--samples cannot be combined with --resume") != std::string::npos);
  const CliOutcome both = run_in(work, cli({"run", study.campaign.string(), "--resume", "out"}));
  CHECK(both.exit_code == 2);
  CHECK(both.err.find("not both") != std::string::npos);

  // The campaign file edited since (another seed): the resume finishes the run as started, from
  // the stored text (the results are the reference's), and says so in one line; --quiet keeps
  // the progress off stderr.
  std::string campaign_text = slurp(study.campaign);
  const std::size_t seed = campaign_text.find("seed = 11\n");
  REQUIRE(seed != std::string::npos);
  spit(study.campaign, campaign_text.replace(seed, 10, "seed = 12\n"));
  const CliOutcome resumed = check_resumes_identically(study, work, reference, cli({"run", "--resume", "out", "--quiet"}));
  CHECK(resumed.err == "growthuq run: warning: " + study.campaign.string() +
                           " changed since the run started; resuming with the campaign text stored in " +
                           (fs::path("out") / "checkpoint" / "manifest.txt").string() +
                           " (to run the file as it is now, start the run again with --force)\n");
  CHECK_FALSE(fs::exists(work / "out" / "checkpoint"));

  const CliOutcome finished = run_in(work, cli({"run", "--resume", "out"}));
  CHECK(finished.exit_code == 2);
  CHECK(finished.err.find("holds no checkpoint") != std::string::npos);
}

TEST_CASE("after SIGKILL and a torn record, a changed line file is refused; restored, the run resumes identically") {
  Study study("sigkill");
  const CliOutcome reference = reference_run(study);
  const fs::path work = study.directory("killed");
  const int status = interrupt_after_chunks(study, work, SIGKILL);
  REQUIRE(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGKILL);

  // A record cut short, as a kill in the middle of a write leaves it: the scan must ignore it.
  const fs::path log = work / "out" / "checkpoint" / "chunks.bin";
  const std::string bytes = slurp(log);
  const std::size_t record = 40 + 5 * 37 * 8;
  spit(log, bytes + bytes.substr(16, record / 2));
  const std::size_t held = samples_in_log(log);
  CHECK(held > 0);

  const fs::path line = study.root / "lines" / "pme48.ini";
  const std::string original = slurp(line);
  spit(line, original + "# edited after the run started\n");
  const CliOutcome refused = run_in(work, cli({"run", "--resume", "out"}));
  CHECK(refused.exit_code == 2);
  CHECK(refused.err.find(line.string() + ": changed since the interrupted run") != std::string::npos);
  spit(line, original);

  // The campaign file gone: a warning, and the stored text is used. Without --quiet (the
  // interrupted run had it): progress, one line per plant line as stderr is not a terminal;
  // the results the same.
  fs::rename(study.campaign, study.root / "moved.ini");
  const CliOutcome resumed = check_resumes_identically(study, work, reference, cli({"run", "--resume", "out"}));
  const std::vector<std::string> progress = split(resumed.err, '\n');
  REQUIRE(progress.size() == 3);
  CHECK(progress[0] == "growthuq run: warning: " + study.campaign.string() +
                           " cannot be read now; resuming with the campaign text stored in " +
                           (fs::path("out") / "checkpoint" / "manifest.txt").string() +
                           " (to run the file as it is now, start the run again with --force)");
  for (std::size_t i = 1; i < 3; ++i) CHECK(progress[i].find(" 100000 samples in ") != std::string::npos);
  CHECK(entries(work / "out") == std::set<std::string>{"provenance.json", "samples.csv", "sensitivity.csv", "summary.csv", "results.h5"});
}

TEST_CASE("a serially interrupted run resumes under mpirun -np 2 to the identical result") {
  Study study("mpi");
  const CliOutcome reference = reference_run(study);
  const fs::path work = study.directory("interrupted");
  interrupt_cleanly(study, work, SIGINT, 130);

  const std::vector<std::string> environment = split(GROWTHUQ_MPI_ENVIRONMENT, ' ');
  const CliOutcome resumed = check_resumes_identically(
      study, work, reference,
      {GROWTHUQ_MPIEXEC, "-np", "2", "--oversubscribe", GROWTHUQ_CLI, "run", "--resume", "out", "--quiet"}, environment);
  CHECK(resumed.err.find("warning") == std::string::npos);  // the campaign file is as it was
}

TEST_CASE("with --no-checkpoint an interrupted run keeps nothing and says so") {
  Study study("no_checkpoint");
  const fs::path work = study.directory("interrupted");
  std::vector<std::string> command = cli(study.run_arguments);
  command.push_back("--no-checkpoint");
  const pid_t pid = start(command, work);
  // The partial results file appears when sampling starts; the run then lasts over a second.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(work / "out" / "staging" / "samples.csv.partial")) {
    int status = 0;
    REQUIRE_MESSAGE(waitpid(pid, &status, WNOHANG) == 0, "the run ended before it could be interrupted");
    REQUIRE(std::chrono::steady_clock::now() < deadline);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  CHECK_FALSE(fs::exists(work / "out" / "checkpoint"));
  kill(pid, SIGTERM);
  const int status = wait_for(pid);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 143);
  CHECK(slurp(work / "stderr.txt") == "growthuq run: interrupted; nothing was kept to resume (--no-checkpoint)\n");
  CHECK_FALSE(fs::exists(work / "out"));  // the run made it and left nothing in it
}
