#include "growthuq/sampling/line_design.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <memory>
#include <span>
#include <stdexcept>

#include "growthuq/core/error.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "correlation/score_reordering.hpp"
#include "sampling/large_buffer.hpp"
#include "sampling/latin_column.hpp"
#include "stats/keyed_sort.hpp"

namespace growthuq {

namespace {

// How many elements ahead random gathers and scatters prefetch: enough cache misses in flight.
constexpr std::size_t prefetch_distance = 48;
// Strata per block of points and quantiles: the points never exist as a whole column.
constexpr std::size_t block = 2048;

// values_by_stratum[k - first] = quantile of stratum k's point, k = first .. first + count - 1,
// the points drawn from `random` (which must be at stratum `first` of its column).
void stratum_values(const DesignVariable& variable, detail::Mt19937_64Block& random, const SamplingOptions& options,
                    std::size_t first, std::span<double> values_by_stratum) {
  double points[block];
  for (std::size_t done = 0; done < values_by_stratum.size(); done += block) {
    const std::size_t count = std::min(block, values_by_stratum.size() - done);
    detail::stratum_points(random, options.samples, first + done, std::span<double>(points, count), options.position);
    quantiles(variable.distribution, std::span<const double>(points, count), values_by_stratum.subspan(done, count));
  }
}

// One column's stratum and value per sample, written in any order of the samples and then
// handed over as the design's two columns. A sample's pair shares a cache line, so a write to a
// random sample costs one cache miss rather than two; the columns then come from one sequential
// pass (1e6 samples: 10 ms for writing both columns at random, 7.6 ms this way, measured).
class ColumnScatter {
 public:
  explicit ColumnScatter(std::size_t n) : entries_(n) {}

  void prefetch(std::uint32_t sample) { __builtin_prefetch(entries_.data() + sample, 1); }
  void put(std::uint32_t sample, std::uint32_t stratum, double value) { entries_[sample] = Entry{value, stratum}; }

  // Every sample must have been put since the last call.
  void hand_over(LargeVector<std::uint32_t>& ranks, LargeVector<double>& values) const {
    const std::size_t n = entries_.size();
    ranks.resize(n);  // not zero-filled (large_vector.hpp): each element is written once, here
    values.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      ranks[i] = entries_[i].stratum;
      values[i] = entries_[i].value;
    }
  }

