#include "growthuq/core/large_vector.hpp"

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <new>
#include <vector>

namespace growthuq::detail {

namespace {

constexpr std::size_t smallest_kept = std::size_t{1} << 20;
constexpr std::size_t most_blocks_kept = 64;
constexpr std::size_t most_bytes_kept = std::size_t{1} << 29;

struct KeptBlock {
  void* memory;
  std::size_t bytes;
};

struct BlockCache {
  std::mutex mutex;
  std::vector<KeptBlock> blocks;  // oldest first
  std::size_t bytes = 0;
};

BlockCache& cache() {
  static BlockCache* instance = new BlockCache;  // never destroyed: blocks may be released at exit
  return *instance;
}

}  // namespace

void* acquire_block(std::size_t bytes) {
  if (bytes >= smallest_kept) {
    BlockCache& kept = cache();
    const std::lock_guard lock(kept.mutex);
    auto best = kept.blocks.end();
    for (auto block = kept.blocks.begin(); block != kept.blocks.end(); ++block) {
      if (block->bytes >= bytes && block->bytes - bytes <= bytes / 4 &&
          (best == kept.blocks.end() || block->bytes < best->bytes)) {
        best = block;
      }
    }
    if (best != kept.blocks.end()) {
      void* memory = best->memory;
      kept.bytes -= best->bytes;
      kept.blocks.erase(best);
      return memory;
    }
  }
  void* memory = std::malloc(std::max<std::size_t>(bytes, 1));
  if (memory == nullptr) throw std::bad_alloc();
  return memory;
}

void release_block(void* block, std::size_t bytes) noexcept {
  if (block == nullptr) return;
  if (bytes < smallest_kept || bytes > most_bytes_kept) {
    std::free(block);
    return;
  }
  BlockCache& kept = cache();
  const std::lock_guard lock(kept.mutex);
  try {
    kept.blocks.push_back({block, bytes});
  } catch (...) {
    std::free(block);
    return;
  }
  kept.bytes += bytes;
  while (kept.blocks.size() > most_blocks_kept || kept.bytes > most_bytes_kept) {
    std::free(kept.blocks.front().memory);
    kept.bytes -= kept.blocks.front().bytes;
    kept.blocks.erase(kept.blocks.begin());
  }
}

void release_cached_blocks() noexcept {
  BlockCache& kept = cache();
  const std::lock_guard lock(kept.mutex);
  for (const KeptBlock& block : kept.blocks) std::free(block.memory);
  kept.blocks.clear();
  kept.bytes = 0;
}

}  // namespace growthuq::detail
