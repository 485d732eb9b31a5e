// The 64-bit Mersenne Twister (Matsumoto & Nishimura 1998; Nishimura 2000, the 64-bit
// parameters of [rand.predef], std::mt19937_64), generating its 312-word state a block at a time
// and tempering a whole block in one vectorizable loop. Same sequence as std::mt19937_64 seeded
// with the same value, bit for bit (tests/sampling/test_mt19937_64_block.cpp). It exists because
// std::mt19937_64's per-call index check and scalar tempering were most of the ~17 % of a design's
// time spent on the shuffle and its random numbers.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

namespace growthuq::detail {

class Mt19937_64Block {
 public:
  static constexpr std::size_t state_size = 312;  // n
  static constexpr std::size_t shift_size = 156;  // m

  // The seeding of [rand.eng.mers]: x_0 = seed, x_i = f (x_{i-1} ^ (x_{i-1} >> 62)) + i.
  explicit Mt19937_64Block(std::uint64_t seed) {
    state_[0] = seed;
    for (std::size_t i = 1; i < state_size; ++i) {
      state_[i] = 6364136223846793005ULL * (state_[i - 1] ^ (state_[i - 1] >> 62)) + i;
    }
  }

  std::uint64_t operator()() {
    if (next_ == state_size) refill();
    return block_[next_++];
  }

  // The next out.size() numbers, in order.
  void fill(std::span<std::uint64_t> out) {
    std::size_t done = 0;
    while (done < out.size()) {
      if (next_ == state_size) refill();
      const std::size_t count = std::min(out.size() - done, state_size - next_);
      std::copy_n(block_ + next_, count, out.data() + done);
      next_ += count;
      done += count;
    }
  }

 private:
  static constexpr std::uint64_t upper_mask = ~std::uint64_t{0} << 31;  // w - r = 33 bits
  static constexpr std::uint64_t lower_mask = ~upper_mask;
  static constexpr std::uint64_t matrix_a = 0xb5026f5aa96619e9ULL;

  static std::uint64_t twist(std::uint64_t current, std::uint64_t following, std::uint64_t shifted) {
    const std::uint64_t y = (current & upper_mask) | (following & lower_mask);
    return shifted ^ (y >> 1) ^ ((0 - (y & 1)) & matrix_a);
  }

  // The recurrence of [rand.eng.mers] in the three ranges where its operands do not overlap
  // (so the first two loops vectorize), then the tempering of every word.
  void refill() {
    constexpr std::size_t n = state_size;
    constexpr std::size_t m = shift_size;
    for (std::size_t k = 0; k < n - m; ++k) state_[k] = twist(state_[k], state_[k + 1], state_[k + m]);
    for (std::size_t k = n - m; k < n - 1; ++k) state_[k] = twist(state_[k], state_[k + 1], state_[k + m - n]);
    state_[n - 1] = twist(state_[n - 1], state_[0], state_[m - 1]);
    for (std::size_t k = 0; k < n; ++k) {
      std::uint64_t z = state_[k];
      z ^= (z >> 29) & 0x5555555555555555ULL;
      z ^= (z << 17) & 0x71d67fffeda60000ULL;
      z ^= (z << 37) & 0xfff7eee000000000ULL;
      z ^= z >> 43;
      block_[k] = z;
    }
    next_ = 0;
  }

  std::uint64_t state_[state_size];
  std::uint64_t block_[state_size];
  std::size_t next_ = state_size;
};

}  // namespace growthuq::detail
