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
// inflations) at a mesh level, measured on this project's 2-core machine (2026-12-05), means
// with the failed samples in (a campaign's time is the sum, and a sample that does not converge
// costs several that do): coarse 8.9 s per sample over the first 270 samples of
// campaigns/published_scale.ini (wild type and xxt1_xxt2, one process alone), rounded to 9;
// default 54 s per forward curve, the mean over the 245 training tubes of
// src/correction/training.csv, plus the inflations, 55; fine four times that (src/fe/README.md,
// "Speed": 575 s against 149 s at the test tube); finer, not measured over a campaign, fine's
// time times 2.9, the median ratio of the finer to the fine curve over the five points of
// `tools/bench/fe-mesh-convergence --finer` (2.0 to 3.9). A campaign's own tubes may differ by a
// factor of two either way.
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
