// Reproducible random numbers without global state. Every random number of a design is a
// function of (campaign seed, line name, variable name) only, so adding a variable to a line
// leaves the other variables' columns unchanged, and per-sample numbers are a function of
// (key, sample index) only, so results do not depend on how many processes evaluate them.
//
// THE SCHEME (bit-exact on every conforming C++ standard library):
//   fnv1a64(text)        64-bit FNV-1a hash of the UTF-8 bytes (offset basis 0xcbf29ce484222325,
//                        prime 0x100000001b3).
//   mix64(x)             the SplitMix64 finalizer (Steele, Lea & Flood 2014):
//                        x += 0x9e3779b97f4a7c15; x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9;
//                        x = (x ^ (x >> 27)) * 0x94d049bb133111eb; return x ^ (x >> 31).
//   derive_key(key, name) = mix64(key ^ fnv1a64(name)).
//   stream_key(seed, line, variable) = derive_key(derive_key(mix64(seed), line), variable).
//   RandomStream(key)    std::mt19937_64 seeded with `key` (engine and seeding are specified
//                        bit for bit by the C++ standard, [rand.eng.mers]). Bits are turned into
//                        numbers here, never by std::uniform_real_distribution or std::shuffle,
//                        whose outputs differ between standard libraries:
//                        uniform in [0,1):  (x >> 11) * 2^-53;
//                        uniform in (0,1):  ((x >> 11) + 0.5) * 2^-53;
//                        integer in [0, b): Lemire's multiply-shift with rejection (Lemire 2019,
//                        "Fast random integer generation in an interval", ACM TOMACS 29(1):3).
//   counter_bits(key, i) = mix64(key ^ mix64(i)): a counter-based generator for per-sample
//                        randomness (e.g. measurement noise of sample i), independent of order.
#pragma once

#include <cstdint>
#include <random>
#include <string_view>

namespace growthuq {

std::uint64_t fnv1a64(std::string_view text) noexcept;

constexpr std::uint64_t mix64(std::uint64_t x) noexcept {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A child key of `key` named `name` (a line, a variable, a noise stream).
std::uint64_t derive_key(std::uint64_t key, std::string_view name) noexcept;

// The key of one variable of one line of a campaign.
std::uint64_t stream_key(std::uint64_t seed, std::string_view line, std::string_view variable) noexcept;

// 53 random bits as a double in [0,1) and in the open interval (0,1).
// (The 53-bit value is converted as a signed integer: the same number, one instruction.)
constexpr double bits_to_unit(std::uint64_t bits) noexcept {
  return static_cast<double>(static_cast<std::int64_t>(bits >> 11)) * 0x1.0p-53;
}
// (k + 1/2) 2^-53 for the 53-bit value k: for k = 2^53 - 1 the sum rounds (to even) to 2^53 and
// the number to exactly 1, so that one bit pattern is mapped to the largest double below 1.
constexpr double bits_to_open_unit(std::uint64_t bits) noexcept {
  const double u = (static_cast<double>(static_cast<std::int64_t>(bits >> 11)) + 0.5) * 0x1.0p-53;
  return u < 1.0 ? u : 1.0 - 0x1.0p-53;
}

// Counter-based randomness: the index-th number of the stream `key`.
constexpr std::uint64_t counter_bits(std::uint64_t key, std::uint64_t index) noexcept {
  return mix64(key ^ mix64(index));
}
constexpr double uniform(std::uint64_t key, std::uint64_t index) noexcept {
  return bits_to_unit(counter_bits(key, index));
}
constexpr double uniform_open(std::uint64_t key, std::uint64_t index) noexcept {
  return bits_to_open_unit(counter_bits(key, index));
}

// A sequential stream (Mersenne Twister 19937-64) for work done in one place, such as the
// permutations of a Latin hypercube column.
class RandomStream {
 public:
  explicit RandomStream(std::uint64_t key) : engine_(key) {}

  std::uint64_t bits() { return engine_(); }
  double uniform() { return bits_to_unit(engine_()); }
  double uniform_open() { return bits_to_open_unit(engine_()); }

  // Uniform integer in [0, bound), bound >= 1, without modulo bias (Lemire 2019).
  std::uint64_t below(std::uint64_t bound) {
    __extension__ using Wide = unsigned __int128;
    Wide product = static_cast<Wide>(engine_()) * bound;
    auto low = static_cast<std::uint64_t>(product);
    if (low < bound) {
      const std::uint64_t threshold = (0 - bound) % bound;
      while (low < threshold) {
        product = static_cast<Wide>(engine_()) * bound;
        low = static_cast<std::uint64_t>(product);
      }
    }
    return static_cast<std::uint64_t>(product >> 64);
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace growthuq
