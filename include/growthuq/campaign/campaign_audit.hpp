// The audit of a campaign's fast fidelity ([audit] samples = N, campaigns/README.md "Audit"):
// before the run's lines, the first N samples of each line on closed_form or corrected also run
// through shell_fe (the campaign's [shell_fe] options), kept in the run's checkpoint and
// committed with its results (src/campaign/audit_addition.hpp); per line and output, the fast
// fidelity's bias (mean of shell_fe - fast) and the multifidelity estimates of the finite
// elements' mean and median (stats/multifidelity.hpp) from the N pairs and the fast fidelity's
// M samples.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/campaign/prepared_campaign.hpp"
#include "growthuq/pool/pool.hpp"
#include "growthuq/stats/multifidelity.hpp"

namespace growthuq {

// One line and output of the audit.
struct AuditRow {
  std::string line;
  std::string fidelity;  // the line's fast fidelity
  std::string quantity;
  std::string unit;      // the quantity's default unit, that of every value below
  std::size_t audit_samples = 0;  // N: the first N samples, run through shell_fe too
  std::size_t pairs = 0;          // of those, the samples both models gave a value for
  std::size_t fast_samples = 0;   // of all M samples, those the fast fidelity gave a value for
  double fast_mean = 0;           // the fast fidelity's, over its fast_samples
  std::optional<MultifidelityEstimate> estimate;  // none with fewer than 3 pairs
};

// The lines an audit covers: those whose fidelity is not shell_fe, in run order (indices into
// PreparedCampaign::lines()); empty when the campaign has no audit.
std::vector<std::size_t> audited_lines(const PreparedCampaign& campaign);

// Finite-element samples the audit adds to the run: N per line not at shell_fe.
std::size_t audit_fe_samples(const Campaign& campaign);

// The audit's two models of every line: the campaign with its computed outputs (and E, so
// that both fidelities read the same variables and share one design) at each line's own
// fidelity, and with the audited lines at shell_fe. Built on every process alike.
class CampaignAudit {
 public:
  // InputError at the campaign file's [audit] line: N above the campaign's samples, every line
  // at fidelity shell_fe, or a line whose variables shell_fe cannot run on (no h).
  CampaignAudit(const PreparedCampaign& campaign, Pool& pool);
  ~CampaignAudit();
  CampaignAudit(const CampaignAudit&) = delete;
  CampaignAudit& operator=(const CampaignAudit&) = delete;

  // All processes; the rows on the coordinator (empty elsewhere). The finite-element samples go
  // through `pool` in [shell_fe] chunk_size chunks; with a `journal` (the checkpoint's; its
  // lines are the audited lines' positions in audited_lines()), the chunks it holds are
  // replayed and the others recorded, so a resumed audit redoes no finished sample and gives
  // the uninterrupted one's rows bit for bit. A line's start is said on `log`, when given.
  // PoolInterrupted when the pool is stopped.
  std::vector<AuditRow> run(Pool& pool, std::ostream* log, ChunkJournal* journal = nullptr) const;
  const PreparedCampaign& campaign() const noexcept { return campaign_; }
  // The outputs each finite-element sample computes (the values of a journal's chunks).
  const std::vector<std::string>& computed_outputs() const;

 private:
  const PreparedCampaign& campaign_;
  std::unique_ptr<PreparedCampaign> fast_, fe_;
  std::vector<std::size_t> lines_;
  std::vector<std::string> quantities_;  // audited: the campaign's computed outputs but v
};

// The rows as a table for the run's report (after its summary table): per line and output the
// fast fidelity's mean, its bias with the 95 % interval, and shell_fe's mean and median.
std::string audit_table(const std::vector<AuditRow>& rows, const Campaign& campaign);

// audit.csv: one row per line and output, every estimate with its standard error and 95 %
// interval (columns in campaigns/README.md "Audit"); the same table as /audit in results.h5.
std::string audit_csv(const std::vector<AuditRow>& rows);

}  // namespace growthuq
