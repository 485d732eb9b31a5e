// Benchmark (not a test): a correlated Latin hypercube design of 4 lognormal variables (the
// wild type's k, h, d, d0 of distributions/README.md) with a 4x4 Spearman target: LHS, quantile
// transform and Iman-Conover, single thread. Prints the median time over repetitions, each
// step's share, and the largest |achieved - target| Spearman error. tools/bench/bench-sampling runs
// it side by side with tools/bench/peer_sampling.py, which does the same steps with numpy/scipy.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/core/large_vector.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/correlation/iman_conover.hpp"
#include "growthuq/correlation/rank_correlation_target.hpp"
#include "growthuq/distributions/families.hpp"
#include "growthuq/sampling/line_design.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/stats/rank_correlation.hpp"
#include "bench_timing.hpp"

using namespace growthuq;
using bench::median;
using bench::thread_cpu_seconds;

namespace {

struct Options {
  std::uint64_t samples = 1'000'000;
  std::uint64_t repeats = 5;
  std::uint64_t seed = 2022;
};

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) throw InputError("bench_sampling", "option " + flag + " needs a value");
    const std::string value = argv[++i];
    if (flag == "--samples") {
      options.samples = parse_count(value, "bench_sampling", "--samples", 5, 4'000'000'000);
    } else if (flag == "--repeats") {
      options.repeats = parse_count(value, "bench_sampling", "--repeats", 1, 1000);
    } else if (flag == "--seed") {
      options.seed = parse_count(value, "bench_sampling", "--seed");
    } else {
      throw InputError("bench_sampling", "unknown option " + flag + " (--samples, --repeats, --seed)");
    }
  }
  return options;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) try {
  const Options options = parse(argc, argv);
  // Same target in tools/bench/peer_sampling.py.
  const std::vector<std::string> names{"k", "h", "d", "d0"};
  const std::vector<DesignVariable> variables{{"k", Lognormal::from_median_iqr(2.87, 0.83)},
                                              {"h", Lognormal::from_median_iqr(145, 31)},
                                              {"d", Lognormal::from_median_iqr(6.56, 1.19)},
                                              {"d0", Lognormal::from_median_iqr(5.35, 1.15)}};
  Eigen::MatrixXd spearman(4, 4);
  spearman << 1.0, 0.25, 0.55, 0.30,  //
      0.25, 1.0, -0.10, 0.05,         //
      0.55, -0.10, 1.0, 0.70,         //
      0.30, 0.05, 0.70, 1.0;
  SamplingOptions sampling;
  sampling.samples = options.samples;
  sampling.seed = options.seed;

  std::vector<double> totals, cpu_totals;
  LineDesign design;
  for (std::uint64_t r = 0; r < options.repeats; ++r) {
    sampling.seed = options.seed + r;
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = thread_cpu_seconds();
    // The target's validation and conversion is part of the work a user's run does.
    const ImanConoverTarget target = make_iman_conover_target(spearman, names, "benchmark");
    design = latin_hypercube_design("wild_type", variables, sampling, &target);
    cpu_totals.push_back(thread_cpu_seconds() - cpu_start);
    totals.push_back(seconds_since(start));
  }

  const Eigen::MatrixXd achieved =
      spearman_matrix_of_ranks({design.ranks[0], design.ranks[1], design.ranks[2], design.ranks[3]});
  const double error = (achieved - spearman).cwiseAbs().maxCoeff();
  design = LineDesign{};  // release it, and the blocks kept for reuse: the peak memory reported is the timed run's
  detail::release_cached_blocks();

  // Step shares, outside the timed runs through the public pieces (thread CPU, median over the
  // repetitions): unit-cube LHS (permutation and points), quantile transform, Iman-Conover on
  // the ranks, and the lookup of each sample's value by its rank. Their sum exceeds the fused
  // design's time, which never stores the points.
  const std::size_t n = options.samples;
  std::vector<double> lhs_times, quantile_times, ic_times, lookup_times;
  for (std::uint64_t r = 0; r < options.repeats; ++r) {
    double start = thread_cpu_seconds();
    std::vector<LatinColumn> columns;
    for (const auto& variable : variables) {
      columns.push_back(latin_hypercube_column(n, stream_key(options.seed + r, "wild_type", variable.name), StratumPosition::random));
    }
    lhs_times.push_back(thread_cpu_seconds() - start);
    start = thread_cpu_seconds();
    std::vector<std::vector<double>> value_by_stratum;
    for (std::size_t j = 0; j < variables.size(); ++j) {
      value_by_stratum.emplace_back(n);
      quantiles(variables[j].distribution, columns[j].u_by_stratum, value_by_stratum[j]);
      std::vector<double>().swap(columns[j].u_by_stratum);
    }
    quantile_times.push_back(thread_cpu_seconds() - start);
    std::vector<std::vector<std::uint32_t>> ranks;
    for (auto& column : columns) ranks.push_back(std::move(column.stratum));
    start = thread_cpu_seconds();
    const ImanConoverTarget target = make_iman_conover_target(spearman, names, "benchmark");
    iman_conover(ranks, target.normal_correlation);
    ic_times.push_back(thread_cpu_seconds() - start);
    start = thread_cpu_seconds();
    for (std::size_t j = 0; j < variables.size(); ++j) {
      std::vector<double> values(n);
      for (std::size_t i = 0; i < n; ++i) values[i] = value_by_stratum[j][ranks[j][i]];
      std::vector<double>().swap(value_by_stratum[j]);
    }
    lookup_times.push_back(thread_cpu_seconds() - start);
  }

  std::printf("samples %llu, repeats %llu, single thread\n", static_cast<unsigned long long>(n),
              static_cast<unsigned long long>(options.repeats));
  std::printf("median_seconds %.6f\n", median(totals));
  std::printf("median_cpu_seconds %.6f\n", median(cpu_totals));
  std::printf("steps_cpu_seconds lhs %.6f quantile %.6f iman_conover %.6f value_lookup %.6f\n", median(lhs_times),
              median(quantile_times), median(ic_times), median(lookup_times));
  std::printf("max_spearman_error %.6f\n", error);
  return 0;
} catch (const InputError& error) {
  std::cerr << "bench_sampling: error: " << error.what() << "\n";
  return 2;
}
