// Launcher detection on the environments the launchers really set (captured from Debian 12's
// Slurm 22.05 and Open MPI 4.1 on one node, tests/slurm/slurm_campaign.sh), and the stop of a
// process that was started in parallel but cannot join the others.
#include <doctest/doctest.h>

#include <map>
#include <string>

#include "growthuq/pool/launch.hpp"

using namespace growthuq;

namespace {

using Environment = std::map<std::string, std::string>;

Launch detect(const Environment& environment) {
  return detect_launch([&](const char* name) -> const char* {
    const auto found = environment.find(name);
    return found == environment.end() ? nullptr : found->second.c_str();
  });
}

// What every task of `srun -n 2` in a 2-task allocation has, whatever --mpi says.
Environment srun_task(int procid) {
  return {{"SLURM_NTASKS", "2"},         {"SLURM_NPROCS", "2"},         {"SLURM_PROCID", std::to_string(procid)},
          {"SLURM_STEP_ID", "0"},        {"SLURM_STEPID", "0"},         {"SLURM_STEP_NUM_TASKS", "2"},
          {"SLURM_STEP_NUM_NODES", "1"}, {"SLURM_TASKS_PER_NODE", "2"}, {"SLURM_STEP_TASKS_PER_NODE", "2"}};
}

std::string unjoinable_message(const Launch& launch, int world_size) {
  try {
    require_mpi_interface(launch);
    require_whole_world(launch, world_size);
  } catch (const UnjoinableLaunch& error) {
    CHECK(error.launcher_rank() == launch.rank);
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a process started alone, or by a batch script directly, is not a parallel launch") {
  CHECK_FALSE(detect({}).uses_mpi());
  CHECK(detect({}).launcher.empty());
  // sbatch --ntasks=2: the script sees the allocation's tasks, but it is one process.
  const Launch batch = detect({{"SLURM_NTASKS", "2"}, {"SLURM_NPROCS", "2"}, {"SLURM_PROCID", "0"},
                               {"SLURM_TASKS_PER_NODE", "2"}, {"SLURM_JOB_ID", "7"}});
  CHECK_FALSE(batch.uses_mpi());
  CHECK(batch.processes == 1);
  // srun -n 1: a step of one task.
  Environment single = srun_task(0);
  single["SLURM_STEP_NUM_TASKS"] = "1";
  CHECK_FALSE(detect(single).uses_mpi());
  CHECK(unjoinable_message(detect(single), 1).empty());
}

TEST_CASE("mpirun, also inside a Slurm allocation, is recognised by Open MPI's variables") {
  Environment environment = {{"OMPI_COMM_WORLD_SIZE", "2"}, {"OMPI_COMM_WORLD_RANK", "1"}, {"PMIX_RANK", "1"},
                             {"SLURM_NTASKS", "2"},         {"SLURM_PROCID", "0"}};
  const Launch launch = detect(environment);
  CHECK(launch.launcher == "mpirun");
  CHECK(launch.processes == 2);
  CHECK(launch.rank == 1);
  CHECK(launch.mpi_interface);
  CHECK(launch.uses_mpi());
  CHECK(unjoinable_message(launch, 2).empty());
  // mpirun -np 1 is an MPI pool of one process (as before).
  const Launch one = detect({{"OMPI_COMM_WORLD_SIZE", "1"}, {"OMPI_COMM_WORLD_RANK", "0"}});
  CHECK(one.uses_mpi());
  CHECK(unjoinable_message(one, 1).empty());
}

TEST_CASE("srun --mpi=pmix is a parallel launch MPI can join; a world smaller than the step is refused") {
  Environment environment = srun_task(1);
  environment["PMIX_RANK"] = "1";
  const Launch launch = detect(environment);
  CHECK(launch.launcher == "srun");
  CHECK(launch.processes == 2);
  CHECK(launch.rank == 1);
  CHECK(launch.mpi_interface);
  CHECK(unjoinable_message(launch, 2).empty());
  CHECK(unjoinable_message(launch, 1) ==
        "srun: process 2 of 2 (SLURM_STEP_NUM_TASKS=2, SLURM_PROCID=1, PMIX_RANK=1) cannot join the other "
        "processes: its MPI world has 1 process (MPI did not reach the launcher's other processes); it stops "
        "rather than write the results alone. Start growthuq with `srun --mpi=pmix` (Debian's Open MPI joins a "
        "Slurm step through PMIx only) or with mpirun inside the allocation");
}

TEST_CASE("srun --mpi=pmi2 is recognised by PMI_SIZE and PMI_RANK; a world smaller than PMI_SIZE is refused") {
  Environment environment = srun_task(0);
  environment.insert({{"PMI_FD", "11"}, {"PMI_JOBID", "1.1"}, {"PMI_RANK", "0"}, {"PMI_SIZE", "2"}});
  const Launch launch = detect(environment);
  CHECK(launch.launcher == "srun");
  CHECK(launch.processes == 2);
  CHECK(launch.rank == 0);
  CHECK(launch.mpi_interface);
  CHECK(unjoinable_message(launch, 2).empty());
  CHECK(unjoinable_message(launch, 1).find("srun: process 1 of 2 (PMI_SIZE=2, PMI_RANK=0) cannot join") == 0);
  // MPICH's mpiexec sets the same variables without Slurm's.
  const Launch hydra = detect({{"PMI_RANK", "3"}, {"PMI_SIZE", "4"}});
  CHECK(hydra.launcher == "PMI");
  CHECK(hydra.processes == 4);
  CHECK(hydra.rank == 3);
}

TEST_CASE("srun --mpi=none is a parallel launch no MPI can join: every task stops before MPI starts") {
  for (const int procid : {0, 1}) {
    const Launch launch = detect(srun_task(procid));
    CHECK(launch.launcher == "srun");
    CHECK(launch.processes == 2);
    CHECK(launch.rank == procid);
    CHECK_FALSE(launch.mpi_interface);
    CHECK(launch.uses_mpi());
    CHECK_THROWS_AS(require_mpi_interface(launch), UnjoinableLaunch);
    CHECK(unjoinable_message(launch, 2) ==
          "srun: process " + std::to_string(procid + 1) + " of 2 (SLURM_STEP_NUM_TASKS=2, SLURM_PROCID=" +
              std::to_string(procid) +
              ") cannot join the other processes: no MPI process-management interface reached it (none of "
              "PMIX_RANK, PMI_RANK, OMPI_COMM_WORLD_SIZE is set: srun --mpi=none?); it stops rather than write "
              "the results alone. Start growthuq with `srun --mpi=pmix` (Debian's Open MPI joins a Slurm step "
              "through PMIx only) or with mpirun inside the allocation");
  }
}

TEST_CASE("a PMIx launcher without a size is an MPI launch of its own world") {
  const Launch launch = detect({{"PMIX_RANK", "0"}});
  CHECK(launch.launcher == "PMIx");
  CHECK(launch.mpi_interface);
  CHECK(launch.processes == 1);
  CHECK(unjoinable_message(launch, 1).empty());
}

TEST_CASE("a launcher variable that is not a count is an error naming it") {
  Environment environment = srun_task(0);
  environment["SLURM_STEP_NUM_TASKS"] = "two";
  CHECK_THROWS_WITH_AS(detect(environment),
                       "environment: SLURM_STEP_NUM_TASKS = 'two': expected a whole number from 1 to 2147483647",
                       InputError);
  CHECK_THROWS_WITH_AS(detect({{"PMI_SIZE", "0"}, {"PMI_RANK", "0"}}),
                       "environment: PMI_SIZE = '0': expected a whole number from 1 to 2147483647", InputError);
  CHECK_THROWS_WITH_AS(detect({{"OMPI_COMM_WORLD_SIZE", "2"}, {"OMPI_COMM_WORLD_RANK", "-1"}}),
                       "environment: OMPI_COMM_WORLD_RANK = '-1': expected a whole number from 0 to 2147483647",
                       InputError);
}
