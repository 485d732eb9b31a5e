// growthuq tradeoff: the measured speed/accuracy trade of a campaign (issue 4, "The trade").
// The campaign runs once per fidelity and sample count through the evaluation pool (serially or
// under mpirun); the summaries of each count are compared with those of the same fidelity's
// largest count and with the largest shell_fe run, written as tradeoff.csv, and the smallest
// count meeting the requested accuracy (per fidelity) and the cheapest run within it of the
// finite-element model are printed on stdout.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "commands.hpp"
#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/campaign/progress.hpp"
#include "growthuq/campaign/run_footprint.hpp"
#include "growthuq/campaign/run_time_estimate.hpp"
#include "growthuq/campaign/tradeoff.hpp"
#include "growthuq/campaign/tradeoff_choice.hpp"
#include "growthuq/campaign/tradeoff_run.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/fe/shell_fe_evaluator.hpp"
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
  std::string fidelities;       // default: the campaign's fidelity if analytic, else closed_form
  std::string fe_samples_list;  // none: no shell_fe runs
  std::string target = "1%";
  std::string out;  // the CSV; default tradeoff.csv in the campaign's output_dir
  std::string lines;
  std::string seed;
  bool force = false;
  bool quiet = false;
};

constexpr std::string_view location = "growthuq tradeoff";
constexpr const char* tradeoff_csv_name = "tradeoff.csv";

// "a,b,c" -> {"a", "b", "c"}; an empty text is one empty entry.
std::vector<std::string> comma_separated(const std::string& text) {
  std::vector<std::string> entries;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    entries.push_back(std::string(trim(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start))));
    if (comma == std::string::npos) return entries;
    start = comma + 1;
  }
}

// "100,1000,10000": strictly increasing counts, each from 2 to 2^32 - 1, at least
// `minimum_counts` of them.
std::vector<std::size_t> parse_sample_counts(const std::string& text, std::string_view flag, std::size_t minimum_counts,
                                             std::string_view expected) {
  std::vector<std::size_t> counts;
  for (const std::string& entry : comma_separated(text)) {
    counts.push_back(parse_count(entry, location, flag, 2, 4294967295ULL));
  }
  bool increasing = counts.size() >= minimum_counts;
  for (std::size_t i = 1; i < counts.size(); ++i) increasing = increasing && counts[i] > counts[i - 1];
  if (!increasing) throw_bad_value(location, flag, text, expected);
  return counts;
}

// "closed_form,corrected": the analytic fidelities, each once. shell_fe takes minutes per
// sample and its own counts, so it is refused here in favour of --fe-samples-list.
std::vector<Fidelity> parse_fidelities(const std::string& text) {
  constexpr std::string_view flag = "--fidelities";
  const std::string expected = "closed_form or corrected, comma-separated, each once";
  std::vector<Fidelity> fidelities;
  for (const std::string& entry : comma_separated(text)) {
    if (entry == "shell_fe") {
      throw_bad_value(location, flag, text,
                      "closed_form or corrected; finite-element runs take their own sample counts: "
                      "--fe-samples-list (e.g. --fe-samples-list 10,50)");
    }
    if (entry != "closed_form" && entry != "thin_shell" && entry != "corrected") {
      throw_bad_value(location, flag, text, expected);
    }
    const Fidelity fidelity = parse_fidelity(entry, location, flag);
    if (std::find(fidelities.begin(), fidelities.end(), fidelity) != fidelities.end()) {
      throw_bad_value(location, flag, text, expected);
    }
    fidelities.push_back(fidelity);
  }
  return fidelities;
}

// The campaign's own fidelity when it is analytic (instant), closed_form otherwise: a shell_fe
// campaign's finite-element runs are asked for with --fe-samples-list.
Fidelity default_fidelity(const Campaign& campaign) {
  return campaign.fidelity == Fidelity::shell_fe ? Fidelity::closed_form : campaign.fidelity;
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
  check_can_write(path, overwrite, Folder::created_if_missing);
  const fs::path folder = fs::path(path).parent_path();
  if (folder.empty() || fs::exists(folder, error)) return std::nullopt;
  fs::create_directories(folder, error);
  if (error) throw InputError(folder.string(), "cannot create the folder of the trade-off table: " + error.message());
  return folder;
}

