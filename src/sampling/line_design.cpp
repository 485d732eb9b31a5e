#include "growthuq/sampling/line_design.hpp"

#include <algorithm>

#include "growthuq/core/error.hpp"
#include "growthuq/sampling/random_stream.hpp"

namespace growthuq {

LineDesign latin_hypercube_design(std::string_view line_name, const std::vector<DesignVariable>& variables,
                                  const SamplingOptions& options, const ImanConoverTarget* target) {
  const std::size_t n = options.samples;
  const std::size_t m = variables.size();
  LineDesign design;
  design.ranks.resize(m);
  design.values.resize(m);
  // Values by stratum: the quantile of stratum k's point. The quantile is non-decreasing, so
  // a sample's value follows from its rank by a lookup, without sorting.
  std::vector<std::vector<double>> value_by_stratum(m);
  for (std::size_t j = 0; j < m; ++j) {
    design.names.push_back(variables[j].name);
    LatinColumn column = latin_hypercube_column(n, stream_key(options.seed, line_name, variables[j].name), options.position);
    design.ranks[j] = std::move(column.stratum);
    value_by_stratum[j].resize(n);
    quantiles(variables[j].distribution, column.u_by_stratum, value_by_stratum[j]);
  }
  if (target != nullptr) {
    design.target = *target;
    if (target->repaired) design.warnings.push_back(target->warning);
    design.correlation = iman_conover(design.ranks, target->normal_correlation);
    if (!design.correlation.imposed) design.warnings.push_back("warning: " + design.correlation.message);
  } else {
    design.correlation.imposed = false;
  }
  for (std::size_t j = 0; j < m; ++j) {
    design.values[j].resize(n);
    const std::uint32_t* rank = design.ranks[j].data();
    const double* lookup = value_by_stratum[j].data();
    double* out = design.values[j].data();
    for (std::size_t i = 0; i < n; ++i) out[i] = lookup[rank[i]];
    std::vector<double>().swap(value_by_stratum[j]);
  }
  return design;
}

LineDesign sample_line(const LineDistributions& line, const SamplingOptions& options,
                       const RankCorrelationFile* correlation) {
  std::vector<DesignVariable> variables;
  std::vector<std::string> names;
  for (const LineVariable& variable : line.variables) {
    variables.push_back({variable.name, variable.distribution});
    names.push_back(variable.name);
  }
  if (correlation == nullptr) return latin_hypercube_design(line.name, variables, options, nullptr);

  // The line's full matrix: the file's entries where it names both variables, 0 elsewhere.
  const auto m = static_cast<Eigen::Index>(names.size());
  Eigen::MatrixXd spearman = Eigen::MatrixXd::Identity(m, m);
  std::vector<Eigen::Index> position(correlation->names.size());
  for (std::size_t a = 0; a < correlation->names.size(); ++a) {
    const auto found = std::find(names.begin(), names.end(), correlation->names[a]);
    if (found == names.end()) {
      std::string known;
      for (const auto& name : names) known += (known.empty() ? "" : ", ") + name;
      throw InputError(file_location(correlation->path, 0),
                       "variable '" + correlation->names[a] + "' is not in line '" + line.name + "' (" + line.path +
                           "), which has " + known);
    }
    position[a] = found - names.begin();
  }
  for (std::size_t a = 0; a < position.size(); ++a) {
    for (std::size_t b = 0; b < position.size(); ++b) {
      spearman(position[a], position[b]) =
          correlation->spearman(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
    }
  }
  const ImanConoverTarget target = make_iman_conover_target(spearman, names, correlation->path);
  return latin_hypercube_design(line.name, variables, options, &target);
}

}  // namespace growthuq
