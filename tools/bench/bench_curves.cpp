// What processing raw force curves costs (src/forcecurves/README.md, Eqs. (C1)-(C9)): `count`
// synthetic curves of `samples` approach samples each (simulate_indentation_curve, drawn before
// the clock starts), each through process_force_curve with the default options (relative window,
// deviation contact, both contact methods, the checks and the sensitivity refits), one thread.
//   bench_curves [--curves N] [--samples S] [--repeats R]
// Prints `median_seconds` (wall), `median_cpu_seconds` (thread CPU), `curves_per_second` and the
// ok count and mean k (a check that the work was done).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "growthuq/forcecurves/curve_processing.hpp"
#include "growthuq/synthetic/indentation_curve.hpp"

using namespace growthuq;

int main(int argc, char** argv) {
  std::size_t count = 10000, samples = 2000, repeats = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    const auto value = static_cast<std::size_t>(std::strtoull(argv[i + 1], nullptr, 10));
    if (flag == "--curves") count = value;
    else if (flag == "--samples") samples = value;
    else if (flag == "--repeats") repeats = value;
    else {
      std::fprintf(stderr, "usage: bench_curves [--curves N] [--samples S] [--repeats R]\n");
      return 2;
    }
  }
  IndentationTruth truth;
  truth.sensor_stiffness = 100.0;
  truth.approach_samples = samples;
  std::vector<ForceCurve> curves;
  curves.reserve(count);
  for (std::size_t c = 0; c < count; ++c) curves.push_back(simulate_indentation_curve(truth, c + 1, "c", "t", 1));

  const CurveProcessingOptions options;
  std::vector<double> walls, cpus;
  std::size_t ok = 0;
  double sum = 0.0;
  for (std::size_t r = 0; r < repeats; ++r) {
    ok = 0;
    sum = 0.0;
    const auto wall = std::chrono::steady_clock::now();
    const double cpu = bench::thread_cpu_seconds();
    for (const ForceCurve& curve : curves) {
      const CurveResult result = process_force_curve(curve, options);
      if (result.status == CurveStatus::ok) {
        ++ok;
        sum += result.stiffness;
      }
    }
    cpus.push_back(bench::thread_cpu_seconds() - cpu);
    walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count());
  }
  std::printf("curves %zu\nsamples %zu\nok %zu\nmean_k_N_per_m %.6f\n", count, samples, ok, ok ? sum / ok : 0.0);
  std::printf("median_seconds %.4f\nmedian_cpu_seconds %.4f\ncurves_per_second %.0f\n", bench::median(walls),
              bench::median(cpus), static_cast<double>(count) / bench::median(walls));
  return 0;
}
