// Benchmark (not a test): the fast per-sample chain of a campaign, thin-shell turgor and
// modulus, viscosity from relaxation distributions, and growth rate, on one SampleBlock of
// physiological random tubes (default 1e7), single thread. Prints samples per second per
// evaluator and for the chain; tools/bench/bench-evaluators builds and runs it. --block-size B
// instead runs the chain block by block (B samples each), as a Monte Carlo driver would;
// --checked yes runs each evaluator through evaluate_checked, as a campaign does (the cost of
// checking the declarations); --fidelity corrected replaces turgor and modulus by the corrected
// closed form (src/correction/README.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/correction/corrected_closed_form.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/growth/growth_rate.hpp"
#include "growthuq/growth/viscosity.hpp"
#include "growthuq/mechanics/thin_shell_evaluators.hpp"
#include "bench_timing.hpp"

using namespace growthuq;
using bench::thread_cpu_seconds;

namespace {

struct Options {
  std::uint64_t samples = 10'000'000;
  std::uint64_t repeats = 3;
  std::uint64_t seed = 2022;
  std::uint64_t block_size = 0;  // 0: all samples in one SampleBlock
  bool checked = false;          // through evaluate_checked
  bool corrected = false;        // fidelity corrected instead of closed_form
};

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) throw InputError("bench_evaluators", "option " + flag + " needs a value");
    const std::string value = argv[++i];
    if (flag == "--samples") {
      options.samples = parse_count(value, "bench_evaluators", "--samples", 1, 1'000'000'000);
    } else if (flag == "--repeats") {
      options.repeats = parse_count(value, "bench_evaluators", "--repeats", 1, 1000);
    } else if (flag == "--seed") {
      options.seed = parse_count(value, "bench_evaluators", "--seed");
    } else if (flag == "--block-size") {
      options.block_size = parse_count(value, "bench_evaluators", "--block-size");
    } else if (flag == "--checked") {
      if (value != "yes" && value != "no") throw_bad_value("bench_evaluators", flag, value, "yes or no");
      options.checked = value == "yes";
    } else if (flag == "--fidelity") {
      if (value != "closed_form" && value != "corrected") throw_bad_value("bench_evaluators", flag, value, "closed_form or corrected");
      options.corrected = value == "corrected";
    } else {
      throw InputError("bench_evaluators",
                       "unknown option " + flag + " (--samples, --repeats, --seed, --block-size, --checked, --fidelity)");
    }
  }
  return options;
}

// Lognormal from a published median and IQR (Eq. (D1), src/distributions/README.md):
// sigma = asinh(r/(2m))/z.
std::lognormal_distribution<double> lognormal(double median, double iqr) {
  const double z = 0.6744897501960817;
  return std::lognormal_distribution<double>(std::log(median), std::asinh(iqr / (2 * median)) / z);
}

// Wild-type-like tubes (distributions/README.md), SI, as one block of `size` samples drawn from
// `engine`. d = lambda d0 with lambda uniform in the physiological 1.02-1.4, so the thin-shell
// inverse is defined; einf normal (IQR 18.2 %) restricted to [0.05, 0.95].
SampleBlock physiological_tubes(std::mt19937_64& engine, std::size_t size) {
  auto k = lognormal(2.87, 0.83);
  auto d0 = lognormal(5.35e-6, 1.15e-6);
  auto h = lognormal(145e-9, 31e-9);
  auto tau = lognormal(6.81, 3.61);
  std::uniform_real_distribution<double> lambda(1.02, 1.4);
  std::normal_distribution<double> einf(0.65, 0.182 / 1.3489795003921634);
  SampleBlock block(size);
  const std::span<double> columns[6] = {block.add_column("k"), block.add_column("d"), block.add_column("d0"),
                                        block.add_column("h"), block.add_column("tau"), block.add_column("einf")};
  for (std::size_t i = 0; i < size; ++i) {
    columns[0][i] = k(engine);
    columns[2][i] = d0(engine);
    columns[1][i] = lambda(engine) * columns[2][i];
    columns[3][i] = h(engine);
    columns[4][i] = tau(engine);
    double e = einf(engine);
    while (e < 0.05 || e > 0.95) e = einf(engine);
    columns[5][i] = e;
  }
  return block;
}

// Peak resident memory of this process (Linux /proc), in MiB; 0 when unavailable.
double peak_memory_mib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  }
  return 0.0;
}

}  // namespace