 private:
  struct alignas(16) Entry {
    double value;
    std::uint32_t stratum;
  };
  detail::LargeBuffer<Entry> entries_;
};

// Writes a column from sample_of_stratum (the shuffled 0, 1, ..., n-1 of the column's stream,
// latin_hypercube.hpp): stratum k and its value go to sample sample_of_stratum[k]. Values are
// computed in stratum order a block at a time, continuing the column's stream.
void write_column(const DesignVariable& variable, detail::Mt19937_64Block& random, const SamplingOptions& options,
                  const std::uint32_t* sample_of_stratum, ColumnScatter& scatter, LargeVector<std::uint32_t>& ranks,
                  LargeVector<double>& values) {
  const std::size_t n = options.samples;
  double by_stratum[block];
  for (std::size_t first = 0; first < n; first += block) {
    const std::size_t count = std::min(block, n - first);
    stratum_values(variable, random, options, first, std::span<double>(by_stratum, count));
    const std::uint32_t* sample = sample_of_stratum + first;
    for (std::size_t k = 0; k < count; ++k) {
      if (first + k + prefetch_distance < n) scatter.prefetch(sample[k + prefetch_distance]);
      scatter.put(sample[k], static_cast<std::uint32_t>(first + k), by_stratum[k]);
    }
  }
  scatter.hand_over(ranks, values);
}

// Every column from its own stream alone.
void independent_columns(std::string_view line_name, const std::vector<DesignVariable>& variables,
                         const SamplingOptions& options, LineDesign& design) {
  const std::size_t n = options.samples;
  detail::LargeBuffer<std::uint32_t> sample_of_stratum(n);
  ColumnScatter scatter(n);
  for (std::size_t j = 0; j < variables.size(); ++j) {
    detail::Mt19937_64Block random(stream_key(options.seed, line_name, variables[j].name));
    detail::shuffle_strata(std::span<std::uint32_t>(sample_of_stratum.data(), n), random);
    write_column(variables[j], random, options, sample_of_stratum.data(), scatter, design.ranks[j], design.values[j]);
  }
}

// Iman-Conover (iman_conover.hpp) fused with the Latin hypercube, in few passes over memory. The
// score matrix is held by rows in the order of variable 0's strata: row r is the sample that
// holds stratum r of variable 0 (sample_of_row, the shuffle of variable 0's stream), so
// column 0 of the score matrix is the table of scores itself, in order. Column j >= 1 is the
// table shuffled by variable j's stream: in sample terms, variable j's initial ranks are its
// permutation composed with variable 0's, as uniformly random and independent of the others as
// a permutation of its own. Iman-Conover then only reorders columns j >= 1 (P Q^-1 is lower
// triangular), whose new order arrives sorted: position p holds stratum p, so each sample's
// stratum and value are written once, values computed in stratum order (no table, no gather).
// Variable 0 is written exactly as in the independent design. Returns false (columns 1.. not
// written) when the sample's score correlation is singular.
bool correlated_columns(std::string_view line_name, const std::vector<DesignVariable>& variables,
                        const SamplingOptions& options, const Eigen::MatrixXd& normal_correlation, LineDesign& design) {
  const std::size_t n = options.samples;
  const std::size_t m = variables.size();
  const Eigen::LLT<Eigen::MatrixXd> target(normal_correlation);
  if (target.info() != Eigen::Success) {
    throw std::invalid_argument("latin_hypercube_design: target correlation is not positive definite");
  }
  const std::shared_ptr<const detail::ScoreTable> table = detail::van_der_waerden_table(n);
  // Each stream is kept where its shuffle left it: the stratum points come next.
  std::vector<std::unique_ptr<detail::Mt19937_64Block>> random(m);
  detail::LargeBuffer<double> shuffled(n * (m - 1));
  std::vector<const double*> columns{table->score.data()};
  for (std::size_t j = 1; j < m; ++j) {
    const std::span<double> column(shuffled.data() + (j - 1) * n, n);
    random[j] = std::make_unique<detail::Mt19937_64Block>(stream_key(options.seed, line_name, variables[j].name));
    detail::shuffled_copy(table->score, column, *random[j]);
    columns.push_back(column.data());
  }

  detail::LargeBuffer<std::uint32_t> sample_of_row(n);
  random[0] = std::make_unique<detail::Mt19937_64Block>(stream_key(options.seed, line_name, variables[0].name));
  detail::shuffle_strata(std::span<std::uint32_t>(sample_of_row.data(), n), *random[0]);
  ColumnScatter scatter(n);
  write_column(variables[0], *random[0], options, sample_of_row.data(), scatter, design.ranks[0], design.values[0]);

  detail::ScoreReordering reordering(columns, *table, target);
  if (!reordering.valid()) return false;
  reordering.set_row_order(std::span<const std::uint32_t>(sample_of_row.data(), n), design.ranks[0]);
  detail::LargeBuffer<std::uint64_t> records(n), scratch(n);
  for (std::size_t j = 1; j < m; ++j) {
    double by_stratum[block];
    reordering.sort_column(j, std::span<std::uint64_t>(records.data(), n), std::span<std::uint64_t>(scratch.data(), n),
                           [&](std::size_t first, std::span<const std::uint64_t> sorted) {
                             // Position first + p of the new order holds stratum first + p.
                             for (std::size_t done = 0; done < sorted.size(); done += block) {
                               const std::size_t count = std::min(block, sorted.size() - done);
                               stratum_values(variables[j], *random[j], options, first + done,
                                              std::span<double>(by_stratum, count));
                               const std::uint64_t* run = sorted.data() + done;
                               for (std::size_t p = 0; p < count; ++p) {
                                 if (p + prefetch_distance < count) scatter.prefetch(detail::record_index(run[p + prefetch_distance]));
                                 scatter.put(detail::record_index(run[p]), static_cast<std::uint32_t>(first + done + p),
                                             by_stratum[p]);
                               }
                             }
                           });
    scatter.hand_over(design.ranks[j], design.values[j]);
  }
  return true;
}

}  // namespace

LineDesign latin_hypercube_design(std::string_view line_name, const std::vector<DesignVariable>& variables,
                                  const SamplingOptions& options, const ImanConoverTarget* target) {
  const std::size_t n = options.samples;
  const std::size_t m = variables.size();
  if (n == 0 || n > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("latin_hypercube_design: n must be in [1, 2^32 - 1]");
  }
  if (target != nullptr && static_cast<std::size_t>(target->normal_correlation.rows()) != m) {
    throw std::invalid_argument("latin_hypercube_design: correlation matrix does not match the number of variables");
  }
  LineDesign design;
  design.ranks.resize(m);
  design.values.resize(m);
  for (const DesignVariable& variable : variables) design.names.push_back(variable.name);
  design.correlation.imposed = false;
  if (target != nullptr) {
    design.target = *target;
    if (target->repaired) design.warnings.push_back(target->warning);
    if (m < 2) {
      design.correlation.imposed = true;
    } else if (n <= m) {
      design.correlation.message = "a rank correlation between " + std::to_string(m) +
                                   " variables cannot be imposed on " + std::to_string(n) +
                                   " samples (it needs more samples than variables); the design is uncorrelated";
    } else if (correlated_columns(line_name, variables, options, target->normal_correlation, design)) {
      design.correlation.imposed = true;
      return design;
    } else {
      design.correlation.message = "the " + std::to_string(n) +
                                   " samples' score correlation is singular; the design is uncorrelated";
    }
    if (!design.correlation.imposed) design.warnings.push_back("warning: " + design.correlation.message);
  }
  independent_columns(line_name, variables, options, design);
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
