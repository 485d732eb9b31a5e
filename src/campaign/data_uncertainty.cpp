#include "growthuq/campaign/data_uncertainty.hpp"
#include "growthuq/campaign/progress.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include "campaign/chunk_values.hpp"
#include "campaign/parametric_resample.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/large_vector.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/growth/kappa.hpp"
#include "growthuq/mechanics/probe_radius_column.hpp"
#include "growthuq/rawdata/raw_line_fit.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/stats/quantity_summary.hpp"
#include "growthuq/stats/sample_summary.hpp"

namespace growthuq {
namespace {

// A raw line's laws refitted to a parametric resample of its data: as many values per
// variable as the line has, drawn from the law the campaign fitted, fitted as the campaign did.
LineDistributions refitted_line(const PreparedLine& line, std::uint64_t key) {
  std::vector<VariableFit> refits;
  for (const VariableFit& fit : line.raw_fit->variables) {
    std::vector<double> values =
        parametric_resample(fit.best().distribution, fit.values.size(), key, line.campaign_line.name, fit.variable);
    if (!fit.uncertainties.empty()) add_measurement_error(values, fit.uncertainties, key, line.campaign_line.name, fit.variable);
    refits.push_back(fit_variable_by_aic(fit.variable, *fit.unit, std::move(values), fit.families, fit.source,
                                         "data uncertainty, line " + line.campaign_line.name));
  }
  return line_distributions_of(line.raw_fit->raw, refits);
}

// The line's design variables with the laws of `laws` (same names, same order).
LineDistributions with_laws(const LineDistributions& design_variables, const LineDistributions& laws) {
  LineDistributions result = design_variables;
  for (LineVariable& variable : result.variables) {
    const LineVariable* refitted = laws.find(variable.name);
    // A law of the probe radius is the instrument's, not the tubes': no replicate moves it.
    if (refitted == nullptr && variable.name == probe_radius_column) continue;
    if (refitted == nullptr) throw std::logic_error("refitted line lacks " + variable.name);
    variable.unit = refitted->unit;
    variable.distribution = refitted->distribution;
  }
  return result;
}

// One output of a line in a replicate: a design variable (its column of the design) or a
// computed output (its block of evaluate_chunk's values), in the campaign's output order.
struct ReplicateOutput {
  std::string quantity;
  std::optional<std::size_t> input;     // index into the line's design variables
  std::optional<std::size_t> computed;  // index into computed_outputs()
};

// The outputs a line has (the campaign's outputs that are its design variables or are computed),
// the same for every replicate: a replicate changes the laws, not the variables.
std::vector<ReplicateOutput> replicate_outputs(const PreparedCampaign& campaign, const PreparedLine& line) {
  const std::vector<std::string>& computed = campaign.computed_outputs();
  const auto& variables = line.design_variables.variables;
  std::vector<ReplicateOutput> outputs;
  for (const std::string& output : campaign.campaign().outputs) {
    const auto input = std::find_if(variables.begin(), variables.end(), [&](const LineVariable& v) { return v.name == output; });
    if (input != variables.end()) {
      outputs.push_back({output, static_cast<std::size_t>(input - variables.begin()), std::nullopt});
      continue;
    }
    const auto computed_index = std::find(computed.begin(), computed.end(), output);
    if (computed_index != computed.end()) {
      outputs.push_back({output, std::nullopt, static_cast<std::size_t>(computed_index - computed.begin())});
    }
  }
  return outputs;
}

// The unit of an output of `line` in summary.csv: the variable's for a design variable, the
// quantity's default for a computed output.
const Unit& output_unit(const PreparedLine& line, const ReplicateOutput& output) {
  if (output.input) return *line.design_variables.variables[*output.input].unit;
  return find_unit(find_quantity(output.quantity)->default_unit, "quantity table", output.quantity);
}

struct ReplicateLine {
  std::vector<ResultColumn> outputs;  // the campaign's outputs this line has, in campaign order
  std::vector<SampleStatus> status;
};

ReplicateLine evaluate_replicate_line(const PreparedCampaign& campaign, const PreparedLine& line, std::uint64_t key,
                                      std::size_t samples) {
  const Campaign& c = campaign.campaign();
  SamplingOptions options;
  options.samples = samples;
  options.seed = key;
  options.position = c.stratum_position;
  const LineDesign design = sample_line(line.design_variables, options, line.correlation ? &*line.correlation : nullptr);
  const std::vector<double> values = campaign.evaluate_chunk(line, design, ChunkRange{0, samples});
  const ChunkValues chunk(values, campaign.computed_outputs().size());
  ReplicateLine result;
  for (std::size_t i = 0; i < samples; ++i) result.status.push_back(chunk.status(i));
  for (const ReplicateOutput& output : replicate_outputs(campaign, line)) {
    const Unit& unit = output_unit(line, output);
    if (output.input) {
      result.outputs.push_back(ResultColumn{output.quantity, &unit, true, design.values[*output.input]});
      continue;
    }
    const std::span<const double> si = chunk.output(*output.computed);
    LargeVector<double> column(si.begin(), si.end());
    for (double& value : column) value /= unit.to_si;
    result.outputs.push_back(ResultColumn{output.quantity, &unit, false, std::move(column)});
  }
  return result;
}

ResultColumn* column_of(ReplicateLine& line, std::string_view quantity) {
  for (ResultColumn& column : line.outputs) {
    if (column.quantity == quantity) return &column;
  }
  return nullptr;
}

// One replicate: the medians of every line's outputs (NaN where no sample counts), lines in
// run order, so the reference line calibrates kappa before the others use it.
std::vector<std::vector<QuantitySummary>> replicate_summaries(const PreparedCampaign& campaign, std::uint64_t key,
                                                              std::size_t samples) {
  const Campaign& c = campaign.campaign();
  std::optional<KappaCalibration> kappa;  // the replicate's own, on its refitted reference line
  std::vector<std::vector<QuantitySummary>> summaries;
  for (const PreparedLine& original : campaign.lines()) {
    PreparedLine line = original;
    std::optional<LineDistributions> refit;
    if (original.raw_fit) {
      refit = refitted_line(original, key);
    } else if (states_tubes(original.distributions)) {
      refit = resampled_stated_line(original.distributions, original.campaign_line.name, key);
    }
    if (refit) line.design_variables = with_laws(original.design_variables, *refit);
    ReplicateLine result = evaluate_replicate_line(campaign, line, key, samples);
    if (campaign.calibrates_kappa()) {
      ResultColumn* v = column_of(result, KappaCalibration::quantity);
      if (original.campaign_line.name == c.reference_line) {
        const LineDistributions& laws = refit ? *refit : original.distributions;
        const LineVariable* v_exp = laws.find("v_exp");
        kappa.emplace(c.reference_line, quantile(v_exp->distribution, 0.5) * v_exp->unit->to_si);
        kappa->calibrate(v->values, v->unit->to_si, result.status);
      }
      if (v != nullptr && kappa) kappa->apply(v->values, result.status);
    }
    std::vector<QuantitySummary> line_summaries;
    for (const ResultColumn& column : result.outputs) {
      line_summaries.push_back(summarize_quantity(original.campaign_line.name, column));
    }
    summaries.push_back(std::move(line_summaries));
  }
  return summaries;
}

// Summary rows of the bootstrap: one per line (run order) and output the line has, as every
// replicate's summaries hold them.
struct LayoutRow {
  std::string line;
  std::string quantity;
  std::string unit;
  bool resampled = false;
  bool measurement_error = false;
};

// Whether a replicate draws some of the line's values within their measurement uncertainty.
bool draws_measurement_error(const PreparedLine& line) {
  if (!line.raw_fit) return false;
  return std::any_of(line.raw_fit->variables.begin(), line.raw_fit->variables.end(),
                     [](const VariableFit& fit) { return !fit.uncertainties.empty(); });
}

std::vector<LayoutRow> bootstrap_layout(const PreparedCampaign& campaign) {
  std::vector<LayoutRow> rows;
  for (const PreparedLine& line : campaign.lines()) {
    for (const ReplicateOutput& output : replicate_outputs(campaign, line)) {
      // Only raw-data lines are compared: a line file's laws are fixed, or redrawn only where they
      // state tubes (the shipped ones for k alone), so its interval is a lower bound.
      rows.push_back({line.campaign_line.name, output.quantity, std::string(output_unit(line, output).symbol),
                      line.raw_fit != nullptr, draws_measurement_error(line)});
    }
  }
  return rows;
}

// Replicate b as numbers, for the pool: 1 and its medians in layout order, or 0 and the
// reason it failed (character codes).
std::vector<double> replicate_numbers(const PreparedCampaign& campaign, std::uint64_t key, std::size_t samples) {
  std::vector<double> numbers{1.0};
  try {
    for (const std::vector<QuantitySummary>& line : replicate_summaries(campaign, key, samples)) {
      for (const QuantitySummary& row : line) numbers.push_back(row.median);
    }
  } catch (const InputError& error) {
    const std::string reason = error.what();
    numbers.assign(1, 0.0);
    for (const char c : reason) numbers.push_back(static_cast<double>(static_cast<unsigned char>(c)));
  }
  return numbers;
}

// The rows of the bootstrap from every replicate's numbers (in order of b), as one process
// would have found them replicate after replicate.
DataUncertaintyResult summarize_replicates(const PreparedCampaign& campaign, const std::vector<std::vector<double>>& replicates) {
  const Campaign& c = campaign.campaign();
  const std::size_t samples = data_uncertainty_samples(c);
  const std::vector<LayoutRow> layout = bootstrap_layout(campaign);
  DataUncertaintyResult result;
  std::vector<std::vector<double>> medians(layout.size());  // [row][replicate]
  std::vector<std::vector<std::size_t>> indices(layout.size());  // [row][replicate]: its b
  std::size_t succeeded = 0;
  for (std::size_t b = 0; b < replicates.size(); ++b) {
    const std::vector<double>& numbers = replicates[b];
    if (numbers.front() == 0.0) {
      if (result.failures.size() < 5) {
        std::string reason;
        for (std::size_t i = 1; i < numbers.size(); ++i) reason += static_cast<char>(static_cast<unsigned char>(numbers[i]));
        result.failures.push_back("replicate " + std::to_string(b) + ": " + reason);
      }
      continue;
    }
    if (numbers.size() != layout.size() + 1) throw std::logic_error("a data-uncertainty replicate has the wrong number of medians");
    ++succeeded;
    for (std::size_t r = 0; r < layout.size(); ++r) {
      if (std::isfinite(numbers[r + 1])) {
        medians[r].push_back(numbers[r + 1]);
        indices[r].push_back(b);
      }
    }
  }
  if (succeeded == 0) {
    throw InputError(c.path, "[data_uncertainty]: every one of " + std::to_string(replicates.size()) +
                                 " replicates failed (" + (result.failures.empty() ? std::string() : result.failures.front()) + ")");
  }
  for (std::size_t r = 0; r < layout.size(); ++r) {
    DataUncertainty row;
    row.line = layout[r].line;
    row.quantity = layout[r].quantity;
    row.unit = layout[r].unit;
    row.samples = samples;
    std::vector<double>& values = medians[r];
    row.replicate_medians = values;
    row.replicate_indices = indices[r];
    row.resampled = layout[r].resampled;
    row.measurement_error = layout[r].measurement_error;
    row.replicates = values.size();
    row.failed = replicates.size() - values.size();
    if (values.size() >= 2) {
      std::sort(values.begin(), values.end());
      row.low = sorted_quantile(values, 0.025);
      row.high = sorted_quantile(values, 0.975);
      double mean = 0.0;
      for (const double v : values) mean += v;
      mean /= static_cast<double>(values.size());
      double squares = 0.0;
      for (const double v : values) squares += (v - mean) * (v - mean);
      row.sd = std::sqrt(squares / static_cast<double>(values.size() - 1));
    }
    result.rows.push_back(row);
  }
  return result;
}

}  // namespace

DataUncertaintyResult estimate_data_uncertainty(const PreparedCampaign& campaign, Pool& pool, ProgressMode progress,
                                                std::ostream& log) {
  const Campaign& c = campaign.campaign();
  const std::size_t replicates = c.data_uncertainty.replicates;
  if (replicates == 0) return {};
  const std::size_t samples = data_uncertainty_samples(c);
  const std::uint64_t root = derive_key(mix64(c.seed), "data_uncertainty");

  // One replicate per chunk (tens of milliseconds each): the pool hands them out as processes
  // become free, and replicate b's key depends on b alone.
  StepProgress shown(pool.is_coordinator() ? progress : ProgressMode::none, log, "data uncertainty", "replicate", replicates);
  // rank 0: each replicate's numbers
  const std::vector<std::vector<double>> numbers = run_items(
      pool, replicates, [&](std::size_t b) { return replicate_numbers(campaign, counter_bits(root, b), samples); },
      [&] { shown.advance(1); });
  shown.finish();

  DataUncertaintyResult result;
  on_coordinator(pool, [&] { result = summarize_replicates(campaign, numbers); });
  return result;
}

std::vector<std::string> data_uncertainty_sources(const PreparedCampaign& campaign) {
  const auto listed = [](const std::string& list, const std::string& item) { return list.empty() ? item : list + ", " + item; };
  std::vector<std::string> sources;
  for (const PreparedLine& line : campaign.lines()) {
    // The sampled variables, and the reference line's v_exp, whose median calibrates kappa.
    std::vector<LineVariable> variables = line.design_variables.variables;
    const LineVariable* v_exp = line.distributions.find("v_exp");
    if (campaign.calibrates_kappa() && line.campaign_line.name == campaign.campaign().reference_line && v_exp != nullptr &&
        line.design_variables.find("v_exp") == nullptr) {
      variables.push_back(*v_exp);
    }
    std::string redrawn, fixed;
    for (const LineVariable& variable : variables) {
      if (line.raw_fit) {
        for (const VariableFit& fit : line.raw_fit->variables) {
          if (fit.variable != variable.name) continue;
          redrawn = listed(redrawn, variable.name + " (n = " + std::to_string(fit.values.size()) +
                                        (fit.uncertainties.empty() ? ")" : ", each drawn within its tube's measurement "
                                                                           "uncertainty: the interval includes measurement error)"));
        }
      } else if (variable.tubes > 0) {
        redrawn = listed(redrawn, variable.name + " (tubes = " + std::to_string(variable.tubes) + ", " +
                                      std::string(family_name(variable.distribution)) + ")");
      } else {
        fixed = listed(fixed, variable.name);
      }
    }
    std::string text = line.campaign_line.name + (line.raw_fit ? " (raw data): " : " (line file): ");
    if (!redrawn.empty()) {
      text += redrawn + (line.raw_fit ? " redrawn and refitted by least AIC" : " redrawn and refitted within their family");
    }
    if (!fixed.empty()) text += (redrawn.empty() ? "" : "; ") + std::string("fixed (no tubes stated): ") + fixed;
    sources.push_back(text);
  }
  return sources;
}

DataUncertaintyResult estimate_data_uncertainty(const PreparedCampaign& campaign) {
  const std::unique_ptr<Pool> pool = make_serial_pool();
  return estimate_data_uncertainty(campaign, *pool, ProgressMode::none, std::cerr);
}

}  // namespace growthuq
