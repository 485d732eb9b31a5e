// growthuq sample: the correlated Latin hypercube design of one plant line, written as CSV
// (one column per variable, named <name>_<unit>, values in the line file's unit), with a
// summary of each variable and of the achieved rank correlation on stdout.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <limits>
#include <optional>
#include <string>

#include "commands.hpp"
#include "growthuq/campaign/run_footprint.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/printable.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/correlation/matrix_file.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/sampling/line_design.hpp"
#include "growthuq/stats/rank_correlation.hpp"
#include "growthuq/stats/sample_summary.hpp"
#include "options.hpp"
#include "result_output.hpp"

namespace growthuq::cli {

namespace {

struct SampleOptions {
  std::string line_file;
  std::string samples;
  std::string seed;
  std::string rank_correlation_file;  // empty: uncorrelated design
  bool centred = false;
  std::string out;
  bool force = false;
};

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

std::string padded(const std::string& text, std::size_t width) {
  return text.size() >= width ? text + " " : text + std::string(width - text.size(), ' ');
}

// The design as CSV, streamed a row at a time through a partial file (output_file.hpp), or to
// standard output for "-", so the text is never in memory whole.
void write_design_csv(const std::string& path, const LineDistributions& line, const LineDesign& design) {
  std::optional<PartialFile> file;
  if (!is_standard_output(path)) file.emplace(path);
  const auto write = [&file](const std::string& text) {
    if (file) {
      file->write(text);
    } else {
      std::cout << text;
    }
  };
  std::string row;
  for (const LineVariable& variable : line.variables) {
    row += (row.empty() ? "" : ",") + csv_cell(column_name(variable.name, *variable.unit));
  }
  write(row + "\n");
  const std::size_t n = design.values.empty() ? 0 : design.values[0].size();
  for (std::size_t i = 0; i < n; ++i) {
    row.clear();
    for (std::size_t j = 0; j < design.values.size(); ++j) {
      if (j > 0) row += ',';
      row += format_double(design.values[j][i]);
    }
    row += '\n';
    write(row);
  }
  if (file) file->commit();
}

// Column j's summary. When its values strictly increase with the strata, stratum k holds the
// k-th smallest value, so the sorted column is a scatter by stratum, no sort.
SampleSummary column_summary(const LineDesign& design, std::size_t j) {
  if (design.strictly_increasing[j] == 0) return summarize(design.values[j]);
  const std::size_t n = design.values[j].size();
  std::vector<double> sorted(n);
  for (std::size_t i = 0; i < n; ++i) sorted[design.ranks[j][i]] = design.values[j][i];
  return summarize_sorted(sorted);
}

std::string correlation_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%+.3f", value);
  return text;
}

void print_summary(const LineDistributions& line, const LineDesign& design, std::ostream& report) {
  std::size_t law_width = 14;
  for (const LineVariable& variable : line.variables) law_width = std::max(law_width, describe(variable.distribution).size() + 2);
  report << padded("variable", 10) << padded("unit", 8) << padded("distribution", law_width) << padded("median", 11)
            << padded("(law)", 11) << padded("IQR", 11) << "(law)\n";
  for (std::size_t j = 0; j < line.variables.size(); ++j) {
    const LineVariable& variable = line.variables[j];
    const SampleSummary sample = column_summary(design, j);
    const double law_q1 = quantile(variable.distribution, 0.25);
    const double law_q3 = quantile(variable.distribution, 0.75);
    report << padded(variable.name, 10) << padded(std::string(variable.unit->symbol), 8)
              << padded(describe(variable.distribution), law_width) << padded(number(sample.median), 11)
              << padded(number(quantile(variable.distribution, 0.5)), 11) << padded(number(sample.iqr()), 11)
              << number(law_q3 - law_q1) << "\n";
  }
  const std::size_t m = design.ranks.size();
  if (m < 2 || design.ranks[0].size() < 2) return;
  // Pairs with a target are listed one by one; pairs meant to be independent are summarized by
  // their largest achieved correlation, which shows the design's chance correlation.
  std::vector<std::span<const std::uint32_t>> ranks(design.ranks.begin(), design.ranks.end());
  const Eigen::MatrixXd achieved = spearman_matrix_of_ranks(ranks);
  report << "\n" << padded("rank correlation (Spearman)", 30) << padded("target", 10) << "achieved\n";
  double largest_independent = 0;
  std::size_t independent_pairs = 0;
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t b = a + 1; b < m; ++b) {
      const auto ia = static_cast<Eigen::Index>(a);
      const auto ib = static_cast<Eigen::Index>(b);
      const double target = design.target ? design.target->target_spearman(ia, ib) : 0.0;
      if (target == 0.0) {
        largest_independent = std::max(largest_independent, std::abs(achieved(ia, ib)));
        ++independent_pairs;
        continue;
      }
      report << padded(design.names[a] + ", " + design.names[b], 30) << padded(correlation_number(target), 10)
                << correlation_number(achieved(ia, ib)) << "\n";
    }
  }
  if (independent_pairs > 0) {
    report << padded("other " + std::to_string(independent_pairs) + " pairs", 30) << padded(correlation_number(0.0), 10)
              << "largest |achieved| " << number(largest_independent) << "\n";
  }
}

}  // namespace

