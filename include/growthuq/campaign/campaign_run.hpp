// The run of a campaign over its plant lines, all processes taking part. Per line: its design
// is made whole by one process, one line ahead of the run (which one: line_schedule.hpp) and
// shared to every process; its samples are evaluated through the Pool in chunks (or replayed
// from a checkpoint), v scaled by kappa, which the reference line calibrates (kappa.hpp, Eq.
// (G5) of src/growth/README.md); the evaluated outputs go to every process, which compute the
// statistics (summaries, ranks, correlation matrices, principal components) column by column;
// the coordinating process gathers them, assembles the line (LineResult, LineStatistics) and
// hands it to an observer, which writes it, while the next line is being designed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/prepared_campaign.hpp"
#include "growthuq/evaluation/line_result.hpp"
#include "growthuq/campaign/progress_mode.hpp"
#include "growthuq/correlation/matrix_file.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/evaluation/evaluator.hpp"
#include "growthuq/growth/kappa.hpp"
#include "growthuq/pool/pool.hpp"
#include "growthuq/rawdata/raw_line_fit.hpp"
#include "growthuq/sampling/line_design.hpp"
#include "growthuq/stats/line_analysis.hpp"

namespace growthuq {

// A finished line's statistics: the rows of summary.csv (one per campaign output the line has,
// in the campaign's order) and the analyses (input x output rank correlation, PCA).
struct LineStatistics {
  std::vector<QuantitySummary> summaries;
  LineAnalysis analysis;
};

// The statistics of `result` computed by this process alone (the same numbers the run computes
// with all processes): summarize_quantity of each of `outputs` the result has, and analyze_line.
LineStatistics line_statistics(const LineResult& result, const std::vector<std::string>& outputs);

// Receives the run's events on the coordinating process.
class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void line_started(const PreparedLine& line, std::size_t samples) = 0;
  virtual void chunk_done(ChunkRange range) = 0;
  // A chunk a resumed run found in its checkpoint (no work done now): by default as chunk_done.
  virtual void chunk_replayed(ChunkRange range) { chunk_done(range); }
  // The finished line, v already scaled by the campaign's kappa; `warnings` from its design.
  virtual void line_done(const LineResult& result, const std::vector<std::string>& warnings) = 0;
  // What the run calls: the finished line with its statistics, which all processes computed
  // together; the observer may keep both (move from them). By default: line_done(result,
  // warnings).
  virtual void line_analyzed(LineResult&& result, LineStatistics&& statistics, const std::vector<std::string>& warnings) {
    (void)statistics;
    line_done(result, warnings);
  }
};

// Wall time this process spent in each part of a run, in seconds (growthuq run prints them when
// the environment variable GROWTHUQ_TIMINGS is set).
struct RunTimings {
  double design = 0;      // building the designs this process makes, and receiving the others
  double evaluation = 0;  // the models, in chunks through the pool
  double sharing = 0;     // sending the evaluated outputs to every process
  double statistics = 0;  // summaries, ranks and correlation matrices
  double observer = 0;    // the observer's line_analyzed (writing, on the coordinator)
};

// Keeps finished chunks beyond the process (checkpoint.hpp): a chunk the journal holds is not
// evaluated again but replayed into the sink, and every chunk evaluated is recorded before it
// is sunk. Lines are numbered in run order (PreparedCampaign::lines()); values are the chunk's
// raw values as evaluate_chunk returns them (before kappa).
class ChunkJournal {
 public:
  virtual ~ChunkJournal() = default;
  // Every process, with the same answer everywhere: whether the journal holds the chunk.
  virtual bool holds(std::size_t line, ChunkRange range) const = 0;
  // Coordinator: feeds every chunk of `line` the journal holds to `sink`.
  virtual void replay(std::size_t line, const ChunkSink& sink) = 0;
  // Coordinator: keeps a chunk just evaluated.
  virtual void record(std::size_t line, ChunkRange range, std::span<const double> values) = 0;
};

// Pool::run over the `count` samples of the journal's `line` (every process calls it): the
// chunks `journal` holds are fed to `replayed` on the coordinator first (a read error raised on
// every process), the others evaluated by `work`, recorded and fed to `sink`. Without a journal,
// Pool::run itself.
void run_with_journal(Pool& pool, ChunkJournal* journal, std::size_t line, std::size_t count, std::size_t chunk_size,
                      const ChunkWork& work, const ChunkSink& sink, const ChunkSink& replayed);

struct RunOutcome {
  double kappa = 1.0;       // the calibrated kappa on the coordinator; 1 elsewhere and without v
  bool calibrated = false;  // v was an output and kappa was calibrated on the reference line
  RunTimings timings;
};

// Runs every line through `pool` (all processes call it; `observer` is used on rank 0 only).
// An InputError on the coordinator (kappa cannot be calibrated) is raised on every process;
// a failed chunk raises PoolError everywhere, a stop request (Pool::stop_when) PoolInterrupted.
// With a `journal`, chunks it holds are replayed instead of evaluated and new ones recorded.
RunOutcome run_campaign_lines(const PreparedCampaign& campaign, Pool& pool, RunObserver& observer,
                              ChunkJournal* journal = nullptr);

// Runs `action` on the coordinator and raises what it threw on every process: InputError as
// InputError (same location and problem), anything else as std::runtime_error. All processes
// must call it at the same point.
void on_coordinator(Pool& pool, const std::function<void()>& action);

}  // namespace growthuq
