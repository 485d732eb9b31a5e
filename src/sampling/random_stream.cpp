#include "growthuq/sampling/random_stream.hpp"

namespace growthuq {

std::uint64_t fnv1a64(std::string_view text) noexcept {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

std::uint64_t derive_key(std::uint64_t key, std::string_view name) noexcept { return mix64(key ^ fnv1a64(name)); }

std::uint64_t stream_key(std::uint64_t seed, std::string_view line, std::string_view variable) noexcept {
  return derive_key(derive_key(mix64(seed), line), variable);
}

}  // namespace growthuq
