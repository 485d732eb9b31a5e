// growthuq tradeoff: the measured speed/accuracy trade of a campaign (issue 4, "The trade").
// The campaign runs once per sample count through the evaluation pool (serially or under
// mpirun); the summaries of each count are compared with those of the largest, written as
// tradeoff.csv, and the smallest count meeting the requested accuracy is printed on stdout.
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "commands.hpp"
#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "campaign/progress.hpp"
#include "campaign/run_footprint.hpp"
#include "growthuq/campaign/tradeoff.hpp"
#include "growthuq/campaign/tradeoff_run.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/pool/pool.hpp"
#include "options.hpp"
#include "pool_command.hpp"

namespace growthuq::cli {

namespace {

namespace fs = std::filesystem;

struct TradeoffOptions {
  std::string campaign;
  std::string samples_list = "100,1000,10000,100000,1000000";
  std::string target = "1%";
  std::string out;  // the CSV; default tradeoff.csv in the campaign's output_dir
  std::string lines;
  std::string seed;
  bool force = false;
  bool quiet = false;
};

constexpr std::string_view location = "growthuq tradeoff";
constexpr const char* tradeoff_csv_name = "tradeoff.csv";

// "100,1000,10000": at least two strictly increasing counts, each from 2 to 2^32 - 1.
std::vector<std::size_t> parse_sample_counts(const std::string& text) {
  std::vector<std::size_t> counts;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string entry = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    counts.push_back(parse_count(entry, location, "--samples-list", 2, 4294967295ULL));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  bool increasing = counts.size() >= 2;
  for (std::size_t i = 1; i < counts.size(); ++i) increasing = increasing && counts[i] > counts[i - 1];
  if (!increasing) {
    throw_bad_value(location, "--samples-list", text,
                    "at least two increasing sample counts, the largest being the reference (e.g. 100,1000,10000)");
  }
  return counts;
}

// "1%", "0.5 %" or "1": a percentage above 0 and at most 100.
double parse_target_pct(const std::string& text) {
  std::string_view number = trim(text);
  if (number.ends_with('%')) number = trim(number.substr(0, number.size() - 1));
  const std::optional<double> value = try_parse_double(number);
  if (!value || !(*value > 0) || *value > 100) {
    throw_bad_value(location, "--target", text, "a percentage above 0 and at most 100, e.g. 1%");
  }
  return *value;
}

CampaignOverrides overrides_of(const TradeoffOptions& options, const po::variables_map& values) {
  CampaignOverrides overrides;
  if (values.count("seed")) overrides.seed = parse_count(options.seed, location, "--seed");
  if (values.count("lines")) overrides.lines = options.lines;
  return overrides;
}

// Checks before any sampling that the CSV may be written and creates its folder when missing;
// returns the folder when this run created it (removed again if the run fails).
std::optional<fs::path> prepare_csv_path(const std::string& path, Overwrite overwrite) {
  std::error_code error;
  if (fs::is_directory(path, error)) throw InputError(path, "is a directory; --out names the table file (e.g. trade.csv)");
  check_can_write(path, overwrite);
  const fs::path folder = fs::path(path).parent_path();
  if (folder.empty() || fs::exists(folder, error)) return std::nullopt;
  fs::create_directories(folder, error);
  if (error) throw InputError(folder.string(), "cannot create the folder of the trade-off table: " + error.message());
  return folder;
}

int run_tradeoff_command(const TradeoffOptions& options, const po::variables_map& values, Pool& pool) {
  const std::vector<std::size_t> counts = parse_sample_counts(options.samples_list);
  const double target_pct = parse_target_pct(options.target);

  Campaign campaign = read_campaign_on_pool(options.campaign, pool);
  apply_overrides(campaign, overrides_of(options, values));
  {
    // Everything validated (line files, models, reference line) before any output or sampling.
    Campaign first = campaign;
    first.samples = counts.front();
    const PreparedCampaign validated(std::move(first), pool, ProgressMode::none, std::cerr);
    // The largest count must fit in memory (run_footprint.hpp); the trade-off writes no samples.
    on_coordinator(pool, [&] {
      RunShape shape = run_shape(validated, false);
      shape.samples = counts.back();
      shape.csv = shape.hdf5 = false;
      require_room(estimate_run_footprint(shape), machine_room(pool.processes_on_this_machine()), location, "--samples-list");
    });
  }

  const std::string csv_path =
      values.count("out") ? options.out : (fs::path(campaign.output_dir) / tradeoff_csv_name).string();
  const Overwrite overwrite = options.force ? Overwrite::allow : Overwrite::refuse;
  std::optional<fs::path> created_folder;
  on_coordinator(pool, [&] { created_folder = prepare_csv_path(csv_path, overwrite); });

  try {
    const ProgressMode progress = pool.is_coordinator() ? choose_progress_mode(options.quiet) : ProgressMode::none;
    const std::vector<TradeoffRun> runs = run_tradeoff(campaign, counts, pool, progress, std::cerr);
    on_coordinator(pool, [&] {
      const std::vector<TradeoffRow> rows = tradeoff_rows(runs);
      write_file_atomically(csv_path, tradeoff_csv_text(rows), overwrite);
      const std::string fidelity = fidelity_label(campaign.fidelity);
      std::cout << "trade-off of campaign '" << campaign.name << "' (" << fidelity << "): " << campaign.lines.size()
                << " lines x " << campaign.outputs.size() << " quantities, seed " << campaign.seed
                << ", errors against the " << counts.back() << "-sample run\n\n"
                << format_tradeoff_report(judge_tradeoff(rows, fidelity, target_pct)) << "\ntable: " << csv_path
                << " (" << rows.size() << " rows)\n";
    });
  } catch (...) {
    // A failed run leaves no empty folder of its own making behind.
    std::error_code ignored;
    if (created_folder) fs::remove(*created_folder, ignored);
    throw;
  }
  return 0;
}

}  // namespace

int run_tradeoff(const Arguments& arguments) {
  TradeoffOptions options;
  po::options_description described("options");
  described.add_options()
      ("campaign", po::value(&options.campaign)->required(), "campaign file (INI; its samples key is not used)")
      ("samples-list", po::value(&options.samples_list)->default_value(options.samples_list),
       "increasing samples per line, comma-separated; the largest is the reference")
      ("target", po::value(&options.target)->default_value(options.target),
       "accuracy wanted for every median and IQR, in percent of the reference (e.g. 1% or 0.5%)")
      ("out", po::value(&options.out), "the table (default: tradeoff.csv in the campaign's output_dir)")
      ("force", po::bool_switch(&options.force), "overwrite an existing table")
      ("lines", po::value(&options.lines), "comma-separated subset of the campaign's lines (keep the reference line)")
      ("seed", po::value(&options.seed), "campaign seed, 0 to 2^64 - 1 (overrides [campaign] seed)")
      ("quiet", po::bool_switch(&options.quiet), "no progress on stderr");
  po::positional_options_description positional;
  positional.add("campaign", 1);
  po::variables_map values;
  if (!parse_arguments(
          arguments, "tradeoff", "CAMPAIGN.ini [options]",
          "Measures the speed/accuracy trade of a campaign: runs it once per sample count of\n"
          "--samples-list (no samples.csv or results.h5), and compares each count's median and IQR per\n"
          "line and quantity with those of the largest count (the reference): error in % of the\n"
          "reference, and the median's error over the half-width of its own 95 % confidence interval.\n"
          "Writes the table as CSV (one row per count x line x quantity, with the wall time of the\n"
          "whole campaign at that count) and prints per count the time and the worst errors, then the\n"
          "smallest count from which on every median and IQR is within --target of the reference,\n"
          "and whether the reference itself is precise enough for that answer to mean something.\n"
          "The seed is the same at every count, so the designs at different counts are independent\n"
          "Latin hypercube draws (a design depends on seed, line, variable and sample count).\n"
          "Works under mpirun like growthuq run.",
          described, positional, values)) {
    return 0;
  }
  return run_on_pool([&](Pool& pool) { return run_tradeoff_command(options, values, pool); });
}

}  // namespace growthuq::cli