// Seconds of one core the shell_fe runs will take: every line at every count, at the mesh
// level's stated time per sample (run_time_estimate.hpp); the trade runs no bootstrap.
ShellFeTimeEstimate shell_fe_runs_time(const Campaign& campaign, const std::vector<std::size_t>& fe_counts) {
  ShellFeTimeEstimate estimate;
  for (const std::size_t count : fe_counts) estimate.samples += count * campaign.lines.size();
  estimate.seconds_per_sample = shell_fe_seconds_per_sample(campaign.shell_fe.mesh);
  estimate.core_seconds = static_cast<double>(estimate.samples) * estimate.seconds_per_sample;
  return estimate;
}

// Every fidelity's campaign prepared (line files, models, reference line; the corrected model's
// fitted correction) before any output or sampling, and the largest count of each checked to
// fit in memory (run_footprint.hpp); the trade-off writes no samples.
void validate_series(const Campaign& campaign, const std::vector<TradeoffSeries>& series, Pool& pool) {
  for (const TradeoffSeries& one : series) {
    Campaign first = campaign_at_fidelity(campaign, one.fidelity);
    first.samples = one.sample_counts.front();
    const PreparedCampaign validated(std::move(first), pool, ProgressMode::none, std::cerr);
    on_coordinator(pool, [&] {
      RunShape shape = run_shape(validated, false);
      shape.samples = one.sample_counts.back();
      shape.csv = shape.hdf5 = false;
      const bool fe = one.fidelity == Fidelity::shell_fe;
      require_room(estimate_run_footprint(shape), machine_room(pool.processes_on_this_machine()), location,
                   fe ? "--fe-samples-list" : "--samples-list");
    });
  }
}

// "trade-off of campaign 'quick' (closed_form): 5 lines x 5 quantities, seed 2022, errors
// against the 1000000-sample run", then the verdict of that fidelity's counts.
std::string fidelity_section(const Campaign& campaign, const TradeoffSeries& one, const std::vector<TradeoffRow>& rows,
                             double target_pct) {
  const std::string fidelity = fidelity_label(one.fidelity);
  return "trade-off of campaign '" + campaign.name + "' (" + fidelity + "): " + std::to_string(campaign.lines.size()) +
         " lines x " + std::to_string(campaign.outputs.size()) + " quantities, seed " + std::to_string(campaign.seed) +
         ", errors against the " + std::to_string(one.sample_counts.back()) + "-sample run\n\n" +
         format_tradeoff_report(judge_tradeoff(rows, fidelity, target_pct)) + "\n";
}

