// The audit (campaign_audit.hpp) as a part of its run (campaign_outputs.hpp, RunAddition): its
// finite-element chunks kept in the run's checkpoint (checkpoint/audit.bin), so an interrupted
// audit resumes where it stopped; its results committed with the run's: audit.csv, results.h5
// /audit, the measured bias in provenance.json and results.h5 /provenance/audit, and its table in
// the report.
#pragma once

#include <memory>
#include <ostream>

#include "campaign/campaign_outputs.hpp"
#include "growthuq/campaign/campaign_audit.hpp"
#include "growthuq/campaign/progress_mode.hpp"

namespace growthuq {

// `audit` and `log` must outlive the run; a line's start is said on `log` unless `progress` is none.
std::unique_ptr<RunAddition> audit_addition(const CampaignAudit& audit, ProgressMode progress, std::ostream& log);

}  // namespace growthuq
