// growthuq run: a whole campaign (campaign_file.hpp) through the evaluation pool, serially or
// under mpirun, writing samples.csv, summary.csv and results.h5 into the output directory and
// a readable summary on stdout. Every process validates the same campaign text (rank 0 reads
// the file and broadcasts it); only rank 0 prints.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/campaign_outputs.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/campaign/progress.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/pool/pool.hpp"
#include "options.hpp"

namespace growthuq::cli {

namespace {

struct RunOptions {
  std::string campaign;
  std::string samples;  // as typed, parsed strictly below
  std::string seed;
  std::string out;
  std::string lines;
  std::string formats;
  bool force = false;
  bool quiet = false;
};

constexpr std::string_view location = "growthuq run";

CampaignOverrides overrides_of(const RunOptions& options, const po::variables_map& values) {
  CampaignOverrides overrides;
  if (values.count("samples")) overrides.samples = parse_count(options.samples, location, "--samples", 1, 4294967295ULL);
  if (values.count("seed")) overrides.seed = parse_count(options.seed, location, "--seed");
  if (values.count("out")) overrides.output_dir = options.out;
  if (values.count("lines")) overrides.lines = options.lines;
  if (values.count("formats")) overrides.formats = options.formats;
  return overrides;
}

std::string command_line_of(const Arguments& arguments) {
  std::string text = "growthuq run";
  for (const std::string& argument : arguments) text += " " + argument;
  return text;
}

int run_campaign_command(const RunOptions& options, const po::variables_map& values, const Arguments& arguments, Pool& pool) {
  // Rank 0 reads the file so that every process validates exactly the same text.
  std::string text;
  on_coordinator(pool, [&] {
    Campaign probe = read_campaign(options.campaign);
    text = std::move(probe.text);
  });
  text = pool.broadcast(text);
  Campaign campaign = parse_campaign(text, options.campaign);
  apply_overrides(campaign, overrides_of(options, values));
  const PreparedCampaign prepared(std::move(campaign));

  OutputSettings settings;
  settings.overwrite = options.force ? Overwrite::allow : Overwrite::refuse;
  settings.progress = pool.is_coordinator() ? choose_progress_mode(options.quiet) : ProgressMode::none;
  settings.command_line = command_line_of(arguments);
  const CampaignOutcome outcome = run_campaign_with_outputs(prepared, pool, settings, std::cout, std::cerr);
  if (std::getenv("GROWTHUQ_TIMINGS") != nullptr) {
    // One line per process, for measuring how the work is shared (tools/bench-campaign-scaling).
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
      ("campaign", po::value(&options.campaign)->required(), "campaign file (INI; relative paths in it start at its folder)")
      ("samples", po::value(&options.samples), "samples per line (overrides [campaign] samples)")
      ("seed", po::value(&options.seed), "campaign seed, 0 to 2^64 - 1 (overrides [campaign] seed)")
      ("out", po::value(&options.out), "output directory (overrides [campaign] output_dir)")
      ("lines", po::value(&options.lines), "comma-separated subset of the campaign's lines (keep the reference line)")
      ("formats", po::value(&options.formats), "csv, hdf5 or csv,hdf5 (summary.csv is always written)")
      ("force", po::bool_switch(&options.force), "reuse an existing output directory, replacing its results")
      ("quiet", po::bool_switch(&options.quiet), "no progress on stderr");
  po::positional_options_description positional;
  positional.add("campaign", 1);
  po::variables_map values;
  if (!parse_arguments(arguments, "run", "CAMPAIGN.ini [options]",
                       "Runs a campaign: for each plant line, a correlated Latin hypercube design through the\n"
                       "thin-shell and growth models, in chunks over all processes (mpirun -np K growthuq run ...\n"
                       "gives bit-identical results for any K). Writes samples.csv (one row per sample; flagged\n"
                       "values are empty cells), summary.csv (median, quartiles, 10-90 %, mean, sd and a 95 %\n"
                       "confidence interval of the median per line and quantity) and results.h5 into the output\n"
                       "directory, which must not exist unless --force is given. Growth rates are scaled by kappa,\n"
                       "calibrated so the reference line's predicted median equals its experimental median.\n"
                       "Progress goes to stderr (a bar on a terminal, a line per plant line otherwise).",
                       described, positional, values)) {
    return 0;
  }
  const std::unique_ptr<Pool> pool = make_pool();
  if (pool->is_coordinator()) return run_campaign_command(options, values, arguments, *pool);
  // Every process meets the same errors at the same point (on_coordinator shares the
  // coordinator's); only rank 0 reports them.
  try {
    return run_campaign_command(options, values, arguments, *pool);
  } catch (const InputError&) {
    return 2;
  } catch (const std::exception&) {
    return 3;
  }
}

}  // namespace growthuq::cli
