// growthuq run: a whole campaign (campaign_file.hpp) through the evaluation pool, serially or
// under mpirun, writing samples.csv, summary.csv and results.h5 into the output directory and
// a readable summary on stdout. Every process validates the same campaign text (rank 0 reads
// the file, or the checkpoint manifest with --resume, and broadcasts it); only rank 0 prints.
// Ctrl-C or SIGTERM stops the run after the chunks under way; the checkpoint keeps every
// finished chunk for `growthuq run --resume DIR`.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>

#include "commands.hpp"
#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/run_campaign.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/interrupt.hpp"
#include "growthuq/core/printable.hpp"
#include "growthuq/pool/pool.hpp"
#include "campaign_flags.hpp"
#include "options.hpp"
#include "pool_command.hpp"

namespace growthuq::cli {

namespace {

struct RunFlags {
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
void check_resume_options(const RunFlags& options, const po::variables_map& values) {
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

int run_campaign_command(const RunFlags& flags, const po::variables_map& values, const Arguments& arguments, Pool& pool) {
  check_resume_options(flags, values);
  RunOptions options;
  options.overwrite = flags.force ? Overwrite::allow : Overwrite::refuse;
  options.checkpoint = !flags.no_checkpoint;
  options.stop_on_signals = true;
  options.progress = choose_progress_mode(flags.quiet);
  options.line_reports = !flags.summary_only;
  options.caller = std::string(location);
  options.report = &std::cout;
  options.log = &std::cerr;
  RunSummary summary;
  if (values.count("resume")) {
    summary = resume_campaign(flags.resume, pool, options);
  } else {
    Campaign campaign = read_campaign_on_pool(flags.campaign, pool);
    options.overrides = flags.flags.overrides(values, location);
    options.command_line = command_line_of(arguments);
    summary = run_campaign(std::move(campaign), pool, options);
  }
  if (!summary.completed) {
    if (pool.is_coordinator()) std::cerr << "growthuq run: " << printable(summary.stop_message) << "\n";
    return exit_status_of_signal(summary.stop_reason);
  }
  if (std::getenv("GROWTHUQ_TIMINGS") != nullptr) {
    // One line per process, for measuring how the work is shared (tools/bench/bench-campaign-scaling).
    const RunTimings& t = summary.timings;
    std::fprintf(stderr,
                 "growthuq run: timings of process %d of %d [s]: design %.3f evaluation %.3f sharing %.3f statistics %.3f "
                 "observer %.3f\n",
                 pool.rank(), pool.size(), t.design, t.evaluation, t.sharing, t.statistics, t.observer);
  }
  return 0;
}

}  // namespace

int run_run(const Arguments& arguments) {
  RunFlags options;
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
                       "models of turgor and modulus at the campaign's fidelity (closed_form: the thin-shell closed\n"
                       "form; corrected; shell_fe: the finite-element shell, minutes per sample; --fidelity or the\n"
                       "campaign's and lines' fidelity =), then viscosity and growth, in chunks over all processes\n"
                       "(mpirun -np K growthuq run ... gives bit-identical results for any K). Growth rates are\n"
                       "scaled by kappa, calibrated so the reference line's predicted median equals its\n"
                       "experimental median. For lines given by raw data (raw = FILE) a parametric bootstrap over\n"
                       "the tubes gives each median its data 95 % interval, the one to quote ([data_uncertainty];\n"
                       "\"fixed\" where the bootstrap does not move it), beside the Monte Carlo 95 % CI of this\n"
                       "run's samples.\n\n"
                       "Writes into the output directory, which must not exist unless --force is given:\n"
                       "summary.csv (per line and quantity the median, quartiles, 10-90 %, mean, sd, the Monte\n"
                       "Carlo CI and the data interval), sensitivity.csv (first-order indices) and provenance.json\n"
                       "(version, campaign and its SHA-256, seed, models and their references) always;\n"
                       "samples.csv (one row per sample; flagged values are empty cells) with csv among the\n"
                       "formats, results.h5 (everything, for Python) with hdf5; with the bootstrap\n"
                       "data_uncertainty.csv, and for two or more raw-data lines comparisons.csv and letters.csv.\n"
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
