#include "campaign/line_sobol.hpp"

#include <algorithm>
#include <cstdio>

#include "campaign/line_model.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "sensitivity/table_text.hpp"

namespace growthuq {
namespace {

std::string table(const LineSobol& sobol, const Eigen::MatrixXd& value, const Eigen::MatrixXd& low, const Eigen::MatrixXd& high) {
  std::size_t name_width = 0;
  for (const std::string& input : sobol.inputs) name_width = std::max(name_width, input.size());
  name_width += 4;
  std::size_t cell = 22;
  for (const std::string& output : sobol.outputs) cell = std::max(cell, output.size() + 2);
  std::string text(name_width, ' ');
  for (const std::string& output : sobol.outputs) text += padded_left(output, cell);
  text += "\n";
  for (std::size_t i = 0; i < sobol.inputs.size(); ++i) {
    std::string row = "    " + sobol.inputs[i];
    row += std::string(name_width - row.size(), ' ');
    for (std::size_t o = 0; o < sobol.outputs.size(); ++o) {
      const auto r = static_cast<Eigen::Index>(i), c = static_cast<Eigen::Index>(o);
      row += padded_left(two_decimals(value(r, c)) + " [" + two_decimals(low(r, c)) + ", " + two_decimals(high(r, c)) + "]", cell);
    }
    text += row + "\n";
  }
  return text;
}

}  // namespace

LineSobol line_sobol(const PreparedCampaign& campaign, const LineResult& result, const SensitivitySettings& settings) {
  LineSobol sobol;
  sobol.line = result.name;
  const PreparedLine& line = prepared_line(campaign, result.name);
  for (const LineVariable& variable : line.design_variables.variables) sobol.inputs.push_back(column_name(variable.name, *variable.unit));
  for (const ResultColumn& column : result.columns) {
    if (!column.is_input) sobol.outputs.push_back(column.column_name());
  }
  if (line.correlation) {
    sobol.note = "no Sobol indices: the inputs of line '" + result.name + "' are rank-correlated (rank_correlation = " +
                 (line.campaign_line.correlation == CorrelationSource::physics ? std::string("physics")
                                                                               : line.campaign_line.correlation_path) +
                 "), and the Saltelli/Jansen estimators assume independent inputs; use "
                 "[sensitivity] method = shapley";
    return sobol;
  }
  if (campaign.campaign().fidelity_of(line.campaign_line) == Fidelity::shell_fe) {
    sobol.note = "no Sobol indices: fidelity shell_fe would take a finite-element solve per model run";
    return sobol;
  }
  if (sobol.inputs.size() < 2 || sobol.outputs.empty()) {
    sobol.note = "no Sobol indices: they need two inputs or more and an output";
    return sobol;
  }
  SobolSettings cost = settings.sobol_cost;
  cost.key = stream_key(campaign.campaign().seed, result.name, "sobol");
  sobol.indices = sobol_indices(line_model(campaign, line), line_marginals(line), cost);
  sobol.computed = true;
  return sobol;
}

std::string format_line_sobol(const LineSobol& sobol) {
  if (!sobol.computed) return "  note: " + sobol.note + "\n";
  const SobolIndices& s = sobol.indices;
  return "  Sobol first-order indices (Saltelli et al. 2010; independent inputs), " + std::to_string(s.model_runs) +
         " model runs, with their 95 % interval:\n" + table(sobol, s.first, s.first_low, s.first_high) +
         "  Sobol total indices (Jansen 1999):\n" + table(sobol, s.total, s.total_low, s.total_high);
}

}  // namespace growthuq
