#include "growthuq/sampling/latin_hypercube.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

#include "growthuq/sampling/random_stream.hpp"
#include "core/avx2_clone.hpp"
#include "sampling/latin_column.hpp"

namespace growthuq {

namespace detail {

namespace {

// The inside-out shuffle of latin_column.hpp, out[r] = source(shuffled_iota[r]). For large n
// every step touches a random element of `out`: the draws do not depend on the array, so they
// run one batch ahead of the moves, and the elements the next batch will touch are prefetched
// while this batch moves. Draws and moves each happen in the same order as in the plain loop.
template <class T, class Source>
void inside_out_shuffle(const Source& source, std::span<T> out, Mt19937_64Block& random) {
  constexpr std::size_t batch = 64;
  const std::size_t n = out.size();
  T* values = out.data();
  std::uint32_t partners[2][batch];
  std::uint64_t word_pair = 0;
  bool has_low = false;
  const auto next_word = [&]() -> std::uint32_t {
    if (has_low) {
      has_low = false;
      return static_cast<std::uint32_t>(word_pair);
    }
    word_pair = random();
    has_low = true;
    return static_cast<std::uint32_t>(word_pair >> 32);
  };
  // Draws j for i = first, first + 1, ..., first + count - 1 into `partner`.
  const auto draw = [&](std::size_t first, std::size_t count, std::uint32_t* partner) {
    for (std::size_t b = 0; b < count; ++b) {
      const auto bound = static_cast<std::uint32_t>(first + b + 1);
      std::uint64_t product = std::uint64_t{next_word()} * bound;
      if (static_cast<std::uint32_t>(product) < bound) {
        const std::uint32_t threshold = (0u - bound) % bound;
        while (static_cast<std::uint32_t>(product) < threshold) product = std::uint64_t{next_word()} * bound;
      }
      partner[b] = static_cast<std::uint32_t>(product >> 32);
      __builtin_prefetch(values + partner[b], 1);
    }
  };
  values[0] = source(0);
  std::size_t i = 1;
  std::size_t count = std::min(batch, n - i);
  int current = 0;
  draw(i, count, partners[current]);
  while (i < n) {
    const std::size_t next_first = i + count;
    const std::size_t next_count = std::min(batch, n - next_first);
    draw(next_first, next_count, partners[1 - current]);
    for (std::size_t b = 0; b < count; ++b) {
      const std::uint32_t j = partners[current][b];
      if (j != i + b) values[i + b] = values[j];
      values[j] = source(i + b);
    }
    i = next_first;
    count = next_count;
    current = 1 - current;
  }
}

}  // namespace

GROWTHUQ_AVX2_CLONE
void shuffled_copy(std::span<const double> source, std::span<double> out, Mt19937_64Block& random) {
  inside_out_shuffle([&](std::size_t i) { return source[i]; }, out, random);
}

GROWTHUQ_AVX2_CLONE
void shuffle_strata(std::span<std::uint32_t> sample_of_stratum, Mt19937_64Block& random) {
  inside_out_shuffle([](std::size_t i) { return static_cast<std::uint32_t>(i); }, sample_of_stratum, random);
}

GROWTHUQ_AVX2_CLONE
void stratum_points(Mt19937_64Block& random, std::size_t n, std::size_t first, std::span<double> u,
                    StratumPosition position) {
  const double width = 1.0 / static_cast<double>(n);
  const double below_one = std::nextafter(1.0, 0.0);
  constexpr std::size_t block = 512;
  std::uint64_t bits[block];
  double offset[block];
  for (std::size_t start = 0; start < u.size(); start += block) {
    const std::size_t count = std::min(block, u.size() - start);
    if (position == StratumPosition::random) {
      random.fill(std::span<std::uint64_t>(bits, count));
      for (std::size_t i = 0; i < count; ++i) offset[i] = bits_to_open_unit(bits[i]);
    } else {
      std::fill_n(offset, count, 0.5);
    }
    // Branch-free so it vectorizes: rounding may put the point on the next stratum's edge (or
    // on 1 for the last one); it must stay strictly inside its own stratum for the
    // one-point-per-stratum property to be exact. The largest double below the (positive)
    // upper edge is the edge's bit pattern minus one.
    double* out = u.data() + start;
    const auto base = static_cast<double>(first + start);
    for (std::size_t i = 0; i < count; ++i) {
      // k exactly (k < 2^32); the int32 conversion vectorizes where a 64-bit one would not
      const double k = base + static_cast<double>(static_cast<std::int32_t>(i));
      const double lower = k * width;
      const double upper = (k + 1.0) * width;
      const double below_upper = std::bit_cast<double>(std::bit_cast<std::uint64_t>(upper) - 1);
      double point = (k + offset[i]) * width;
      point = point < below_upper ? point : below_upper;
      point = point > lower ? point : lower;
      out[i] = point < below_one ? point : below_one;
    }
  }
}

}  // namespace detail

double stratum_edge(std::size_t k, std::size_t n) noexcept {
  return static_cast<double>(k) * (1.0 / static_cast<double>(n));
}

LatinColumn latin_hypercube_column(std::size_t n, std::uint64_t key, StratumPosition position) {
  if (n == 0 || n > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("latin_hypercube_column: n must be in [1, 2^32 - 1]");
  }
  detail::Mt19937_64Block random(key);
  std::vector<std::uint32_t> sample_of_stratum(n);
  detail::shuffle_strata(sample_of_stratum, random);
  LatinColumn column;
  column.stratum.resize(n);
  for (std::size_t k = 0; k < n; ++k) column.stratum[sample_of_stratum[k]] = static_cast<std::uint32_t>(k);
  column.u_by_stratum.resize(n);
  detail::stratum_points(random, n, 0, column.u_by_stratum, position);
  return column;
}

}  // namespace growthuq
