// The Monte Carlo design of one plant line: a Latin hypercube over the line's variables, mapped
// through each marginal's quantile and, when a rank correlation target is given, reordered by
// Iman-Conover. Columns are struct-of-arrays, in the unit the line file gives each variable.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "growthuq/core/large_vector.hpp"
#include "growthuq/correlation/iman_conover.hpp"
#include "growthuq/correlation/matrix_file.hpp"
#include "growthuq/correlation/rank_correlation_target.hpp"
#include "growthuq/distributions/distribution.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/sampling/latin_hypercube.hpp"

namespace growthuq {

struct SamplingOptions {
  std::size_t samples = 1000;  // 1 .. 2^32 - 1
  std::uint64_t seed = 0;      // campaign seed
  StratumPosition position = StratumPosition::random;
};

struct DesignVariable {
  std::string name;
  Distribution distribution;
};

struct LineDesign {
  std::vector<std::string> names;
  std::vector<LargeVector<std::uint32_t>> ranks;  // ranks[j][i]: stratum (= 0-based rank) of sample i in variable j
  std::vector<LargeVector<double>> values;        // values[j][i]: quantile of variable j at sample i's point
  // strictly_increasing[j] != 0: variable j's values strictly increase with the stratum (no two
  // samples share a value), so its strata are also the exact ranks of its values. (Not so when
  // a quantile is flat or two strata's points round to one value, e.g. an empirical law.)
  std::vector<std::uint8_t> strictly_increasing;
  std::optional<ImanConoverTarget> target;        // over `names`, when a correlation was requested
  ImanConoverOutcome correlation;                 // imposed or not, and why not
  std::vector<std::string> warnings;              // for stderr: repaired target, correlation not imposed
};

// The design of variables `variables` of line `line_name`: column j comes from the stream
// stream_key(seed, line_name, variables[j].name) (random_stream.hpp), so it does not depend on
// the other variables; `target` (over the same variables, in order) reorders the columns
// (Iman-Conover; the first column keeps its order, and a variable added at the end leaves the
// others unchanged).
LineDesign latin_hypercube_design(std::string_view line_name, const std::vector<DesignVariable>& variables,
                                  const SamplingOptions& options, const ImanConoverTarget* target);

// The same design, a column at a time: the constructor does what every column needs (for a
// correlated design the shuffled score columns and Iman-Conover's mix, about a fifth of the
// work); compute_column(j) then gives column j from that alone, in any order, on any thread.
class LineDesigner {
 public:
  LineDesigner(std::string_view line_name, std::vector<DesignVariable> variables, const SamplingOptions& options,
               const ImanConoverTarget* target);
  LineDesigner(const LineDesigner&) = delete;
  LineDesigner& operator=(const LineDesigner&) = delete;
  ~LineDesigner();

  std::size_t columns() const;

  // The design without its columns: names, target, outcome, warnings; ranks and values hold
  // columns() empty vectors.
  const LineDesign& outline() const { return outline_; }

  // Column j (LineDesign::ranks[j] and values[j]); returns LineDesign::strictly_increasing[j].
  // Thread-safe.
  bool compute_column(std::size_t j, LargeVector<std::uint32_t>& ranks, LargeVector<double>& values) const;

 private:
  struct Preparation;
  std::unique_ptr<Preparation> preparation_;
  LineDesign outline_;
};

// The design of a line file's variables. `correlation` may name a subset of them (the others
// are uncorrelated with everything); a name the line lacks is an InputError naming the file.
LineDesign sample_line(const LineDistributions& line, const SamplingOptions& options,
                       const RankCorrelationFile* correlation);

}  // namespace growthuq
