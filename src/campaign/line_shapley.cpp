#include "campaign/line_shapley.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "campaign/line_model.hpp"
#include "growthuq/correlation/rank_correlation_target.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "sensitivity/table_text.hpp"

namespace growthuq {
namespace {

// The normal-score correlation of the line's inputs: Iman-Conover's target (the same conversion
// and repair the design made) over the correlated inputs, independence elsewhere.
Eigen::MatrixXd copula_of(const LineResult& result, const std::vector<std::string>& variables) {
  const auto d = static_cast<Eigen::Index>(variables.size());
  Eigen::MatrixXd r = Eigen::MatrixXd::Identity(d, d);
  if (result.target_spearman.size() == 0 || result.correlated_inputs.size() < 2) return r;
  const ImanConoverTarget target = make_iman_conover_target(result.target_spearman, result.correlated_inputs, "line " + result.name);
  const auto index_of = [&](const std::string& name) {
    return static_cast<Eigen::Index>(std::find(variables.begin(), variables.end(), name) - variables.begin());
  };
  for (std::size_t a = 0; a < target.names.size(); ++a) {
    for (std::size_t b = 0; b < target.names.size(); ++b) {
      const Eigen::Index i = index_of(target.names[a]), j = index_of(target.names[b]);
      if (i < d && j < d) r(i, j) = target.normal_correlation(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
    }
  }
  return r;
}

}  // namespace

LineShapley line_shapley(const PreparedCampaign& campaign, const LineResult& result, const SensitivitySettings& settings) {
  LineShapley shapley;
  shapley.line = result.name;
  const PreparedLine& line = prepared_line(campaign, result.name);
  const auto& variables = line.design_variables.variables;
  for (const LineVariable& variable : variables) shapley.inputs.push_back(column_name(variable.name, *variable.unit));
  for (const ResultColumn& column : result.columns) {
    if (!column.is_input) shapley.outputs.push_back(column.column_name());
  }
  if (campaign.campaign().fidelity_of(line.campaign_line) == Fidelity::shell_fe) {
    shapley.note = "no Shapley effects: fidelity shell_fe would take a finite-element solve per model run; run the line "
                   "with fidelity = corrected for them";
    return shapley;
  }
  if (variables.size() < 2 || shapley.outputs.empty()) {
    shapley.note = "no Shapley effects: they need two inputs or more and an output";
    return shapley;
  }
  std::vector<std::string> names;
  for (const LineVariable& variable : variables) names.push_back(variable.name);
  ShapleySettings cost = settings.cost;
  cost.key = stream_key(campaign.campaign().seed, result.name, "shapley");
  shapley.effects = shapley_effects(line_model(campaign, line), line_marginals(line), copula_of(result, names), cost);
  shapley.computed = true;
  return shapley;
}

std::size_t shapley_model_runs(std::size_t inputs, const ShapleySettings& cost) {
  if (inputs < 2) return 0;
  const std::size_t group = cost.outer * cost.inner;
  if (inputs <= 6) return cost.variance_samples + ((std::size_t{1} << inputs) - 2) * group;
  return cost.variance_samples + cost.permutations * (inputs - 1) * group;
}

std::string describe_shapley_cost(const PreparedCampaign& campaign) {
  const SensitivitySettings settings = sensitivity_settings(campaign.campaign());
  if (!settings.shapley) return {};
  std::string text = "sensitivity: Shapley effects by new model runs per line:";
  std::size_t total = 0;
  for (const PreparedLine& line : campaign.lines()) {
    const std::size_t d = line.design_variables.variables.size();
    const bool refused = campaign.campaign().fidelity_of(line.campaign_line) == Fidelity::shell_fe;
    const std::size_t runs = refused ? 0 : shapley_model_runs(d, settings.cost);
    total += runs;
    text += " " + line.campaign_line.name + " " + (refused ? std::string("none (shell_fe)") : std::to_string(runs) + " (" + std::to_string(d) + " inputs)") + ",";
  }
  text.back() = ';';
  const double ratio = static_cast<double>(total) /
                       static_cast<double>(campaign.campaign().samples * std::max<std::size_t>(campaign.lines().size(), 1));
  char times[32];
  std::snprintf(times, sizeof times, "%.1f", ratio);
  return text + " " + times + " times the run's own samples\n";
}

std::string format_line_shapley(const LineShapley& shapley) {
  if (!shapley.computed) return "  note: " + shapley.note + "\n";
  const ShapleyEffects& e = shapley.effects;
  std::string text = "  Shapley effects as shares of Var(output) (each column sums to 1), inputs (rows) x outputs (columns),\n"
                     "  with their 95 % interval; " + std::to_string(e.model_runs) + " model runs, " +
                     (e.exact_permutations ? "exact permutations" : "random permutations") +
                     ", inputs joined by a Gaussian copula of the line's rank correlation:\n";
  std::size_t name_width = 0;
  for (const std::string& input : shapley.inputs) name_width = std::max(name_width, input.size());
  name_width += 4;
  std::size_t cell = 22;
  for (const std::string& output : shapley.outputs) cell = std::max(cell, output.size() + 2);
  text += std::string(name_width, ' ');
  for (const std::string& output : shapley.outputs) text += padded_left(output, cell);
  text += "\n";
  for (std::size_t i = 0; i < shapley.inputs.size(); ++i) {
    std::string row = "    " + shapley.inputs[i];
    row += std::string(name_width - row.size(), ' ');
    for (std::size_t o = 0; o < shapley.outputs.size(); ++o) {
      const auto r = static_cast<Eigen::Index>(i), c = static_cast<Eigen::Index>(o);
      row += padded_left(two_decimals(e.share(r, c)) + " [" + two_decimals(e.share_low(r, c)) + ", " +
                             two_decimals(e.share_high(r, c)) + "]",
                         cell);
    }
    text += row + "\n";
  }
  return text;
}

}  // namespace growthuq
