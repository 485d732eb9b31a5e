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
// inflations) at a mesh level, measured on this project's 2-core machine (2026-12-05): coarse
// 2.6-3.2 s per sample over the five Arabidopsis lines (tools/bench/bench-fe-campaign, failed
// samples included), rounded up to 4; default 32 s per forward curve, the median over the 86
// training tubes of src/correction/training.csv, plus the inflations, 40; fine four times that
// (src/fe/README.md, "Speed": 575 s against 149 s at the test tube).
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
