// How this process was started: alone, by mpirun, or as one task of a Slurm step (srun), read
// from the environment the launchers set. It decides which pool the process gets, and stops a
// process that was started in parallel but cannot join the others (srun without a process
// management interface that Open MPI understands) before it writes the results alone into the
// output directory the other processes write to as well.
#pragma once

#include <functional>
#include <string>

#include "growthuq/core/error.hpp"

namespace growthuq {

// Reads one environment variable: its value, or nullptr when it is not set (std::getenv).
using EnvironmentLookup = std::function<const char*(const char* name)>;

struct Launch {
  // Who started the process ("" when nothing says it runs in parallel): "mpirun", "srun" or
  // "PMI" (a PMI/PMI2 launcher such as srun --mpi=pmi2 or MPICH's mpiexec).
  std::string launcher;
  // The variables it was recognised by, "NAME=value, ...", for messages.
  std::string evidence;
  // How many processes the launcher started, and this one's number among them (from 0).
  int processes = 1;
  int rank = 0;
  // An interface MPI_Init can join the others through is present: Open MPI's own
  // (OMPI_COMM_WORLD_SIZE), PMIx (PMIX_RANK) or PMI (PMI_RANK/PMI_SIZE).
  bool mpi_interface = false;

  // The process belongs to a parallel launch, so it must use the MPI pool (or stop).
  bool uses_mpi() const { return mpi_interface || processes > 1; }
};

// What `environment` says. Priority: mpirun's OMPI_COMM_WORLD_SIZE/RANK, then PMI_SIZE/RANK,
// then a Slurm step's SLURM_STEP_NUM_TASKS and SLURM_PROCID (set by srun for each task; a batch
// script's own SLURM_NTASKS is the allocation, not a launch, and does not count); PMIX_RANK
// alone marks an MPI launch of unknown size. A count that is not a whole number >= 1 is an
// InputError naming the variable.
Launch detect_launch(const EnvironmentLookup& environment);

// A process started in parallel that cannot join the others. Thrown on every such process;
// `launcher_rank` lets all but the first stay silent, so the job log shows the message once.
class UnjoinableLaunch : public InputError {
 public:
  UnjoinableLaunch(const Launch& launch, const std::string& problem);
  int launcher_rank() const noexcept { return launcher_rank_; }

 private:
  int launcher_rank_;
};

// Throws UnjoinableLaunch when `launch` is parallel but no MPI interface reached the process
// (srun --mpi=none, or a Slurm without MPI plugins): MPI_Init would start a world of one.
void require_mpi_interface(const Launch& launch);

// Throws UnjoinableLaunch when the MPI world has fewer processes than the launcher started (an
// MPI that fell back to a world of its own). Debian's Open MPI under an interface it does not
// speak (srun --mpi=pmi2) does not get this far: its MPI_Init stops the process itself.
void require_whole_world(const Launch& launch, int world_size);

}  // namespace growthuq
