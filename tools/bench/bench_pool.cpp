// The pool's scheduling alone, with chunks whose cost is a wait rather than arithmetic, so that
// the figure does not depend on what else the machine runs: 150 one-sample chunks (a
// finite-element line at the published scale) of uneven durations, drawn from a lognormal law
// (median 40 ms, log standard deviation 0.8; one in ten five times longer, as a sample that does
// not converge costs several), handed out by the pool with one chunk queued per worker as a
// finite-element line hands them out. Rank 0 prints the wall time, the sum of the durations and
// the ideal time on K processes (the longest-first schedule's, which no order of handing out
// beats by more than a third: Graham 1969).
//   bench_pool [CHUNKS] [MEDIAN_MS]       (under mpirun -np K, or serially)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <thread>
#include <vector>

#include "growthuq/pool/pool.hpp"

using namespace growthuq;

namespace {

std::vector<double> chunk_seconds(std::size_t chunks, double median_seconds) {
  std::mt19937_64 random(2022);
  std::lognormal_distribution<double> duration(std::log(median_seconds), 0.8);
  std::uniform_real_distribution<double> share(0.0, 1.0);
  std::vector<double> seconds(chunks);
  for (double& s : seconds) s = duration(random) * (share(random) < 0.1 ? 5.0 : 1.0);
  return seconds;
}

// Longest first onto the process that frees up first.
double longest_first(std::vector<double> seconds, int processes) {
  std::sort(seconds.begin(), seconds.end(), std::greater<>());
  std::vector<double> busy(static_cast<std::size_t>(processes), 0.0);
  for (const double s : seconds) *std::min_element(busy.begin(), busy.end()) += s;
  return *std::max_element(busy.begin(), busy.end());
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t chunks = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 150;
  const double median_seconds = (argc > 2 ? std::strtod(argv[2], nullptr) : 40.0) * 1e-3;
  const std::vector<double> seconds = chunk_seconds(chunks, median_seconds);
  auto pool = make_pool();
  pool->set_queued_chunks(1);
  const auto start = std::chrono::steady_clock::now();
  pool->run(
      chunks, 1,
      [&](ChunkRange range) {
        std::this_thread::sleep_for(std::chrono::duration<double>(seconds[range.begin]));
        return std::vector<double>{static_cast<double>(range.begin)};
      },
      [](ChunkRange, std::span<const double>) {});
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (pool->is_coordinator()) {
    double total = 0.0;
    for (const double s : seconds) total += s;
    std::printf("processes %d: %zu chunks, wall %.3f s, sum of chunks %.3f s, longest-first schedule %.3f s\n",
                pool->size(), chunks, wall, total, longest_first(seconds, pool->size()));
  }
  return 0;
}
