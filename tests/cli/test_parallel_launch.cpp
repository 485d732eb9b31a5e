// `growthuq run` started as one of several srun tasks that MPI cannot join (srun --mpi=none: the
// environment of a Slurm step, without PMIx or PMI) stops before writing anything: the first
// task with one message, the others silently, all with exit code 2. Before, each task ran the
// whole campaign serially into the same output directory. (The real Slurm: tests/slurm.)
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"

using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> srun_task(int procid) {
  return {"SLURM_NTASKS=2", "SLURM_PROCID=" + std::to_string(procid), "SLURM_STEP_ID=0", "SLURM_STEP_NUM_TASKS=2"};
}

const std::string campaign = std::string(GROWTHUQ_SOURCE_DIR) + "/tests/campaign/data/small_campaign.ini";

}  // namespace

TEST_CASE("growthuq run as an srun task MPI cannot join stops with one message and writes nothing") {
  const ScratchDirectory scratch("cli_unjoinable_launch");
  const std::vector<std::string> command = cli({"run", campaign, "--quiet", "--out", (scratch.root / "out").string()});

  const CliOutcome first = run_in(scratch.root, command, srun_task(0));
  CHECK(first.exit_code == 2);
  CHECK(first.out.empty());
  CHECK(first.err ==
        "growthuq run: error: srun: process 1 of 2 (SLURM_STEP_NUM_TASKS=2, SLURM_PROCID=0) cannot join the other "
        "processes: no MPI process-management interface reached it (none of PMIX_RANK, PMI_RANK, "
        "OMPI_COMM_WORLD_SIZE is set: srun --mpi=none?); it stops rather than write the results alone. Start "
        "growthuq with `srun --mpi=pmix` (Debian's Open MPI joins a Slurm step through PMIx only) or with mpirun "
        "inside the allocation\n");
  CHECK_FALSE(fs::exists(scratch.root / "out"));

  const CliOutcome second = run_in(scratch.root, command, srun_task(1));
  CHECK(second.exit_code == 2);
  CHECK(second.out.empty());
  CHECK(second.err.empty());
  CHECK_FALSE(fs::exists(scratch.root / "out"));
}

TEST_CASE("growthuq run in a batch script's own environment (the allocation's SLURM_NTASKS) runs serially") {
  const ScratchDirectory scratch("cli_batch_script_launch");
  const CliOutcome outcome =
      run_in(scratch.root, cli({"run", campaign, "--quiet", "--samples", "20", "--out", (scratch.root / "out").string()}),
             {"SLURM_NTASKS=2", "SLURM_NPROCS=2", "SLURM_PROCID=0", "SLURM_JOB_ID=7"});
  CHECK(outcome.exit_code == 0);
  CHECK(fs::exists(scratch.root / "out" / "summary.csv"));
}
