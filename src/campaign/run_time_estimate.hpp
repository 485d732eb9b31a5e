// How long a campaign's finite-element samples will take, said before the run starts (`growthuq
// check`, and `growthuq run` on stderr), so that a campaign that would take days says so first.
// The analytic fidelities take microseconds per sample and are not estimated here (`growthuq
// tradeoff` measures them); a shell_fe sample is one finite-element inverse, whose time
// depends mostly on the mesh level: the stated model below, measured on this project's
// 2-core machine.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "growthuq/campaign/campaign_run.hpp"

namespace growthuq {

// Seconds of one core per shell_fe sample (one inverse: one force curve and up to six
// inflations) at a mesh level, on this project's 2-core machine (2026-12-05), means with the
// failed samples in (a campaign's time is the sum, and a sample that does not converge costs
// several that do). Measured over campaigns with the penalty contact: coarse 8.9 s per sample
// over the first 270 samples of campaigns/published_scale.ini; default 55 s over the 245
// training tubes of src/correction/training.csv. The exact contact (the default now) was
// measured side by side with the penalty on one tube by tools/bench/bench-fe-contact: its
// inverse 2.5 times faster on the coarse mesh and 4.6 times on the default, so coarse
// 8.9 / 2.5 = 3.6 s and default 55 / 4.6 = 12 s, until a campaign measures them. Fine and finer
// keep the penalty's figures (fine four times default's 55 s; finer fine's times 2.9, the median
// ratio over the five points of `tools/bench/fe-mesh-convergence --finer`): at the thick wall of
// the convergence test the exact contact is no faster there. A campaign's own tubes may differ
// by a factor of two either way.
double shell_fe_seconds_per_sample(ShellFeMesh mesh);

struct ShellFeTimeEstimate {
  std::size_t samples = 0;            // finite-element samples: the run's and its bootstrap's
  std::size_t bootstrap_samples = 0;  // of which the data-uncertainty bootstrap's
  double seconds_per_sample = 0.0;
  double core_seconds = 0.0;          // samples x seconds_per_sample
};

// Nothing when no line runs at fidelity shell_fe.
std::optional<ShellFeTimeEstimate> estimate_shell_fe_time(const PreparedCampaign& campaign);

// "fidelity shell_fe: 750 finite-element samples x about 60 s of one core: about 6.3 h with 2
// processes", plus the bootstrap's share and how to shorten it when it dominates.
std::string describe_shell_fe_time(const ShellFeTimeEstimate& estimate, int processes);

}  // namespace growthuq