int run_sample(const Arguments& arguments) {
  SampleOptions options;
  po::options_description described("options");
  described.add_options()
      ("line", po::value(&options.line_file)->required(), "plant line distribution file (INI)")
      ("samples", po::value(&options.samples)->required(), "number of samples N (1 to 4294967295)")
      ("seed", po::value(&options.seed)->required(), "campaign seed (0 to 2^64 - 1)")
      ("rank-correlation", po::value(&options.rank_correlation_file),
       "CSV matrix of Spearman targets (header of variable names, one row per variable)")
      ("centered", po::bool_switch(&options.centred), "put each point at its stratum's centre instead of at random")
      ("out", po::value(&options.out)->required(), "design CSV to write")
      ("force", po::bool_switch(&options.force), "overwrite --out if it exists");
  po::variables_map values;
  if (!parse_arguments(arguments, "sample", "--line FILE --samples N --seed S --out design.csv [options]",
                       "Draws a Latin hypercube design of a plant line's variables, with an optional rank\n"
                       "correlation imposed by Iman-Conover, and writes it as CSV.",
                       described, {}, values)) {
    return 0;
  }
  SamplingOptions sampling;
  sampling.samples = parse_count(options.samples, "growthuq sample", "--samples", 1,
                                 std::numeric_limits<std::uint32_t>::max());
  sampling.seed = parse_count(options.seed, "growthuq sample", "--seed");
  sampling.position = options.centred ? StratumPosition::centred : StratumPosition::random;
  const Overwrite overwrite = options.force ? Overwrite::allow : Overwrite::refuse;
  check_result_target(options.out, overwrite);

  const LineDistributions line = read_line_file(options.line_file);
  // A design this machine cannot hold is refused now rather than killed part way (run_footprint.hpp).
  require_room(estimate_design_footprint(sampling.samples, line.variables.size()),
               machine_room(1, options.out), "growthuq sample", "--samples");
  std::optional<RankCorrelationFile> correlation;
  if (!options.rank_correlation_file.empty()) correlation = read_rank_correlation_csv(options.rank_correlation_file);

  const LineDesign design = sample_line(line, sampling, correlation ? &*correlation : nullptr);
  for (const std::string& warning : design.warnings) std::cerr << "growthuq sample: " << printable(warning) << "\n";
  write_design_csv(options.out, line, design);

  std::ostream& report = report_stream(options.out);
  report << "line '" << line.name << "' (" << line.path << "): " << sampling.samples << " samples, seed "
            << sampling.seed << ", " << (options.centred ? "centred" : "random") << " points in the strata"
            << (design.correlation.imposed ? ", rank correlation imposed (Iman-Conover)" : "") << "\n"
            << wrote(options.out) << "\n\n";
  print_summary(line, design, report);
  return 0;
}

}  // namespace growthuq::cli
