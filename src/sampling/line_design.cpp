#include "growthuq/sampling/line_design.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>

#include "growthuq/core/error.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "sampling/large_buffer.hpp"
#include "sampling/latin_column.hpp"

namespace growthuq {

LineDesign latin_hypercube_design(std::string_view line_name, const std::vector<DesignVariable>& variables,
                                  const SamplingOptions& options, const ImanConoverTarget* target) {
  const std::size_t n = options.samples;
  const std::size_t m = variables.size();
  if (n == 0 || n > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("latin_hypercube_design: n must be in [1, 2^32 - 1]");
  }
  LineDesign design;
  design.ranks.resize(m);
  design.values.resize(m);
  // Every column's permutation first; each generator is kept where the permutation left it,
  // to draw the stratum points after Iman-Conover (the same numbers as latin_hypercube_column).
  std::vector<std::unique_ptr<detail::Mt19937_64Block>> random(m);
  for (std::size_t j = 0; j < m; ++j) {
    design.names.push_back(variables[j].name);
    random[j] = std::make_unique<detail::Mt19937_64Block>(stream_key(options.seed, line_name, variables[j].name));
    detail::resize_large(design.ranks[j], n);
    detail::shuffle_strata(design.ranks[j], *random[j]);
  }
  if (target != nullptr) {
    design.target = *target;
    if (target->repaired) design.warnings.push_back(target->warning);
    design.correlation = iman_conover(design.ranks, target->normal_correlation);
    if (!design.correlation.imposed) design.warnings.push_back("warning: " + design.correlation.message);
  } else {
    design.correlation.imposed = false;
  }
  // Values by stratum: the quantile of stratum k's point, computed a block of strata at a time
  // from the points (which never exist as a whole column). The quantile is non-decreasing, so a
  // sample's value follows from its rank by a lookup, without sorting.
  constexpr std::size_t block = 2048;
  detail::LargeBuffer<double> value_by_stratum(n);
  double points[block];
  for (std::size_t j = 0; j < m; ++j) {
    for (std::size_t first = 0; first < n; first += block) {
      const std::size_t count = std::min(block, n - first);
      detail::stratum_points(*random[j], n, first, std::span<double>(points, count), options.position);
      quantiles(variables[j].distribution, std::span<const double>(points, count),
                std::span<double>(value_by_stratum.data() + first, count));
    }
    detail::resize_large(design.values[j], n);
    const std::uint32_t* rank = design.ranks[j].data();
    const double* lookup = value_by_stratum.data();
    double* out = design.values[j].data();
    // A random gather: prefetching a fixed distance ahead keeps enough cache misses in flight.
    constexpr std::size_t prefetch_distance = 48;
    std::size_t i = 0;
    for (; i + prefetch_distance < n; ++i) {
      __builtin_prefetch(lookup + rank[i + prefetch_distance]);
      out[i] = lookup[rank[i]];
    }
    for (; i < n; ++i) out[i] = lookup[rank[i]];
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
