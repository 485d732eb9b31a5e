#include "growthuq/sampling/latin_hypercube.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "growthuq/sampling/random_stream.hpp"

namespace growthuq {

namespace {

// 32-bit words from a 64-bit stream: the high half of each draw, then its low half.
class WordStream {
 public:
  explicit WordStream(RandomStream& stream) : stream_(stream) {}
  std::uint32_t next() {
    if (has_low_) {
      has_low_ = false;
      return static_cast<std::uint32_t>(buffer_);
    }
    buffer_ = stream_.bits();
    has_low_ = true;
    return static_cast<std::uint32_t>(buffer_ >> 32);
  }

  // Uniform in [0, bound) for 1 <= bound < 2^32 (Lemire 2019, 32-bit form).
  std::uint32_t below(std::uint32_t bound) {
    std::uint64_t product = std::uint64_t{next()} * bound;
    auto low = static_cast<std::uint32_t>(product);
    if (low < bound) {
      const std::uint32_t threshold = (0u - bound) % bound;
      while (low < threshold) {
        product = std::uint64_t{next()} * bound;
        low = static_cast<std::uint32_t>(product);
      }
    }
    return static_cast<std::uint32_t>(product >> 32);
  }

 private:
  RandomStream& stream_;
  std::uint64_t buffer_ = 0;
  bool has_low_ = false;
};

// Fisher-Yates from the last position down: swap position i with j = below(i + 1). The swap
// partners of a batch are drawn first and prefetched, since for large n every swap is a cache
// miss; the draws and swaps happen in the same order as in the plain loop.
void shuffle(std::vector<std::uint32_t>& values, RandomStream& stream) {
  constexpr std::size_t batch = 32;
  WordStream words(stream);
  std::uint32_t partner[batch];
  std::size_t i = values.size() - 1;
  while (i > 0) {
    const std::size_t count = std::min(batch, i);
    for (std::size_t b = 0; b < count; ++b) {
      partner[b] = words.below(static_cast<std::uint32_t>(i - b + 1));
      __builtin_prefetch(&values[partner[b]], 1);
    }
    for (std::size_t b = 0; b < count; ++b) std::swap(values[i - b], values[partner[b]]);
    i -= count;
  }
}

}  // namespace

double stratum_edge(std::size_t k, std::size_t n) noexcept {
  return static_cast<double>(k) * (1.0 / static_cast<double>(n));
}

LatinColumn latin_hypercube_column(std::size_t n, std::uint64_t key, StratumPosition position) {
  if (n == 0 || n > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("latin_hypercube_column: n must be in [1, 2^32 - 1]");
  }
  RandomStream stream(key);
  LatinColumn column;
  column.stratum.resize(n);
  std::iota(column.stratum.begin(), column.stratum.end(), std::uint32_t{0});
  shuffle(column.stratum, stream);

  column.u_by_stratum.resize(n);
  const double width = 1.0 / static_cast<double>(n);
  const double below_one = std::nextafter(1.0, 0.0);
  double lower = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double offset = position == StratumPosition::random ? stream.uniform_open() : 0.5;
    const double upper = static_cast<double>(k + 1) * width;
    double u = (static_cast<double>(k) + offset) * width;
    // Rounding may put u on the next stratum's edge (or on 1 for the last one); the point must
    // stay strictly inside its own stratum for the one-point-per-stratum property to be exact.
    if (u >= upper) u = std::nextafter(upper, 0.0);
    if (u < lower) u = lower;
    if (u > below_one) u = below_one;
    column.u_by_stratum[k] = u;
    lower = upper;
  }
  return column;
}

}  // namespace growthuq
