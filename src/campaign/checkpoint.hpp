// The checkpoint of a run, in DIR/checkpoint/ (issue 4, "Long runs"): manifest.txt
// (checkpoint_manifest.hpp), chunks.bin (chunk_log.hpp) and, for a campaign with an audit, the
// audit's finite-element chunks in audit.bin (a chunk log of the same layout). While a run proceeds the coordinator
// appends every finished chunk; `growthuq run --resume DIR` replays the chunks held and evaluates
// only the others. A chunk's values depend only on its range (pool.hpp), so the resumed result is
// the uninterrupted one bit for bit, whatever the number of processes before and after. The
// checkpoint is removed when the run completes.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_run.hpp"
#include "campaign/checkpoint_manifest.hpp"
#include "campaign/chunk_log.hpp"
#include "growthuq/pool/pool.hpp"

namespace growthuq {

std::string checkpoint_directory(const std::string& output_dir);
std::string checkpoint_manifest_path(const std::string& output_dir);
std::string checkpoint_chunk_log_path(const std::string& output_dir);
std::string checkpoint_audit_log_path(const std::string& output_dir);

// True when `output_dir` holds a checkpoint (an interrupted run).
bool has_checkpoint(const std::string& output_dir);

// The manifest text of the checkpoint in `output_dir`. InputError naming the directory when it
// does not exist or holds no checkpoint (a completed run has none).
std::string read_checkpoint_manifest_text(const std::string& output_dir);

// What the chunks of a log must look like: a record that does not fit is a damaged checkpoint.
struct ChunkShape {
  std::size_t samples = 0;               // per line
  std::vector<std::size_t> chunk_sizes;  // per line: every chunk but a line's last has this size
  std::size_t values_per_sample = 0;     // ChunkValues::values_per_sample
};

class RunCheckpoint final : public ChunkJournal {
 public:
  // A new run (every process calls it at the same point): the coordinator replaces any
  // checkpoint in the campaign's output directory by one holding `manifest` and no chunk.
  // InputError on every process when it cannot be written.
  static std::unique_ptr<RunCheckpoint> start(Pool& pool, const PreparedCampaign& campaign,
                                              const CheckpointManifest& manifest);

  // Continues the checkpoint in the campaign's output directory (every process calls it): the
  // coordinator scans the chunk log, cuts a torn tail, and tells every process which chunks it
  // holds. InputError on every process when a record does not fit the campaign (a damaged
  // checkpoint) or the log cannot be read.
  static std::unique_ptr<RunCheckpoint> resume(Pool& pool, const PreparedCampaign& campaign);

  // The audit's chunks (campaign_audit.hpp) in audit.bin, their lines the audited ones
  // (`shape`). Every process calls it after start() or resume(): resuming, the log is continued
  // as resume() continues chunks.bin; a new run, or one stopped before the log was made, starts
  // it empty. Its remove() is the run's: the whole checkpoint goes.
  static std::unique_ptr<RunCheckpoint> open_audit(Pool& pool, const std::string& output_dir, const ChunkShape& shape,
                                                   bool resuming);

  bool holds(std::size_t line, ChunkRange range) const override;
  void replay(std::size_t line, const ChunkSink& sink) override;
  void record(std::size_t line, ChunkRange range, std::span<const double> values) override;

  // Coordinator: samples the checkpoint holds (earlier runs' and this run's).
  std::size_t samples_held() const noexcept { return samples_held_; }

  // Coordinator: deletes the checkpoint (the run completed, or failed in a way a resume would
  // repeat). Nothing is recorded afterwards.
  void remove();

 private:
  RunCheckpoint(std::string output_dir, std::string log_path, std::size_t lines);

  // Coordinator: scans the log, keeps the records that fit `shape`, opens it for appending;
  // returns the chunks held, encoded for share_held.
  std::string continue_log(const ChunkShape& shape);
  // Every process: the chunks the coordinator holds.
  void share_held(Pool& pool, std::string held);

  std::string output_dir_;
  std::string log_path_;
  std::vector<std::vector<ChunkRecord>> held_;  // per line, by range.begin
  std::optional<ChunkLogWriter> writer_;        // coordinator only
  std::optional<ChunkLogReader> reader_;        // coordinator only, when resuming
  std::size_t samples_held_ = 0;
};

}  // namespace growthuq
