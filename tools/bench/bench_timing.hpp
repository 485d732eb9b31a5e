// What the benchmark programs in tools/bench/ time with: the calling thread's CPU seconds and the
// median of repetitions.
#pragma once

#include <time.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace growthuq::bench {

// CPU time of the calling thread, s: unlike wall time it does not count the time the thread
// waits for a core, so the figure is per core even on a loaded machine.
inline double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// The median (the mean of the middle two for an even count); values must not be empty.
inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace growthuq::bench
