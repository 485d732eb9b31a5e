// A campaign run with its outputs: the output directory (refused when it exists, unless
// forced), samples.csv and results.h5 written line by line as lines finish, summary.csv always,
// progress on stderr and the readable summary on stdout. What `growthuq run` does after
// validating the campaign.
#pragma once

#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_run.hpp"
#include "campaign/checkpoint.hpp"
#include "campaign/checkpoint_manifest.hpp"
#include "campaign/provenance.hpp"
#include "growthuq/campaign/run_campaign.hpp"
#include "growthuq/evaluation/line_result.hpp"
#include "growthuq/campaign/progress.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/pool/pool.hpp"

namespace growthuq {

// Whether finished chunks are kept on disk (checkpoint.hpp) so an interrupted run can resume.
enum class Checkpointing {
  off,     // nothing kept (--no-checkpoint)
  start,   // a new checkpoint in output_dir/checkpoint, with OutputSettings::manifest
  resume,  // continue the checkpoint of the interrupted run in output_dir (which exists)
};

class ResultsH5Writer;  // growthuq/io/results_h5.hpp

// Work a run does beside its lines (the audit of its fast fidelity, campaign_audit.hpp), kept in
// the run's checkpoint and committed with the run's results.
class RunAddition {
 public:
  virtual ~RunAddition() = default;
  // Of its chunks in the checkpoint (checkpoint/audit.bin).
  virtual ChunkShape chunk_shape() const = 0;
  // Every process, once the output directory is locked and the checkpoint started or resumed,
  // before the lines: the chunks `journal` holds are replayed, new ones recorded (null: no
  // checkpoint). PoolInterrupted when the pool is stopped.
  virtual void run(Pool& pool, ChunkJournal* journal) = 0;
  // Coordinator, while the results are staged: adds itself to the provenance, writes its files
  // into `staging` and results.h5 (null without hdf5); returns the text the report prints after
  // the summary table.
  virtual std::string write(RunProvenance& provenance, ResultsH5Writer* h5, const std::string& staging) const = 0;
};

struct OutputSettings {
  Overwrite overwrite = Overwrite::refuse;  // allow: reuse an existing output directory (--force)
  ProgressMode progress = ProgressMode::none;
  bool line_reports = true;                 // false: the report ends after the summary table and kappa (--summary-only)
  std::string command_line;                 // stored in results.h5 (when resuming: the original one)
  Checkpointing checkpointing = Checkpointing::off;
  CheckpointManifest manifest;              // with Checkpointing::start (the coordinator writes it)
  RunAddition* addition = nullptr;          // the audit, where the campaign asks for one
};

// The run stopped on a stop request (Pool::stop_when; Ctrl-C or SIGTERM in the CLI), raised on
// every process. No result file was written; with a checkpoint the output directory keeps every
// finished chunk. what() is the message for the user: "interrupted after N of M samples; finish
// with: growthuq run --resume DIR" (meaningful on the coordinator).
class RunInterrupted : public std::runtime_error {
 public:
  RunInterrupted(int reason, const std::string& message) : std::runtime_error(message), reason_(reason) {}
  int reason() const noexcept { return reason_; }  // PoolInterrupted::reason(): the signal

 private:
  int reason_;
};

struct CampaignOutcome {
  RunOutcome run;
  std::vector<QuantitySummary> summaries;  // rows of summary.csv (coordinator only)
};

// The names of the files a run writes in the output directory.
inline constexpr const char* samples_csv_name = "samples.csv";
inline constexpr const char* summary_csv_name = "summary.csv";
inline constexpr const char* results_h5_name = "results.h5";
inline constexpr const char* audit_csv_name = "audit.csv";
// The folder in the output directory where a run writes its results until all are complete.
inline constexpr const char* staging_name = "staging";

// check_output_directory: growthuq/campaign/run_campaign.hpp.

// Every process calls it. Rank 0 creates campaign.output_dir if needed, locks it for the whole
// run (output_lock.hpp: a second live run is refused naming this one) and checks it before any
// sampling (InputError naming it when it exists and overwrite is refuse), streams the lines
// into output_dir/staging, writes `report` (stdout) and `log` (stderr: progress, design
// warnings). Only when every result file is complete in staging are the old results removed and
// the new ones moved in (summary.csv last; result files of formats not written this time are
// removed too), so the folder never mixes two runs. When the run fails (e.g. kappa cannot be
// calibrated because no reference tube grows), the .partial files and staging are removed and
// so is the output directory if this run created it (a new checkpoint too; a resumed one
// stays); a WriteError (a full disk) keeps the checkpoint either way, its message saying how to
// finish. When the pool is stopped, also during the final writes, nothing is committed, the
// output directory and its checkpoint are kept, and RunInterrupted raised. A checkpoint is
// removed when the run completes.
CampaignOutcome run_campaign_with_outputs(const PreparedCampaign& campaign, Pool& pool, const OutputSettings& settings,
                                          std::ostream& report, std::ostream& log);

}  // namespace growthuq
