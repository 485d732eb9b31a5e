// The library's front door: a whole campaign run with its result files, as `growthuq run` runs
// it (src/cli/command_run.cpp is written on this header alone). run_campaign validates the
// campaign (Campaign::validate, then every file it names), refuses a run this machine cannot
// hold (run_footprint.hpp), runs every line through the pool, writes summary.csv, samples.csv,
// results.h5 and the others into the output directory, and returns a RunSummary, whose
// brief_report() is one line and full_report() the summary table (after Ceres' Solve and
// Solver::Summary). Bad input is an InputError naming where it was given; nothing is written.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/campaign/progress_mode.hpp"
#include "growthuq/evaluation/line_result.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/pool/pool.hpp"

namespace growthuq {

struct RunOptions {
  // Applied to the campaign before it is validated, and kept with the checkpoint so that a
  // resumed run applies them again; their messages name them as command-line flags.
  CampaignOverrides overrides;
  Overwrite overwrite = Overwrite::refuse;  // allow: replace the results of an existing output directory
  // Keep finished chunks in output_dir/checkpoint while the run lasts, so that an interrupted
  // run can be finished by resume_campaign.
  bool checkpoint = true;
  // Ctrl-C and SIGTERM stop the run after the chunks under way (a second one ends the process);
  // off: only the pool's own stop request (Pool::stop_when) stops it.
  bool stop_on_signals = false;
  ProgressMode progress = ProgressMode::none;  // on `log`, by the coordinating process
  bool line_reports = true;  // false: `report` ends after the summary table and kappa
  std::string command_line;  // stored in results.h5 and the checkpoint
  std::string caller = "run_campaign";  // names the caller in messages ("growthuq run")
  std::ostream* report = nullptr;       // the readable summary of the results (none when null)
  std::ostream* log = nullptr;          // progress, design warnings, the finite-element time estimate
};

struct RunSummary {
  bool completed = false;
  // When the pool was stopped (a signal with stop_on_signals): its reason (the signal) and the
  // message saying how to finish (growthuq run --resume DIR). No result file was written.
  int stop_reason = 0;
  std::string stop_message;
  bool resumed = false;
  std::string campaign;     // its name
  std::string output_dir;
  std::size_t lines = 0;
  std::size_t samples_per_line = 0;
  double kappa = 1.0;       // on the coordinating process; 1 elsewhere and without v
  bool calibrated = false;  // kappa was calibrated on the reference line
  std::vector<QuantitySummary> summaries;  // the rows of summary.csv (coordinating process only)
  RunTimings timings;       // this process's
  double seconds = 0.0;     // wall time of the whole call

  // "campaign 'quick': 5 lines x 300 samples run in 0.412 s, kappa 1.23, results in results/quick",
  // or the stop message.
  std::string brief_report() const;
  // The brief report, then per line and quantity the median, quartiles and n, then the time
  // spent in each part of the run.
  std::string full_report() const;
};

// Every process of `pool` calls it with the same campaign. InputError (on every process) for
// bad input, the output directory refused (it exists and overwrite is refuse: the results are
// never replaced unasked) or a run too large for this machine; PoolError when a chunk failed.
RunSummary run_campaign(Campaign campaign, Pool& pool, const RunOptions& options);

// Finishes the interrupted run whose output directory is `output_dir` from its checkpoint,
// with the campaign and overrides stored there (results byte-identical to an uninterrupted
// run). `options` gives only how to report (progress, line_reports, stop_on_signals, caller,
// report, log): overrides, overwrite and checkpoint = false are refused, since they would
// change what the interrupted run started.
RunSummary resume_campaign(const std::string& output_dir, Pool& pool, const RunOptions& options);

// What a run checks of campaign.output_dir before it creates it or writes there, without
// touching it (`growthuq check`, and run_campaign before it prepares the campaign): InputError
// naming it when a live run holds it (the lock's "is in use" message), when it exists and
// overwrite is refuse (suggesting --resume when it holds an interrupted run), when it exists and
// is no directory, when a result file there would replace something that is not a regular file,
// or when it is "-" (standard output, which other commands take for a result file).
void check_output_directory(const Campaign& campaign, Overwrite overwrite);

}  // namespace growthuq
