// How long a campaign's finite-element samples will take, said before the run starts (`growthuq
// check`, and `growthuq run` on stderr), so that a campaign that would take days says so first.
// The analytic fidelities take microseconds per sample and are not estimated here (`growthuq
// tradeoff` measures them); a slow line's models state their cost per sample
// (Evaluator::seconds_per_sample; for shell_fe, the mesh level's: shell_fe_evaluator.hpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "growthuq/campaign/campaign_run.hpp"

namespace growthuq {

struct ShellFeTimeEstimate {
  std::size_t samples = 0;            // finite-element samples: the run's and its bootstrap's
  std::size_t bootstrap_samples = 0;  // of which the data-uncertainty bootstrap's
  std::size_t audit_samples = 0;      // and the audit's of the fast lines ([audit], campaign_audit.hpp)
  double seconds_per_sample = 0.0;   // the slowest line's models'
  double core_seconds = 0.0;          // samples x seconds_per_sample
};

// Nothing when no line runs at fidelity shell_fe and there is no audit.
std::optional<ShellFeTimeEstimate> estimate_shell_fe_time(const PreparedCampaign& campaign);

// "fidelity shell_fe: 750 finite-element samples x about 60 s of one core: about 6.3 h with 2
// processes", plus the bootstrap's share and how to shorten it when it dominates.
std::string describe_shell_fe_time(const ShellFeTimeEstimate& estimate, int processes);

// The Shapley effects' model runs (line_shapley.cpp): one line per campaign, the runs per line
// and their ratio to the run's own samples, or nothing when the campaign does not ask for them.
std::string describe_shapley_cost(const PreparedCampaign& campaign);

}  // namespace growthuq