int main(int argc, char** argv) try {
  const Options options = parse(argc, argv);
  const std::size_t n = options.samples;
  const double count = static_cast<double>(n);
  std::printf("building %zu physiological samples (seed %llu)...\n", n,
              static_cast<unsigned long long>(options.seed));
  const std::size_t block_size = options.block_size == 0 ? n : std::min<std::size_t>(options.block_size, n);
  std::mt19937_64 engine(options.seed);
  std::vector<SampleBlock> blocks;
  for (std::size_t first = 0; first < n; first += block_size) {
    blocks.push_back(physiological_tubes(engine, std::min(block_size, n - first)));
  }
  std::printf("%zu block(s) of up to %zu samples\n", blocks.size(), block_size);

  Instrument shell;
  shell.probe_radius_m = 0.5e-6;  // a typical CFM probe (src/mechanics/README.md: 0.1-2 um)
  const ThinShellTurgor turgor(shell, "bench_evaluators");
  const ThinShellModulus modulus;
  const ViscosityEvaluator viscosity;
  const GrowthEvaluator growth({.p0 = 0.05e6, .kappa = 1.0});
  std::vector<const Evaluator*> chain{&turgor, &modulus, &viscosity, &growth};
  std::optional<CorrectedTurgorModulus> corrected;
  if (options.corrected) {
    corrected.emplace(shell, ShellFeOptions{}, "bench_evaluators");
    chain = {&*corrected, &viscosity, &growth};
  }
  const std::size_t stages = chain.size();

  // CPU seconds per stage per repeat, and wall seconds per repeat. Repeat 1 includes
  // allocating and first touching the output columns (as a campaign's single pass would);
  // later repeats reuse them.
  std::vector<std::vector<double>> seconds(options.repeats, std::vector<double>(stages, 0.0));
  std::vector<double> wall(options.repeats);
  for (std::size_t r = 0; r < options.repeats; ++r) {
    for (SampleBlock& block : blocks) std::fill(block.status().begin(), block.status().end(), SampleStatus::ok);
    const auto wall_start = std::chrono::steady_clock::now();
    for (SampleBlock& block : blocks) {
      for (std::size_t s = 0; s < stages; ++s) {
        const double start = thread_cpu_seconds();
        if (options.checked) {
          evaluate_checked(*chain[s], block);
        } else {
          chain[s]->evaluate(block);
        }
        seconds[r][s] += thread_cpu_seconds() - start;
      }
    }
    wall[r] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  }

  constexpr int codes = static_cast<int>(last_sample_status) + 1;
  std::size_t counts[codes] = {};
  for (const SampleBlock& block : blocks) {
    for (SampleStatus status : block.status()) ++counts[static_cast<int>(status)];
  }
  std::printf("statuses:");
  for (int s = 0; s < codes; ++s) {
    if (counts[s] > 0) {
      std::printf(" %s %zu", std::string(to_string(static_cast<SampleStatus>(s))).c_str(), counts[s]);
    }
  }
  std::printf("\n\nmillions of samples per CPU second\n%-20s %14s %14s\n", "evaluator", "first pass", "best");
  double first_total = 0, best_total = 1e300;
  for (std::size_t s = 0; s < stages; ++s) {
    double best = 1e300;
    for (const auto& run : seconds) best = std::min(best, run[s]);
    std::printf("%-20s %14.2f %14.2f\n", std::string(chain[s]->name()).c_str(), 1e-6 * count / seconds[0][s],
                1e-6 * count / best);
    first_total += seconds[0][s];
  }
  for (const auto& run : seconds) {
    double total = 0;
    for (double t : run) total += t;
    best_total = std::min(best_total, total);
  }
  std::printf("%-20s %14.2f %14.2f\n", "chain", 1e-6 * count / first_total, 1e-6 * count / best_total);
  std::printf("\nchain: %.3g samples/s/core (CPU time, best of %llu; first pass %.3g); "
              "wall clock best %.3g samples/s; peak memory %.0f MiB\n",
              count / best_total, static_cast<unsigned long long>(options.repeats), count / first_total,
              count / *std::min_element(wall.begin(), wall.end()), peak_memory_mib());
  return 0;
} catch (const InputError& error) {
  std::cerr << "bench_evaluators: error: " << error.what() << "\n";
  return 2;
}
