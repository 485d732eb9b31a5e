// Benchmark (not a test): what each pass over memory that a correlated Latin hypercube design
// cannot do without costs on the machine it runs on, with the engine's own implementation of it, so the
// design's time (tools/bench/bench_sampling.cpp) can be read against the sum of its parts. A design of m
// variables with Iman-Conover needs, at least:
//   m random permutations (LHS strata; for m - 1 of them the van der Waerden scores are
//     shuffled, the other shuffles the strata themselves),
//   m quantile transforms of n stratum points (one uniform each, Phi^-1, exp),
//   m random-order writes of each sample's (stratum, value) pair (a sample's stratum is random),
//   m - 1 sorts of n records (the order of the transformed scores, Iman-Conover's reordering),
//   m - 1 streaming passes mixing 2 to m score columns into the keys of those sorts.
// Prints each pass's median thread CPU seconds at n and their sum for m variables: a lower
// bound on the design's time with these implementations (it leaves out the score correlation,
// the keys' ties and every pass the design adds to join these).
//   bench_sampling_passes [--samples N] [--variables M] [--repeats R]
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/distributions/distribution.hpp"
#include "growthuq/distributions/families.hpp"
#include "sampling/latin_column.hpp"
#include "sampling/mt19937_64_block.hpp"
#include "stats/keyed_sort.hpp"
#include "bench_timing.hpp"

using namespace growthuq;
using bench::median;
using bench::thread_cpu_seconds;

namespace {

struct Options {
  std::uint64_t samples = 1'000'000;
  std::uint64_t variables = 4;
  std::uint64_t repeats = 7;
};

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) throw InputError("bench_sampling_passes", "option " + flag + " needs a value");
    const std::string value = argv[++i];
    if (flag == "--samples") {
      options.samples = parse_count(value, "bench_sampling_passes", "--samples", 1000, 100'000'000);
    } else if (flag == "--variables") {
      options.variables = parse_count(value, "bench_sampling_passes", "--variables", 2, 64);
    } else if (flag == "--repeats") {
      options.repeats = parse_count(value, "bench_sampling_passes", "--repeats", 1, 1000);
    } else {
      throw InputError("bench_sampling_passes", "unknown option " + flag + " (--samples, --variables, --repeats)");
    }
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) try {
  const Options options = parse(argc, argv);
  const std::size_t n = options.samples;
  const std::size_t m = options.variables;
  detail::Mt19937_64Block random(2022);
  const Distribution lognormal = Lognormal::from_median_iqr(2.87, 0.83);

  std::vector<std::uint32_t> permutation(n);
  std::vector<double> scores(n), shuffled(n), points(n), values(n);
  std::iota(scores.begin(), scores.end(), 0.0);
  struct alignas(16) Entry {
    double value;
    std::uint32_t stratum;
  };
  std::vector<Entry> by_sample(n);
  std::vector<std::vector<double>> columns(2, std::vector<double>(n, 0.5));
  std::vector<std::uint64_t> keys(n), records(n), scratch(n);
  std::vector<double> shuffle_strata_s, shuffle_scores_s, quantile_s, scatter_s, sort_s, mix_s;

  for (std::uint64_t r = 0; r < options.repeats; ++r) {
    double start = thread_cpu_seconds();
    detail::shuffle_strata(permutation, random);
    shuffle_strata_s.push_back(thread_cpu_seconds() - start);

    start = thread_cpu_seconds();
    detail::shuffled_copy(scores, shuffled, random);
    shuffle_scores_s.push_back(thread_cpu_seconds() - start);

    start = thread_cpu_seconds();
    detail::stratum_points(random, n, 0, points, StratumPosition::random);
    quantiles(lognormal, points, values);
    quantile_s.push_back(thread_cpu_seconds() - start);

    // Stratum k's pair to sample permutation[k], prefetched as the design does.
    start = thread_cpu_seconds();
    for (std::size_t k = 0; k < n; ++k) {
      if (k + 48 < n) __builtin_prefetch(by_sample.data() + permutation[k + 48], 1);
      by_sample[permutation[k]] = Entry{values[k], static_cast<std::uint32_t>(k)};
    }
    scatter_s.push_back(thread_cpu_seconds() - start);

    // Keys of a transformed score column: a sum of uniforms is bell-shaped like one.
    for (std::size_t i = 0; i < n; ++i) {
      const double bell = static_cast<double>((random() >> 40) + (random() >> 40) + (random() >> 40)) / 3.0;
      keys[i] = detail::keyed_record(static_cast<std::uint32_t>(bell * 256.0), static_cast<std::uint32_t>(i));
    }
    std::copy(keys.begin(), keys.end(), records.begin());
    start = thread_cpu_seconds();
    detail::sort_records(records, scratch, 24);
    sort_s.push_back(thread_cpu_seconds() - start);

    // The mixing of two score columns into one key column (the narrowest of the m - 1 mixes,
    // so the sum below stays a lower bound).
    start = thread_cpu_seconds();
    for (std::size_t i = 0; i < n; ++i) {
      const double x = 0.5 * columns[0][i] + 0.25 * columns[1][i];
      records[i] = detail::keyed_record(static_cast<std::uint32_t>(x * 1e6), static_cast<std::uint32_t>(i));
    }
    mix_s.push_back(thread_cpu_seconds() - start);
  }
  if (records[n / 2] == 42 && by_sample[n / 2].stratum == 42) std::printf(" ");  // keep the passes

  const double passes = median(shuffle_strata_s) + static_cast<double>(m - 1) * median(shuffle_scores_s) +
                        static_cast<double>(m) * (median(quantile_s) + median(scatter_s)) +
                        static_cast<double>(m - 1) * (median(sort_s) + median(mix_s));
  std::printf("samples %zu, variables %zu, repeats %llu, single thread, median thread CPU seconds per pass\n", n, m,
              static_cast<unsigned long long>(options.repeats));
  std::printf("pass_seconds shuffle_strata %.6f shuffle_scores %.6f points_and_quantiles %.6f scatter %.6f sort %.6f mix %.6f\n",
              median(shuffle_strata_s), median(shuffle_scores_s), median(quantile_s), median(scatter_s), median(sort_s),
              median(mix_s));
  std::printf("sum_of_passes_seconds %.6f\n", passes);
  return 0;
} catch (const InputError& error) {
  std::cerr << "bench_sampling_passes: error: " << error.what() << "\n";
  return 2;
}
