// Launcher detection, and the pool a process gets from it.
#include "growthuq/pool/launch.hpp"

#include <climits>
#include <cstdlib>

#include "growthuq/core/numbers.hpp"
#include "growthuq/pool/pool.hpp"

namespace growthuq {
namespace {

// Reads variables and keeps "NAME=value" of each one found, for messages.
class RecordedEnvironment {
 public:
  explicit RecordedEnvironment(const EnvironmentLookup& environment) : environment_(environment) {}

  bool has(const char* name) const { return environment_(name) != nullptr; }

  // The variable as a whole number >= minimum, or `fallback` when it is not set.
  int count(const char* name, int minimum, int fallback) {
    const char* value = environment_(name);
    if (value == nullptr) return fallback;
    evidence_ += (evidence_.empty() ? "" : ", ") + std::string(name) + "=" + value;
    return static_cast<int>(parse_count(value, "environment", name, static_cast<std::uint64_t>(minimum), INT_MAX));
  }

  std::string evidence() const { return evidence_; }

 private:
  const EnvironmentLookup& environment_;
  std::string evidence_;
};

std::string plural(int count, const char* noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "es");
}

}  // namespace

Launch detect_launch(const EnvironmentLookup& environment) {
  RecordedEnvironment variables(environment);
  Launch launch;
  // The size and this process's rank, from the launcher closest to the process: mpirun inside
  // a Slurm allocation leaves the allocation's (and, across nodes, its daemons' step's) Slurm
  // variables in the environment, but the world is mpirun's.
  if (variables.has("OMPI_COMM_WORLD_SIZE")) {
    launch.launcher = "mpirun";
    launch.processes = variables.count("OMPI_COMM_WORLD_SIZE", 1, 1);
    launch.rank = variables.count("OMPI_COMM_WORLD_RANK", 0, 0);
  } else if (variables.has("PMI_SIZE") || variables.has("PMI_RANK")) {
    launch.launcher = variables.has("SLURM_STEP_NUM_TASKS") ? "srun" : "PMI";
    launch.processes = variables.count("PMI_SIZE", 1, 1);
    launch.rank = variables.count("PMI_RANK", 0, 0);
  } else if (variables.has("SLURM_STEP_NUM_TASKS")) {
    // srun sets the step's variables in each task; a batch script has only SLURM_NTASKS (the
    // allocation's tasks), and a command it runs directly is one process, not a launch.
    launch.launcher = "srun";
    launch.processes = variables.count("SLURM_STEP_NUM_TASKS", 1, 1);
    launch.rank = variables.count("SLURM_PROCID", 0, 0);
  }
  launch.mpi_interface = variables.has("OMPI_COMM_WORLD_SIZE") || variables.has("PMI_SIZE") ||
                         variables.has("PMI_RANK") || variables.has("PMIX_RANK");
  if (variables.has("PMIX_RANK")) {
    const int pmix_rank = variables.count("PMIX_RANK", 0, 0);
    if (launch.launcher.empty()) {
      launch.launcher = "PMIx";
      launch.rank = pmix_rank;
    }
  }
  launch.evidence = variables.evidence();
  return launch;
}

UnjoinableLaunch::UnjoinableLaunch(const Launch& launch, const std::string& problem)
    : InputError(launch.launcher,
                 "process " + std::to_string(launch.rank + 1) + " of " + std::to_string(launch.processes) + " (" +
                     launch.evidence + ") cannot join the other processes: " + problem +
                     "; it stops rather than write the results alone. Start growthuq with `srun --mpi=pmix` "
                     "(Debian's Open MPI joins a Slurm step through PMIx only) or with mpirun inside the "
                     "allocation"),
      launcher_rank_(launch.rank) {}

void require_mpi_interface(const Launch& launch) {
  if (launch.uses_mpi() && !launch.mpi_interface) {
    throw UnjoinableLaunch(launch, "no MPI process-management interface reached it (none of PMIX_RANK, PMI_RANK, "
                                   "OMPI_COMM_WORLD_SIZE is set: srun --mpi=none?)");
  }
}

void require_whole_world(const Launch& launch, int world_size) {
  if (world_size < launch.processes) {
    throw UnjoinableLaunch(launch, "its MPI world has " + plural(world_size, "process") +
                                       " (MPI did not reach the launcher's other processes)");
  }
}

namespace {

Launch this_process_launch() {
  return detect_launch([](const char* name) -> const char* { return std::getenv(name); });
}

}  // namespace

bool launched_by_mpi() { return this_process_launch().uses_mpi(); }

std::unique_ptr<Pool> make_pool() {
  const Launch launch = this_process_launch();
  if (!launch.uses_mpi()) return make_serial_pool();
  require_mpi_interface(launch);
  std::unique_ptr<Pool> pool = make_mpi_pool();
  require_whole_world(launch, pool->size());
  return pool;
}

}  // namespace growthuq
