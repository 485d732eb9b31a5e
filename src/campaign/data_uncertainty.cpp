#include "growthuq/campaign/data_uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "growthuq/core/error.hpp"
#include "growthuq/core/large_vector.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/growth/kappa.hpp"
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
    RandomStream stream(derive_key(key, line.campaign_line.name + "/" + fit.variable));
    std::vector<double> values(fit.values.size());
    for (double& value : values) value = quantile(fit.best().distribution, stream.uniform_open());
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
    if (refitted == nullptr) throw std::logic_error("refitted line lacks " + variable.name);
    variable.unit = refitted->unit;
    variable.distribution = refitted->distribution;
  }
  return result;
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
  const std::vector<std::string>& computed = campaign.computed_outputs();
  ReplicateLine result;
  for (std::size_t i = 0; i < samples; ++i) {
    result.status.push_back(static_cast<SampleStatus>(static_cast<int>(values[computed.size() * samples + i])));
  }
  for (const std::string& output : c.outputs) {
    const auto& variables = line.design_variables.variables;
    const auto input = std::find_if(variables.begin(), variables.end(), [&](const LineVariable& v) { return v.name == output; });
    if (input != variables.end()) {
      result.outputs.push_back(ResultColumn{output, input->unit, true,
                                            design.values[static_cast<std::size_t>(input - variables.begin())]});
      continue;
    }
    const auto computed_index = std::find(computed.begin(), computed.end(), output);
    if (computed_index == computed.end()) continue;
    const Unit& unit = find_unit(find_quantity(output)->default_unit, "quantity table", output);
    const std::size_t o = static_cast<std::size_t>(computed_index - computed.begin());
    LargeVector<double> column(values.begin() + static_cast<std::ptrdiff_t>(o * samples),
                               values.begin() + static_cast<std::ptrdiff_t>((o + 1) * samples));
    for (double& value : column) value /= unit.to_si;
    result.outputs.push_back(ResultColumn{output, &unit, false, std::move(column)});
  }
  return result;
}

ResultColumn* column_of(ReplicateLine& line, std::string_view quantity) {
  for (ResultColumn& column : line.outputs) {
    if (column.quantity == quantity) return &column;
  }
  return nullptr;
}

// v *= kappa on growing samples, as the campaign applies its kappa (campaign_run.cpp).
void scale_growth(ReplicateLine& line, double kappa) {
  ResultColumn* v = column_of(line, "v");
  if (v == nullptr) return;
  for (std::size_t i = 0; i < v->values.size(); ++i) {
    if (line.status[i] != SampleStatus::ok) continue;
    v->values[i] *= kappa;
    if (!std::isnormal(v->values[i])) {
      v->values[i] = std::numeric_limits<double>::quiet_NaN();
      line.status[i] = SampleStatus::out_of_range;
    }
  }
}

// One replicate: the medians of every line's outputs (NaN where no sample counts), lines in
// run order, so the reference line calibrates kappa before the others use it.
std::vector<std::vector<QuantitySummary>> replicate_summaries(const PreparedCampaign& campaign, std::uint64_t key,
                                                              std::size_t samples) {
  const Campaign& c = campaign.campaign();
  double kappa = 1.0;
  std::vector<std::vector<QuantitySummary>> summaries;
  for (const PreparedLine& original : campaign.lines()) {
    PreparedLine line = original;
    std::optional<LineDistributions> refit;
    if (original.raw_fit) {
      refit = refitted_line(original, key);
      line.design_variables = with_laws(original.design_variables, *refit);
    }
    ReplicateLine result = evaluate_replicate_line(campaign, line, key, samples);
    if (campaign.calibrates_kappa()) {
      if (original.campaign_line.name == c.reference_line) {
        const LineDistributions& laws = refit ? *refit : original.distributions;
        const LineVariable* v_exp = laws.find("v_exp");
        ResultColumn* v = column_of(result, "v");
        std::vector<double> v_si(v->values.begin(), v->values.end());
        for (double& value : v_si) value *= v->unit->to_si;
        kappa = calibrate_kappa(c.reference_line, quantile(v_exp->distribution, 0.5) * v_exp->unit->to_si,
                                median_growth_rate(v_si, result.status));
      }
      scale_growth(result, kappa);
    }
    std::vector<QuantitySummary> line_summaries;
    for (const ResultColumn& column : result.outputs) {
      line_summaries.push_back(summarize_quantity(original.campaign_line.name, column, result.status));
    }
    summaries.push_back(std::move(line_summaries));
  }
  return summaries;
}

}  // namespace

DataUncertaintyResult estimate_data_uncertainty(const PreparedCampaign& campaign) {
  const Campaign& c = campaign.campaign();
  DataUncertaintyResult result;
  const std::size_t replicates = c.data_uncertainty.replicates;
  if (replicates == 0) return result;
  const std::size_t samples = c.data_uncertainty.samples > 0 ? c.data_uncertainty.samples : c.samples;
  const std::uint64_t root = derive_key(mix64(c.seed), "data_uncertainty");

  std::vector<std::vector<QuantitySummary>> layout;      // rows of the first successful replicate
  std::vector<std::vector<std::vector<double>>> medians;  // [line][output][replicate]
  std::size_t failed_replicates = 0;
  for (std::size_t b = 0; b < replicates; ++b) {
    std::vector<std::vector<QuantitySummary>> summaries;
    try {
      summaries = replicate_summaries(campaign, counter_bits(root, b), samples);
    } catch (const InputError& error) {
      ++failed_replicates;
      if (result.failures.size() < 5) result.failures.push_back("replicate " + std::to_string(b) + ": " + error.what());
      continue;
    }
    if (layout.empty()) {
      layout = summaries;
      for (const auto& line : summaries) medians.emplace_back(line.size());
    }
    for (std::size_t l = 0; l < summaries.size(); ++l) {
      for (std::size_t q = 0; q < summaries[l].size() && q < medians[l].size(); ++q) {
        if (std::isfinite(summaries[l][q].median)) medians[l][q].push_back(summaries[l][q].median);
      }
    }
  }
  for (std::size_t l = 0; l < layout.size(); ++l) {
    for (std::size_t q = 0; q < layout[l].size(); ++q) {
      DataUncertainty row;
      row.line = layout[l][q].line;
      row.quantity = layout[l][q].quantity;
      row.unit = layout[l][q].unit;
      row.samples = samples;
      std::vector<double>& values = medians[l][q];
      row.replicate_medians = values;
      row.replicates = values.size();
      row.failed = replicates - values.size();
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
  }
  if (layout.empty() && failed_replicates > 0) {
    throw InputError(c.path, "[data_uncertainty]: every one of " + std::to_string(replicates) +
                                 " replicates failed (" + (result.failures.empty() ? std::string() : result.failures.front()) + ")");
  }
  return result;
}

}  // namespace growthuq
