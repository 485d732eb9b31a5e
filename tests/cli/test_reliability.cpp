// The guarantees of src/cli/README.md's "What a run guarantees", end to end through the CLI: a run refused
// by the lock touches nothing; a full disk during results.h5 gives one line and no crash, and
// keeps the old results and the checkpoint; option abbreviations are errors; every output path
// is checked before the work; a command's outputs commit together or not at all.
#include <doctest/doctest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/small_disk.hpp"
#include "support/special_files.hpp"
#include "support/text_file.hpp"

using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::string source = GROWTHUQ_SOURCE_DIR;
const std::string small_campaign = source + "/tests/campaign/data/small_campaign.ini";

// Every file under `directory` (relative path -> content; folders as "<dir>"): what a refused
// run must leave exactly as it was.
std::map<std::string, std::string> snapshot(const fs::path& directory) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(directory)) {
    const std::string name = fs::relative(entry.path(), directory).string();
    files[name] = entry.is_directory() ? "<dir>" : slurp(entry.path());
  }
  return files;
}

// A lock on DIR/run.lock as another live run holds it (an exclusive flock of this process).
struct ForeignLock {
  int descriptor;
  explicit ForeignLock(const fs::path& directory) {
    descriptor = ::open((directory / "run.lock").c_str(), O_RDWR | O_CREAT, 0644);
    REQUIRE(descriptor >= 0);
    REQUIRE(::flock(descriptor, LOCK_EX | LOCK_NB) == 0);
    const std::string record = "pid 4242 on host elsewhere\n";
    REQUIRE(::ftruncate(descriptor, 0) == 0);
    REQUIRE(::pwrite(descriptor, record.data(), record.size(), 0) == static_cast<ssize_t>(record.size()));
  }
  ~ForeignLock() { ::close(descriptor); }
  ForeignLock(const ForeignLock&) = delete;
  ForeignLock& operator=(const ForeignLock&) = delete;
};

