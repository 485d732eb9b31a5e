#include "growthuq/campaign/run_time_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/evaluation/evaluator.hpp"
#include "growthuq/fe/shell_fe_evaluator.hpp"
#include "growthuq/campaign/campaign_audit.hpp"

namespace growthuq {
namespace {

std::string duration(double seconds) {
  char text[64];
  if (seconds < 120) {
    std::snprintf(text, sizeof text, "%.0f s", seconds);
  } else if (seconds < 7200) {
    std::snprintf(text, sizeof text, "%.0f min", seconds / 60);
  } else if (seconds < 3 * 86400) {
    std::snprintf(text, sizeof text, "%.1f h", seconds / 3600);
  } else {
    std::snprintf(text, sizeof text, "%.1f days", seconds / 86400);
  }
  return text;
}

}  // namespace

std::optional<ShellFeTimeEstimate> estimate_shell_fe_time(const PreparedCampaign& prepared) {
  const Campaign& campaign = prepared.campaign();
  ShellFeTimeEstimate estimate;
  for (const PreparedLine& line : prepared.lines()) {
    if (!prepared.has_slow_samples(line)) continue;
    estimate.seconds_per_sample = std::max(estimate.seconds_per_sample, seconds_per_sample(line.plan));
    estimate.samples += campaign.samples;
    // Every replicate of the bootstrap runs every line's models again.
    estimate.bootstrap_samples += campaign.data_uncertainty.replicates * data_uncertainty_samples(campaign);
  }
  // The audit runs N samples of every line not at shell_fe, on the campaign's [shell_fe] mesh.
  estimate.audit_samples = audit_fe_samples(campaign);
  if (estimate.audit_samples > 0) {
    estimate.seconds_per_sample = std::max(estimate.seconds_per_sample, shell_fe_seconds_per_sample(campaign.shell_fe.mesh));
  }
  if (estimate.samples == 0 && estimate.audit_samples == 0) return std::nullopt;
  estimate.samples += estimate.bootstrap_samples + estimate.audit_samples;
  estimate.core_seconds = static_cast<double>(estimate.samples) * estimate.seconds_per_sample;
  return estimate;
}

std::string describe_shell_fe_time(const ShellFeTimeEstimate& estimate, int processes) {
  const int workers = processes < 1 ? 1 : processes;
  std::string text = "time: fidelity shell_fe, " + std::to_string(estimate.samples) + " finite-element samples x about " +
                     duration(estimate.seconds_per_sample) + " of one core each (the mesh level's mean as measured, stated model): about " +
                     duration(estimate.core_seconds / workers) + " with " + std::to_string(workers) +
                     (workers == 1 ? " process" : " processes");
  if (estimate.bootstrap_samples > 0) {
    text += "; " + std::to_string(estimate.bootstrap_samples) +
            " of the samples are the data-uncertainty bootstrap's ([data_uncertainty] replicates = 0 switches it off)";
  }
  if (estimate.audit_samples > 0) {
    text += "; " + std::to_string(estimate.audit_samples) + " of the samples are the audit's ([audit] samples = 0 switches it off)";
  }
  return text + "\n";
}

}  // namespace growthuq
