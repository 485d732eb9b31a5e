// growthuq run: a whole campaign (campaign_file.hpp) through the evaluation pool, serially or
// under mpirun, writing samples.csv, summary.csv and results.h5 into the output directory and
// a readable summary on stdout. Every process validates the same campaign text (rank 0 reads
// the file, or the checkpoint manifest with --resume, and broadcasts it); only rank 0 prints.
// Ctrl-C or SIGTERM stops the run after the chunks under way; the checkpoint keeps every
// finished chunk for `growthuq run --resume DIR`.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>

#include "commands.hpp"
#include "growthuq/campaign/campaign_file.hpp"
#include "campaign/campaign_audit.hpp"
#include "campaign/campaign_outputs.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "campaign/checkpoint.hpp"
#include "campaign/checkpoint_manifest.hpp"
#include "campaign/progress.hpp"
#include "campaign/run_footprint.hpp"
#include "campaign/run_time_estimate.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/printable.hpp"
#include "core/interrupt.hpp"
#include "growthuq/pool/pool.hpp"
#include "campaign_flags.hpp"
#include "options.hpp"
#include "pool_command.hpp"

namespace growthuq::cli {

namespace {

struct RunOptions {
  std::string campaign;
  CampaignFlags flags;
  std::string resume;  // output directory of an interrupted run
  bool force = false;
  bool quiet = false;
  bool summary_only = false;
  bool no_checkpoint = false;
};

constexpr std::string_view location = "growthuq run";
constexpr std::string_view usage = "CAMPAIGN.ini [options] | growthuq run --resume DIR [--quiet] [--summary-only]";

std::string command_line_of(const Arguments& arguments) {
  std::string text = "growthuq run";
  for (const std::string& argument : arguments) text += " " + argument;
  return text;
}

// --resume takes everything that decides the result from the checkpoint; an option that could
// change it is refused rather than silently ignored or applied.
void check_resume_options(const RunOptions& options, const po::variables_map& values) {
  const std::string where(location);
  if (!values.count("resume")) {
    if (options.campaign.empty()) throw missing_argument("run", usage, "the campaign file");
    return;
  }
  if (!options.campaign.empty()) {
    throw InputError(where, "give a campaign file or --resume DIR, not both: the resumed run uses the campaign stored in its checkpoint");
  }
  for (const std::string_view option : campaign_flag_names) {
    if (values.count(std::string(option))) {
      throw InputError(where, "--" + std::string(option) +
                                  " cannot be combined with --resume: the resumed run keeps the settings of the interrupted "
                                  "one, so that its results are the same");
    }
  }
  if (options.force) {
    throw InputError(where, "--force cannot be combined with --resume (to start the run again instead, run the campaign "
                            "with --force --out DIR)");
  }
  if (options.no_checkpoint) throw InputError(where, "--no-checkpoint cannot be combined with --resume");
}

// An edited campaign file does not change a resumed run (it finishes the run as started, from
// the text stored in the manifest), but the user who edited it should hear so: one line.
void warn_if_campaign_file_differs(const CheckpointManifest& manifest, const std::string& manifest_path) {
  const CampaignFileNow now = campaign_file_now(manifest);
  if (now == CampaignFileNow::unchanged) return;
  std::cerr << printable("growthuq run: warning: " + locate(manifest, manifest.campaign_path) +
                         (now == CampaignFileNow::changed ? " changed since the run started" : " cannot be read now") +
                         "; resuming with the campaign text stored in " + manifest_path +
                         " (to run the file as it is now, start the run again with --force)")
            << "\n";
}

// The checkpoint's campaign, after rank 0 has checked that nothing it read has changed.
Campaign resumed(const std::string& directory, Pool& pool, OutputSettings& settings) {
  const std::string manifest_path = checkpoint_manifest_path(directory);
  std::string text;
  on_coordinator(pool, [&] {
    text = read_checkpoint_manifest_text(directory);
    const CheckpointManifest manifest = parse_manifest(text, manifest_path);
    verify_manifest(manifest, manifest_path);
    warn_if_campaign_file_differs(manifest, manifest_path);
  });
  text = pool.broadcast(text);
  const CheckpointManifest manifest = parse_manifest(text, manifest_path);
  settings.command_line = manifest.command_line;  // results.h5 as the uninterrupted run writes it
  settings.checkpointing = Checkpointing::resume;
  return resumed_campaign(manifest, directory);
}

int run_campaign_command(const RunOptions& options, const po::variables_map& values, const Arguments& arguments, Pool& pool) {
  check_resume_options(options, values);
  OutputSettings settings;
  settings.overwrite = options.force ? Overwrite::allow : Overwrite::refuse;
  settings.progress = pool.is_coordinator() ? choose_progress_mode(options.quiet) : ProgressMode::none;
  settings.line_reports = !options.summary_only;
  std::optional<PreparedCampaign> prepared;
  if (values.count("resume")) {
    prepared.emplace(resumed(options.resume, pool, settings), pool, settings.progress, std::cerr);
  } else {
    Campaign campaign = read_campaign_on_pool(options.campaign, pool);
    const CampaignOverrides overrides = options.flags.overrides(values, location);
    apply_overrides(campaign, overrides);
    // The output directory is checked again under its lock (campaign_outputs.hpp); here, before
    // a raw-data campaign's curve fits and the designs, so a refusal comes at once.
    on_coordinator(pool, [&] { check_output_directory(campaign, settings.overwrite); });
    prepared.emplace(std::move(campaign), pool, settings.progress, std::cerr);
    settings.command_line = command_line_of(arguments);
    if (!options.no_checkpoint) {
      settings.checkpointing = Checkpointing::start;
      on_coordinator(pool, [&] {
        settings.manifest = make_checkpoint_manifest(prepared->campaign(), overrides, settings.command_line);
      });
    }
  }

  // [audit]: its models checked before any sampling, run before the campaign, its results
  // written with the campaign's (campaign_audit.hpp).
  std::optional<CampaignAudit> audit;
  if (prepared->campaign().audit.samples > 0) audit.emplace(*prepared, pool);

  // A run this machine cannot hold is refused now rather than killed part way (run_footprint.hpp).
  const bool resuming = values.count("resume") != 0;
  on_coordinator(pool, [&] {
    const RunShape shape = run_shape(*prepared, !resuming && settings.checkpointing == Checkpointing::start);
    // The count is named where the user gave it.
    const bool from_flag = !resuming && values.count("samples") != 0;
    const std::string where = resuming ? checkpoint_manifest_path(options.resume) : from_flag ? std::string(location) : options.campaign;
    require_room(estimate_run_footprint(shape), machine_room(pool.processes_on_this_machine(), prepared->campaign().output_dir),
                 where, resuming ? "samples" : from_flag ? "--samples" : "[campaign] samples");
    // Finite-element samples take minutes each: how long the run will take, before it starts,
    // with --quiet too (it is no progress report: a run of days must not start without a word).
    if (const auto time = estimate_shell_fe_time(*prepared)) {
      std::string text = describe_shell_fe_time(*time, pool.size());
      // The checkpoint's finished samples are read later, by the pool: the count above is the
      // whole run's, so for a resumed run it bounds the time from above.
      if (resuming) text.insert(text.size() - 1, "; at most that: the samples the checkpoint holds are not run again");
      std::cerr << "growthuq run: " << text << std::flush;
    }
  });

  // From here a first Ctrl-C or SIGTERM stops the pool at the next chunk (the coordinator's
  // signal decides for every process); a second one ends the process.
  const InterruptHandlers handlers;
  pool.stop_when([] { return interrupt_signal(); });
  CampaignOutcome outcome;
  try {
    if (audit) settings.extra_results = audit_results(run_audit(*audit, pool, settings.progress, std::cerr), prepared->campaign());
    outcome = run_campaign_with_outputs(*prepared, pool, settings, std::cout, std::cerr);
  } catch (const RunInterrupted& interrupted) {
    if (pool.is_coordinator()) std::cerr << "growthuq run: " << printable(interrupted.what()) << "\n";
    return exit_status_of_signal(interrupted.reason());
  }
  if (std::getenv("GROWTHUQ_TIMINGS") != nullptr) {
    // One line per process, for measuring how the work is shared (tools/bench/bench-campaign-scaling).
    const RunTimings& t = outcome.run.timings;
    std::fprintf(stderr,
                 "growthuq run: timings of process %d of %d [s]: design %.3f evaluation %.3f sharing %.3f statistics %.3f "
                 "observer %.3f\n",
                 pool.rank(), pool.size(), t.design, t.evaluation, t.sharing, t.statistics, t.observer);
  }
  return 0;
}

}  // namespace

int run_run(const Arguments& arguments) {
  RunOptions options;
  po::options_description described("options");
  described.add_options()
      ("campaign", po::value(&options.campaign), "campaign file (INI; relative paths in it start at its folder)");
  options.flags.declare(described);
  described.add_options()
      ("force", po::bool_switch(&options.force), "reuse an existing output directory, replacing its results")
      ("quiet", po::bool_switch(&options.quiet), "no progress on stderr (a finite-element time estimate is still printed)")
      ("summary-only", po::bool_switch(&options.summary_only),
       "print only the summary table and kappa on stdout, not each line's input correlation, analysis and "
       "raw-data fits (for campaigns of many lines; results.h5 keeps them)")
      ("resume", po::value(&options.resume)->value_name("DIR"),
       "finish the interrupted run whose output directory is DIR (no campaign file: it is in DIR/checkpoint)")
      ("no-checkpoint", po::bool_switch(&options.no_checkpoint),
       "do not keep finished chunks in DIR/checkpoint (an interrupted run cannot be resumed)");
  po::positional_options_description positional;
  positional.add("campaign", 1);
  po::variables_map values;
  if (!parse_arguments(arguments, "run", usage,
                       "Runs a campaign: for each plant line, a correlated Latin hypercube design through the\n"
                       "thin-shell and growth models, in chunks over all processes (mpirun -np K growthuq run ...\n"
                       "gives bit-identical results for any K). Writes samples.csv (one row per sample; flagged\n"
                       "values are empty cells), summary.csv (median, quartiles, 10-90 %, mean, sd and a 95 %\n"
                       "confidence interval of the median per line and quantity) and results.h5 into the output\n"
                       "directory, which must not exist unless --force is given. Growth rates are scaled by kappa,\n"
                       "calibrated so the reference line's predicted median equals its experimental median.\n"
                       "Progress goes to stderr (a bar on a terminal, a line per plant line otherwise).\n\n"
                       "Every finished chunk is kept in DIR/checkpoint (removed when the run completes). Ctrl-C or\n"
                       "SIGTERM stops the run once the chunks under way are done (a second one ends it at once;\n"
                       "kept chunks survive even that), writes no result file, keeps DIR and exits with 130 or\n"
                       "143; 'growthuq run --resume DIR' (any number of processes) then evaluates only the rest\n"
                       "and writes results byte-identical to an uninterrupted run. It refuses to resume when a\n"
                       "line or matrix file changed since, or with options that would change the results. It uses\n"
                       "the campaign text stored in the checkpoint, with a warning if the campaign file was edited.",
                       described, positional, values)) {
    return 0;
  }
  return run_on_pool([&](Pool& pool) { return run_campaign_command(options, values, arguments, pool); });
}

}  // namespace growthuq::cli