std::size_t lines_in(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

TEST_CASE("a run refused by the lock touches nothing: the live run's staging, checkpoint and lock stay as they were") {
  const ScratchDirectory scratch("refused_touches_nothing");
  const fs::path out = scratch.root / "out";
  // A real interrupted run's checkpoint (SIGTERM once chunks are kept).
  const pid_t pid = start(cli({"run", small_campaign, "--samples", "400000", "--quiet", "--out", "out"}), scratch.root);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  std::error_code error;
  while (!(fs::file_size(out / "checkpoint" / "chunks.bin", error) > 1000 && !error)) {
    int status = 0;
    REQUIRE_MESSAGE(::waitpid(pid, &status, WNOHANG) == 0, "the run ended before it could be stopped");
    REQUIRE(std::chrono::steady_clock::now() < deadline);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(pid, SIGTERM);
  const CliOutcome stopped = outcome_in(scratch.root, wait_for(pid));
  REQUIRE_MESSAGE(stopped.exit_code == 143, stopped.err);
  // What the live run has staged and its lock.
  fs::create_directories(out / "staging");
  spit(out / "staging" / "samples.csv.partial", "the live run's rows\n");
  const ForeignLock live(out);
  const std::map<std::string, std::string> before = snapshot(out);
  REQUIRE(before.count("staging/samples.csv.partial") == 1);
  REQUIRE(before.count("checkpoint/chunks.bin") == 1);

  const std::string in_use = ": error: out: is in use by another growthuq run (pid 4242 on host elsewhere, "
                             "lock file out/run.lock): wait for it to end or stop it; two runs in one output directory "
                             "would mix their files\n";
  for (const std::vector<std::string>& arguments :
       {std::vector<std::string>{"run", small_campaign, "--quiet", "--out", "out"},
        std::vector<std::string>{"run", small_campaign, "--quiet", "--out", "out", "--force"},
        std::vector<std::string>{"run", "--resume", "out", "--quiet"},
        std::vector<std::string>{"check", small_campaign, "--out", "out", "--force"}}) {
    CAPTURE(arguments[0]);
    CAPTURE(arguments[1]);
    CAPTURE(arguments.back());
    const CliOutcome refused = run_in(scratch.root, cli(arguments));
    CHECK(refused.exit_code == 2);
    CHECK(refused.err == "growthuq " + arguments[0] + in_use);
    CHECK(snapshot(out) == before);
  }
}

TEST_CASE("a full disk while results.h5 is written: one line, no crash, old results and checkpoint kept, --resume finishes") {
  const ScratchDirectory scratch("hdf5_full_disk");
  SmallDisk disk(scratch.root / "disk", 2048);
  if (!disk.mounted()) {
    MESSAGE("cannot mount a tmpfs here (needs root): the full disk during the HDF5 write is not checked");
    return;
  }
  // The command runs in the scratch folder (its stdout and stderr files must not be on the full
  // disk), its results on the small disk.
  const fs::path out = disk.where / "out";
  const std::vector<std::string> rerun = {"run", small_campaign, "--formats", "hdf5", "--quiet", "--out", "disk/out", "--force"};
  bool hdf5_failed = false;
  // The free space left decides which write meets the full disk first: from too little for the
  // run to start (the up-front room check) through results.h5's data, summary.csv and
  // results.h5's last metadata, to enough for all of it.
  for (std::uint64_t keep = 56 * 1024; keep <= 400 * 1024; keep += 8 * 1024) {
    CAPTURE(keep);
    fs::remove(disk.where / "filler");
    fs::remove_all(out);
    const CliOutcome old = run_in(scratch.root, cli({"run", small_campaign, "--formats", "hdf5", "--samples", "100",
                                                     "--quiet", "--out", "disk/out"}));
    REQUIRE_MESSAGE(old.exit_code == 0, old.err);
    const std::string old_h5 = slurp(out / "results.h5");
    const std::string old_summary = slurp(out / "summary.csv");
    disk.fill_leaving("filler", keep);

    const CliOutcome run = run_in(scratch.root, cli(rerun));
    CAPTURE(run.err);
    REQUIRE(run.exit_code != -1);  // never killed by a signal (it was SIGSEGV, exit 139)
    if (run.exit_code == 0) break;  // room enough: nothing failed
    CHECK(run.exit_code == 2);
    CHECK(lines_in(run.err) == 1);
    CHECK(run.err.starts_with("growthuq run: error: "));
    CHECK(run.err.find("HDF5-DIAG") == std::string::npos);
    CHECK(run.err.find("H5") == std::string::npos);
    // The old results as they were, nothing of the failed run beside them.
    CHECK(slurp(out / "results.h5") == old_h5);
    CHECK(slurp(out / "summary.csv") == old_summary);
    CHECK(!fs::exists(out / "staging"));
    CHECK(!fs::exists(out / "run.lock"));
    if (run.err.find("disk/out/staging/results.h5.partial: write failed: No space left on device") == std::string::npos) {
      continue;
    }
    CHECK(run.err.ends_with("; the checkpoint keeps the finished chunks: make room, then finish with: growthuq run --resume "
                            "disk/out\n"));
    REQUIRE(fs::exists(out / "checkpoint" / "manifest.txt"));
    if (hdf5_failed) continue;
    hdf5_failed = true;
    // Room made, the resume finishes (once: it takes the place of the run).
    fs::remove(disk.where / "filler");
    const CliOutcome resumed = run_in(scratch.root, cli({"run", "--resume", "disk/out", "--quiet"}));
    CHECK_MESSAGE(resumed.exit_code == 0, resumed.err);
    CHECK(!fs::exists(out / "checkpoint"));
    CHECK(slurp(out / "summary.csv") != old_summary);  // the 200-sample run's
  }
  CHECK_MESSAGE(hdf5_failed, "no free space tried made the results.h5 write fail");
}

TEST_CASE("option abbreviations are errors, not another option") {
  const ScratchDirectory scratch("abbreviations");
  const CliOutcome run = run_in(scratch.root, cli({"run", small_campaign, "--sam", "10", "--quiet", "--out", "o"}));
  CHECK(run.exit_code == 2);
  CHECK(run.err == "growthuq run: error: unrecognised option '--sam' (see growthuq run --help)\n");
  CHECK(!fs::exists(scratch.root / "o"));
  // tradeoff has --samples-list, and no --samples: it ran as --samples-list.
  const CliOutcome tradeoff =
      run_in(scratch.root, cli({"tradeoff", small_campaign, "--samples", "100,200", "--quiet", "--out", "t.csv"}));
  CHECK(tradeoff.exit_code == 2);
  CHECK(tradeoff.err == "growthuq tradeoff: error: unrecognised option '--samples' (see growthuq tradeoff --help)\n");
  CHECK(!fs::exists(scratch.root / "t.csv"));
  // The full names and the declared short forms still work.
  const CliOutcome full = run_in(scratch.root, cli({"run", small_campaign, "--samples", "50", "--quiet", "--out", "o"}));
  CHECK_MESSAGE(full.exit_code == 0, full.err);
}

TEST_CASE("every output path is checked before the work") {
  const ScratchDirectory scratch("outputs_first");
  const auto refused_at_once = [&](const std::vector<std::string>& arguments, const std::string& message) {
    CAPTURE(arguments[0]);
    const auto start_time = std::chrono::steady_clock::now();
    const CliOutcome outcome = run_in(scratch.root, cli(arguments));
    CHECK(outcome.exit_code == 2);
    CHECK(outcome.err == message);
    CHECK(seconds_since(start_time) < 5.0);  // the work takes minutes (indent, eval) or 15 s (the raw fits)
  };
  const std::string missing = ": cannot be written: the folder nodir does not exist (expected an existing folder; create it first)\n";
  refused_at_once({"indent", "--p-MPa", "0.3", "--E-MPa", "30", "--h-nm", "150", "--d0-um", "5", "--rho-um", "0.5", "--out", "nodir/c.csv", "--quiet"}, "growthuq indent: error: nodir/c.csv" + missing);
  spit(scratch.root / "tubes.csv", "k_N_per_m,d_um,d0_um,h_nm\n1.5,6.5,6.0,200\n");
  refused_at_once({"eval", "--fidelity", "shell_fe", "--rho-um", "0.5", "--in", "tubes.csv", "--out", "nodir/r.csv"},
                  "growthuq eval: error: nodir/r.csv" + missing);
  refused_at_once({"fit-correction", "--training", source + "/src/correction/training.csv", "--out", "c.inc", "--errors",
                   "nodir/e.csv"},
                  "growthuq fit-correction: error: nodir/e.csv" + missing);
  // A folder that is a device (made here, never /dev's).
  if (make_special_file(scratch.root / "dev", SpecialKind::null_device)) {
    refused_at_once({"indent", "--p-MPa", "0.3", "--E-MPa", "30", "--h-nm", "150", "--d0-um", "5", "--rho-um", "0.5", "--out", "dev/c.csv", "--quiet"},
                    "growthuq indent: error: dev/c.csv: cannot be written: dev is not a folder\n");
  }
  // An existing output directory of a raw-data campaign, before its curves are fitted.
  fs::create_directories(scratch.root / "existing");
  const std::string exists = "existing: output directory already exists; choose another (--out DIR) or pass --force to "
                             "replace its results\n";
  refused_at_once({"check", source + "/campaigns/from_raw.ini", "--out", "existing"}, "growthuq check: error: " + exists);
  refused_at_once({"run", source + "/campaigns/from_raw.ini", "--out", "existing", "--quiet"}, "growthuq run: error: " + exists);
  CHECK(fs::is_empty(scratch.root / "existing"));
}

TEST_CASE("a command's outputs commit together: the second failing leaves no first") {
  const ScratchDirectory scratch("commit_together");
  // The second output's temporary file cannot be made (a folder in its place): the first,
  // written before, must not be committed.
  fs::create_directories(scratch.root / "e.csv.partial");
  const CliOutcome correction = run_in(scratch.root, cli({"fit-correction", "--training", source + "/src/correction/training.csv",
                                                          "--out", "c.inc", "--errors", "e.csv"}));
  CHECK(correction.exit_code == 2);
  CHECK(correction.err == "growthuq fit-correction: error: e.csv.partial: is a directory: expected no file there (the "
                          "temporary file a result is written to before it is renamed into place)\n");
  CHECK(!fs::exists(scratch.root / "c.inc"));
  CHECK(!fs::exists(scratch.root / "c.inc.partial"));

  const std::string raw = source + "/distributions/example_raw/wild_type/";
  fs::create_directories(scratch.root / "d.ini.partial");
  // --quiet: the write fails after the curve fits, whose progress line would come first.
  const CliOutcome relax = run_in(scratch.root, cli({"relax", raw + "relaxation_curves.csv", "--meta", raw + "relaxation_meta.csv",
                                                     "--out", "fits.csv", "--fit-distributions", "d.ini", "--quiet"}));
  CHECK(relax.exit_code == 2);
  CHECK(relax.err.starts_with("growthuq relax: error: d.ini.partial: is a directory"));
  CHECK(!fs::exists(scratch.root / "fits.csv"));
  CHECK(!fs::exists(scratch.root / "fits.csv.partial"));

  // Both possible: both written.
  fs::remove(scratch.root / "e.csv.partial");
  const CliOutcome both = run_in(scratch.root, cli({"fit-correction", "--training", source + "/src/correction/training.csv",
                                                    "--out", "c.inc", "--errors", "e.csv"}));
  CHECK_MESSAGE(both.exit_code == 0, both.err);
  CHECK(fs::file_size(scratch.root / "c.inc") > 0);
  CHECK(fs::file_size(scratch.root / "e.csv") > 0);
}

TEST_CASE("a finite-element run says how long it will take before it starts, also with --quiet") {
  const ScratchDirectory scratch("fe_estimate_quiet");
  // 100 000 finite-element samples: days. Stopped (SIGKILL) once it has said so.
  const std::string campaign = source + "/tests/campaign/data/fidelity_campaign.ini";
  for (const std::vector<std::string>& arguments :
       {std::vector<std::string>{"run", campaign, "--samples", "100000", "--quiet", "--out", "big"},
        std::vector<std::string>{"tradeoff", campaign, "--samples-list", "20,40", "--fe-samples-list", "2,100000", "--quiet",
                                 "--out", "t.csv"}}) {
    CAPTURE(arguments[0]);
    const pid_t pid = start(cli(arguments), scratch.root);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    std::string err;
    bool ended = false;
    while (err.find(" days with 1 process") == std::string::npos && std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      if (::waitpid(pid, &status, WNOHANG) == pid) {
        ended = true;
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      err = slurp(scratch.root / "stderr.txt");
    }
    if (!ended) {
      ::kill(pid, SIGKILL);
      wait_for(pid);
    }
    err = slurp(scratch.root / "stderr.txt");
    CAPTURE(err);
    CHECK(!ended);
    CHECK(err.starts_with("growthuq " + arguments[0] + ": time: "));
    // The finite-element line's 100000 (run); 3 lines x (2 + 100000) (tradeoff).
    CHECK(err.find(arguments[0] == "run" ? "100000 finite-element samples" : "300006 finite-element samples") !=
          std::string::npos);
    CHECK(err.find(" days with 1 process") != std::string::npos);
  }
}

namespace {

// `text` with every line's `column`-th comma-separated cell (0-based) replaced by `value`,
// the header line kept.
std::string with_column(const std::string& text, std::size_t column, const std::string& value) {
  std::string out;
  std::size_t start = 0;
  bool header = true;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!header && !line.empty()) {
      std::size_t from = 0;
      for (std::size_t c = 0; c < column; ++c) from = line.find(',', from) + 1;
      const std::size_t to = line.find(',', from);
      line.replace(from, to - from, value);
    }
    header = false;
    out += line + "\n";
    start = end + 1;
  }
  return out;
}

// The wild type's line file with the section [variable] replaced by `section`.
std::string line_with(const std::string& variable, const std::string& section) {
  const std::string text = slurp(source + "/distributions/wild_type.ini");
  const std::size_t from = text.find("\n[" + variable + "]\n") + 1;
  const std::size_t to = text.find("\n[", from);
  return text.substr(0, from) + section + (to == std::string::npos ? "" : text.substr(to));
}

}  // namespace

TEST_CASE("nonsense inputs are refused naming file, line and value, or warned about") {
  const ScratchDirectory scratch("nonsense_inputs");
  // Laws that draw values <= 0 of a positive quantity: sampled, with a warning saying how many.
  spit(scratch.root / "uniform.ini",
       line_with("k", "[k]\nlaw = uniform\nlower = -1\nupper = 3\nunit = N/m\nsource = illustrative\nnote = test\n"));
  const CliOutcome uniform =
      run_in(scratch.root, cli({"sample", "--line", "uniform.ini", "--samples", "100", "--seed", "1", "--out", "u.csv"}));
  CHECK_MESSAGE(uniform.exit_code == 0, uniform.err);
  CHECK(uniform.err.find("growthuq sample: warning: k: 25 % of the draws of its law uniform") != std::string::npos);
  CHECK(uniform.err.find("are <= 0, which no tube has: those samples are flagged and left out of the statistics") !=
        std::string::npos);
  spit(scratch.root / "empirical.ini",
       line_with("k", "[k]\nlaw = empirical\nvalues = -0.5, 1, 2, 3, 4\nunit = N/m\nsource = illustrative\nnote = test\n"));
  const CliOutcome empirical =
      run_in(scratch.root, cli({"sample", "--line", "empirical.ini", "--samples", "100", "--seed", "1", "--out", "e.csv"}));
  CHECK_MESSAGE(empirical.exit_code == 0, empirical.err);
  CHECK(empirical.err.find("growthuq sample: warning: k: ") != std::string::npos);
  CHECK(empirical.err.find("of the draws of its law empirical") != std::string::npos);
  // The shipped law draws nothing <= 0: no warning.
  const CliOutcome shipped = run_in(
      scratch.root, cli({"sample", "--line", source + "/distributions/wild_type.ini", "--samples", "100", "--seed", "1", "--out", "w.csv"}));
  CHECK_MESSAGE(shipped.exit_code == 0, shipped.err);
  CHECK(shipped.err.find("warning") == std::string::npos);

  // An einf fraction of 1.5.
  spit(scratch.root / "einf.csv", "tube,einf_frac\na,0.5\nb,0.6\nc,1.5\n");
  const CliOutcome fraction = run_in(scratch.root, cli({"fit", "einf.csv", "--column", "einf_frac"}));
  CHECK(fraction.exit_code == 2);
  CHECK(fraction.err == "growthuq fit: error: einf.csv:4: column einf_frac = '1.5': expected a rescaled equilibrium "
                        "modulus in [0, 1) (as a fraction; [0, 100) in %)\n");

  // A tube listed twice in a raw table.
  const fs::path raw = scratch.root / "raw";
  fs::copy(source + "/distributions/example_raw/wild_type", raw);
  const std::string indentation = slurp(raw / "indentation.csv");
  const std::size_t first_row = indentation.find("\nI01,") + 1;
  const std::string repeated = indentation.substr(first_row, indentation.find('\n', first_row) - first_row);
  spit(raw / "indentation.csv", indentation + repeated + "\n");
  const std::size_t lines = lines_in(indentation);
  const std::size_t first_line = lines_in(indentation.substr(0, first_row)) + 1;
  const CliOutcome twice = run_in(scratch.root, cli({"fit-line", "raw/raw.ini", "--out", "fitted.ini"}));
  CHECK(twice.exit_code == 2);
  CHECK(twice.err.find("raw/indentation.csv:" + std::to_string(lines + 1) + ": tube = 'I01': expected each tube once (it is "
                       "also raw/indentation.csv:" + std::to_string(first_line) + ")\n") != std::string::npos);
  CHECK(!fs::exists(scratch.root / "fitted.ini"));

  // Training rows of one probe radius: rho/d0 and a/d0 move together (collinear terms).
  const std::string training = slurp(source + "/src/correction/training.csv");
  REQUIRE(training.starts_with("index,p_MPa,E_MPa,h_nm,h0_nm,d0_um,rho_um,"));
  spit(scratch.root / "one_rho.csv", with_column(training, 6, "0.5"));
  fs::copy(source + "/src/correction/training_curves.csv", scratch.root / "one_rho_curves.csv");
  const CliOutcome collinear = run_in(scratch.root, cli({"fit-correction", "--training", "one_rho.csv", "--out", "c.inc"}));
  CHECK(collinear.exit_code == 2);
  CHECK(collinear.err.starts_with("growthuq fit-correction: error: one_rho.csv: "));
  CHECK(collinear.err.find("fitting rows whose groups are collinear") != std::string::npos);
  CHECK(!fs::exists(scratch.root / "c.inc"));
  // Too few rows: the message names the file.
  spit(scratch.root / "few.csv", training.substr(0, training.find("\n5,") + 1));
  const std::string curves = slurp(source + "/src/correction/training_curves.csv");
  spit(scratch.root / "few_curves.csv", curves.substr(0, curves.find("\n5,") + 1));
  const CliOutcome few = run_in(scratch.root, cli({"fit-correction", "--training", "few.csv", "--out", "c.inc"}));
  CHECK(few.exit_code == 2);
  CHECK(few.err.starts_with("growthuq fit-correction: error: few.csv: "));
  CHECK(few.err.find(" usable fitting rows: expected at least ") != std::string::npos);
}

TEST_CASE("a [shell_fe] key's error names the key's line") {
  const ScratchDirectory scratch("shell_fe_key_line");
  const std::string campaign = slurp(source + "/tests/campaign/data/fidelity_campaign.ini");
  const std::string edited = campaign.substr(0, campaign.find("mesh = coarse")) +
                             "mesh = coarse\ntube_length_um = 20\nprobe_distance_um = 30\n" +
                             campaign.substr(campaign.find("mesh = coarse") + 14);
  // Three folders deep beside a link to the distributions, as its relative paths expect.
  fs::create_directories(scratch.root / "a/b/c");
  fs::create_directory_symlink(source + "/distributions", scratch.root / "distributions");
  const fs::path file = scratch.root / "a/b/c/campaign.ini";
  spit(file, edited);
  const CliOutcome check = run_in(scratch.root, cli({"check", file.string(), "--out", "never"}));
  const std::size_t key_line = lines_in(edited.substr(0, edited.find("probe_distance_um"))) + 1;
  CHECK(check.exit_code == 2);
  CHECK(check.err.starts_with("growthuq check: error: " + file.string() + ":" + std::to_string(key_line) +
                              ": probe_distance_um = '30': expected"));
}

TEST_CASE("a mesh file beyond the generated meshes' 400 000 triangles is refused at once, naming it") {
  const ScratchDirectory scratch("mesh_cap");
  // Four vertices and 400 002 faces: refused by their count, before the surface is validated.
  std::string off = "OFF\n4 400002 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  for (int f = 0; f < 400002; ++f) off += "3 0 1 2\n";
  spit(scratch.root / "big.off", off);
  const auto start_time = std::chrono::steady_clock::now();
  const CliOutcome indent =
      run_in(scratch.root, cli({"indent", "--p-MPa", "0.3", "--E-MPa", "30", "--h-nm", "150", "--d0-um", "5", "--rho-um", "0.5", "--geometry", "file", "--mesh-file", "big.off", "--out", "c.csv", "--quiet"}));
  CHECK(indent.exit_code == 2);
  CHECK(indent.err == "growthuq indent: error: big.off: 400002 triangles: expected at most 400000 (the limit of a "
                      "generated mesh; it bounds time and memory): coarsen the surface\n");
  CHECK(seconds_since(start_time) < 20.0);
  CHECK(!fs::exists(scratch.root / "c.csv"));
}

TEST_CASE("a closed tetrahedron is refused naming its file and face: too coarse for the bending element") {
  // Every vertex of a tetrahedron is in three faces: each face's neighbours share their far vertex.
  const ScratchDirectory scratch("mesh_tetrahedron");
  spit(scratch.root / "tetra.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const CliOutcome indent = run_in(scratch.root, cli({"indent", "--p-MPa", "0.3", "--E-MPa", "30", "--h-nm", "150", "--d0-um",
                                                      "5", "--rho-um", "0.5", "--geometry", "file", "--mesh-file",
                                                      "tetra.off", "--out", "c.csv", "--quiet"}));
  CHECK(indent.exit_code == 2);
  CHECK(indent.err == "growthuq indent: error: tetra.off: face 0: two neighbouring faces share their far vertex 3: the "
                      "bending element needs six different vertices around each face (expected every vertex in at least "
                      "four faces; a tetrahedron has none)\n");
  CHECK(!fs::exists(scratch.root / "c.csv"));
}
