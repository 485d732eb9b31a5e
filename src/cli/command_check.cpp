// growthuq check: everything `growthuq run` validates before it samples (the campaign file and
// the flags, every line, matrix and raw-data file, the raw-data fits, the models each line
// needs, the output directory, the memory and disk the run will take on this machine), then
// the plan on stdout. Nothing is sampled and nothing is written.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "growthuq/campaign/run_campaign.hpp"
#include "growthuq/campaign/run_footprint.hpp"
#include "growthuq/campaign/run_time_estimate.hpp"
#include "growthuq/campaign/campaign_audit.hpp"
#include "campaign_flags.hpp"
#include "commands.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/pool/pool.hpp"
#include "options.hpp"

namespace growthuq::cli {
namespace {

constexpr std::string_view location = "growthuq check";
constexpr std::string_view usage = "CAMPAIGN.ini [--samples N] [--seed S] [--out DIR] [--lines a,b] [--formats F] [--force] [--quiet]";

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

// The physics correlation is always the closed form's: it draws 1e4 tubes through the forward
// model, seconds for the finite-element model each (campaigns/README.md, "Fidelity").
std::string correlation_text(const Campaign& campaign, const PreparedLine& line) {
  switch (line.campaign_line.correlation) {
    case CorrelationSource::none: return "independent";
    case CorrelationSource::file: return "rank correlation from a matrix file";
    case CorrelationSource::physics:
      return campaign.fidelity_of(line.campaign_line) == Fidelity::closed_form
                 ? "rank correlation from the forward thin-shell model"
                 : "rank correlation from the forward thin-shell model (not the line's fidelity " +
                       std::string(to_string(campaign.fidelity_of(line.campaign_line))) +
                       ": its forward model is too slow for the correlation's draws)";
  }
  return "";
}

// The bootstrap's share of the run, which the time line above leaves out: it samples every line
// again in each replicate and refits the raw-data laws (campaigns/README.md, "Data uncertainty").
std::string data_uncertainty_plan(const Campaign& c) {
  const std::size_t replicates = c.data_uncertainty.replicates;
  if (replicates == 0) {
    return std::string("data uncertainty: none, the intervals will be Monte Carlo only (") +
           (has_raw_data_line(c) ? "[data_uncertainty] replicates = 0" : "no line is given by raw data") + ")\n";
  }
  const std::size_t samples = data_uncertainty_samples(c);
  return "data uncertainty: a bootstrap of " + std::to_string(replicates) + " replicates x " + std::to_string(samples) +
         " samples per line (each refits the raw-data laws): " + std::to_string(replicates * samples) +
         " more samples per line, " + format_double(std::round(10.0 * static_cast<double>(replicates * samples) / static_cast<double>(c.samples)) / 10.0) +
         " times the run's own ([data_uncertainty] replicates = 0 switches it off)\n";
}

// The audit's share ([audit], campaign_audit.hpp), which the time line above counts.
std::string audit_plan(const PreparedCampaign& prepared) {
  const Campaign& c = prepared.campaign();
  if (c.audit.samples == 0) return "audit: none (an [audit] section runs the first N samples of each line through shell_fe too)\n";
  return "audit: the first " + std::to_string(c.audit.samples) + " samples of " + std::to_string(audited_lines(prepared).size()) +
         " line(s) through shell_fe too (mesh " + std::string(to_string(c.shell_fe.mesh)) + "): " +
         std::to_string(audit_fe_samples(c)) + " finite-element samples\n";
}

void print_plan(const PreparedCampaign& prepared, const RunFootprint& footprint, const MachineRoom& room) {
  const Campaign& c = prepared.campaign();
  const std::optional<ShellFeTimeEstimate> shell_fe_time = estimate_shell_fe_time(prepared);
  std::cout << "campaign '" << c.name << "' (" << c.path << "): " << prepared.lines().size()
            << (prepared.lines().size() == 1 ? " line" : " lines") << " x " << c.samples << " samples, seed " << c.seed
            << ", fidelity " << to_string(c.fidelity) << "\n"
            << "outputs: " << joined(c.outputs) << "\n\nlines, in run order:\n";
  for (const PreparedLine& line : prepared.lines()) {
    const CampaignLine& source = line.campaign_line;
    std::vector<std::string> variables, models;
    for (const LineVariable& variable : line.design_variables.variables) {
      variables.push_back(variable.name + " [" + std::string(variable.unit->symbol) + "]");
    }
    for (const Evaluator* model : line.plan) models.emplace_back(model->name());
    std::cout << "  " << source.name << ": "
              << (source.raw_path.empty() ? "distributions " + source.distributions_path : "fitted from raw data " + source.raw_path)
              << "\n    samples " << (variables.empty() ? std::string("nothing") : joined(variables)) << "; "
              << correlation_text(c, line) << "\n    models " << (models.empty() ? std::string("none") : joined(models))
              << (source.fidelity ? " (fidelity " + std::string(to_string(*source.fidelity)) + ")" : std::string()) << "\n";
  }
  const auto raw_lines = std::count_if(prepared.lines().begin(), prepared.lines().end(),
                                       [](const PreparedLine& line) { return !line.campaign_line.raw_path.empty(); });
  const bool bootstrap = c.data_uncertainty.replicates > 0;
  std::cout << "\nresults in " << c.output_dir << ": summary.csv, sensitivity.csv, provenance.json" << (c.formats.csv ? ", samples.csv" : "")
            << (c.formats.hdf5 ? ", results.h5" : "") << (bootstrap ? ", data_uncertainty.csv" : "")
            << (bootstrap && raw_lines >= 2 ? ", comparisons.csv, letters.csv" : "") << (c.audit.samples > 0 ? ", audit.csv" : "") << "\n"
            << "estimated peak memory " << readable_size(footprint.memory_bytes) << " for one process ("
            << (room.memory_bytes ? readable_size(*room.memory_bytes) + " available" : std::string("available memory unknown"))
            << "), disk " << readable_size(footprint.disk_bytes) << " ("
            << (room.disk_bytes ? readable_size(*room.disk_bytes) + " free there" : std::string("free space unknown")) << ")\n"
            << (shell_fe_time ? describe_shell_fe_time(*shell_fe_time, 1)
                              : "time: not estimated (growthuq tradeoff " + c.path + " measures it for sample counts you choose)\n")
            << data_uncertainty_plan(c) << audit_plan(prepared) << describe_shapley_cost(prepared) << "checked: nothing was sampled or written\n";
}

}  // namespace

int run_check(const Arguments& arguments) {
  std::string campaign_path;
  CampaignFlags flags;
  bool force = false, quiet = false;
  po::options_description described("options");
  described.add_options()("campaign", po::value(&campaign_path)->required(),
                          "campaign file (INI; relative paths in it start at its folder)");
  flags.declare(described);
  described.add_options()("force", po::bool_switch(&force), "check as for run --force: an existing output directory is accepted")
      ("quiet", po::bool_switch(&quiet), "no progress on stderr (the raw-data lines' curve fits, seconds each)");
  po::positional_options_description positional;
  positional.add("campaign", 1);
  po::variables_map values;
  if (!parse_arguments(arguments, "check", usage,
                       "Checks a campaign as 'growthuq run' with the same options would before it samples: the\n"
                       "campaign file, every line, matrix and raw-data file (raw data is fitted), the models each\n"
                       "line needs, the output directory, and the memory and disk the run needs on this machine.\n"
                       "Prints the plan: lines in run order with the variables they sample and their models,\n"
                       "the outputs, the result files and the estimated memory and disk. Samples nothing and\n"
                       "writes nothing; exits 0 when the run would start, 2 with the run's message otherwise.",
                       described, positional, values)) {
    return 0;
  }
  Campaign campaign = read_campaign(campaign_path);
  const CampaignOverrides overrides = flags.overrides(values, location);
  apply_overrides(campaign, overrides);
  // Before preparing: a raw-data campaign's curve fits take seconds, an output directory that
  // refuses the run is known at once.
  check_output_directory(campaign, force ? Overwrite::allow : Overwrite::refuse);
  // The raw-data lines' curve fits take seconds (15 s for campaigns/from_raw.ini): their
  // progress on stderr, as the run shows it.
  const std::unique_ptr<Pool> pool = make_serial_pool();
  const PreparedCampaign prepared(std::move(campaign), *pool, choose_progress_mode(quiet), std::cerr);
  if (prepared.campaign().audit.samples > 0) {
    const CampaignAudit audit(prepared, *pool);  // its checks, as the run makes them before sampling
  }
  const RunFootprint footprint = estimate_run_footprint(run_shape(prepared, true));
  const MachineRoom room = machine_room(1, prepared.campaign().output_dir);
  // Named where the count was given, as the run names it.
  const bool from_flag = values.count("samples") != 0;
  require_room(footprint, room, from_flag ? std::string(location) : campaign_path,
               from_flag ? "--samples" : "[campaign] samples");
  print_plan(prepared, footprint, room);
  return 0;
}

}  // namespace growthuq::cli