int run_tradeoff_command(const TradeoffOptions& options, const po::variables_map& values, Pool& pool) {
  const std::vector<std::size_t> counts = parse_sample_counts(
      options.samples_list, "--samples-list", 2,
      "at least two increasing sample counts, the largest being the reference (e.g. 100,1000,10000)");
  const std::vector<std::size_t> fe_counts =
      values.count("fe-samples-list")
          ? parse_sample_counts(options.fe_samples_list, "--fe-samples-list", 1,
                                "one or more increasing sample counts for the shell_fe runs, the largest being the "
                                "finite-element reference (e.g. 10,50,150)")
          : std::vector<std::size_t>{};
  std::vector<Fidelity> fidelities;
  if (values.count("fidelities")) fidelities = parse_fidelities(options.fidelities);
  const double target_pct = parse_target_pct(options.target);

  Campaign campaign = read_campaign_on_pool(options.campaign, pool);
  apply_overrides(campaign, overrides_of(options, values));
  if (fidelities.empty()) fidelities.push_back(default_fidelity(campaign));
  std::vector<TradeoffSeries> series;
  for (const Fidelity fidelity : fidelities) series.push_back({fidelity, counts});
  if (!fe_counts.empty()) series.push_back({Fidelity::shell_fe, fe_counts});
  validate_series(campaign, series, pool);
  // Finite-element samples take seconds to minutes each: how long they will take, before the
  // runs start, with --quiet too (it is no progress report: runs of days must not start
  // without a word).
  if (!fe_counts.empty() && pool.is_coordinator()) {
    std::cerr << "growthuq tradeoff: " << describe_shell_fe_time(shell_fe_runs_time(campaign, fe_counts), pool.size())
              << std::flush;
  }

  const std::string csv_path =
      values.count("out") ? options.out : (fs::path(campaign.output_dir) / tradeoff_csv_name).string();
  const Overwrite overwrite = options.force ? Overwrite::allow : Overwrite::refuse;
  std::optional<fs::path> created_folder;
  on_coordinator(pool, [&] { created_folder = prepare_csv_path(csv_path, overwrite); });

  try {
    const ProgressMode progress = pool.is_coordinator() ? choose_progress_mode(options.quiet) : ProgressMode::none;
    const std::vector<TradeoffRun> runs = run_tradeoff(campaign, series, pool, progress, std::cerr);
    on_coordinator(pool, [&] {
      const std::vector<TradeoffRow> rows = tradeoff_rows(runs);
      write_file_atomically(csv_path, tradeoff_csv_text(rows), overwrite);
      std::string report;
      for (const TradeoffSeries& one : series) {
        // One count alone (a single shell_fe run) has nothing to converge against.
        if (one.sample_counts.size() >= 2) report += fidelity_section(campaign, one, rows, target_pct);
      }
      if (const std::optional<TradeoffChoice> choice = choose_cheapest_run(rows, target_pct)) {
        report += "every run against the finite-element model (the " + std::to_string(choice->reference_samples) +
                  "-sample shell_fe run):\n\n" + format_tradeoff_choice(*choice) + "\n";
      }
      std::cout << report << "table: " << csv_path << " (" << rows.size() << " rows)\n";
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
      ("fidelities", po::value(&options.fidelities),
       "comma-separated among closed_form, corrected, each run at every --samples-list count (default: the "
       "campaign's fidelity if closed_form or corrected, else closed_form)")
      ("fe-samples-list", po::value(&options.fe_samples_list),
       "increasing samples per line of shell_fe runs (e.g. 10,50,150; one count allowed); the largest is the "
       "finite-element reference of every run")
      ("target", po::value(&options.target)->default_value(options.target),
       "accuracy wanted for every median and IQR, in percent of the reference (e.g. 1% or 0.5%)")
      ("out", po::value(&options.out), "the table (default: tradeoff.csv in the campaign's output_dir)")
      ("force", po::bool_switch(&options.force), "overwrite an existing table")
      ("lines", po::value(&options.lines), "comma-separated subset of the campaign's lines (keep the reference line)")
      ("seed", po::value(&options.seed), "campaign seed, 0 to 2^64 - 1 (overrides [campaign] seed)")
      ("quiet", po::bool_switch(&options.quiet), "no progress on stderr (the finite-element time estimate is still printed)");
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
          "Each fidelity of --fidelities runs at every count, judged against its own\n"
          "largest count. With --fe-samples-list, shell_fe runs join; every run's errors\n"
          "against the shell_fe run with the most samples fill the table's fe_ columns,\n"
          "and stdout adds every (fidelity, samples) run with its seconds and worst errors\n"
          "against it, and the cheapest run (least seconds) whose every median and IQR is\n"
          "within --target of it, or the closest one. Every line of a run is at that\n"
          "run's fidelity: a line's own `fidelity =` does not apply in the trade.\n"
          "The seed is the same at every count, so the designs at different counts are independent\n"
          "Latin hypercube draws (a design depends on seed, line, variable and sample count).\n"
          "Works under mpirun like growthuq run.",
          described, positional, values)) {
    return 0;
  }
  return run_on_pool([&](Pool& pool) { return run_tradeoff_command(options, values, pool); });
}

}  // namespace growthuq::cli
