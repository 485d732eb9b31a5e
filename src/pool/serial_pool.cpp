// The pool of one process, and the chunking shared by both pools.
#include <stdexcept>
#include <utility>

#include "growthuq/pool/pool.hpp"

namespace growthuq {

std::vector<ChunkRange> split_into_chunks(std::size_t count, std::size_t chunk_size) {
  if (chunk_size == 0) chunk_size = 1;
  std::vector<ChunkRange> chunks;
  chunks.reserve((count + chunk_size - 1) / chunk_size);
  for (std::size_t begin = 0; begin < count; begin += chunk_size) {
    chunks.push_back({begin, std::min(count, begin + chunk_size)});
  }
  return chunks;
}

std::vector<std::vector<double>> run_items(Pool& pool, std::size_t count,
                                           const std::function<std::vector<double>(std::size_t item)>& item,
                                           const std::function<void()>& collected) {
  std::vector<std::vector<double>> records(pool.is_coordinator() ? count : 0);
  pool.run(
      count, 1, [&](ChunkRange range) { return item(range.begin); },
      [&](ChunkRange range, std::span<const double> numbers) {
        records[range.begin].assign(numbers.begin(), numbers.end());
        if (collected) collected();
      });
  return records;
}

namespace {

class SerialPool final : public Pool {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  int processes_on_this_machine() const override { return 1; }

  void run(std::size_t count, std::size_t chunk_size, const ChunkWork& work, const ChunkSink& sink,
           const std::function<bool(ChunkRange)>& skip) override {
    for (const ChunkRange range : split_into_chunks(count, chunk_size)) {
      if (skip && skip(range)) continue;
      if (const int reason = stop_requested()) throw PoolInterrupted(reason);
      std::vector<double> values;
      try {
        values = work(range);
      } catch (const std::exception& error) {
        throw PoolError("rank 0 failed on items [" + std::to_string(range.begin) + ", " +
                        std::to_string(range.end) + "): " + error.what());
      }
      sink(range, values);
    }
  }

  std::string broadcast(const std::string& text) override { return text; }

  std::vector<std::vector<double>> gather(std::vector<double> values) override {
    std::vector<std::vector<double>> all;
    all.push_back(std::move(values));
    return all;
  }

  void broadcast_bytes(std::span<std::byte>, int root) override {
    if (root != 0) throw std::invalid_argument("broadcast_bytes: a serial pool has only process 0");
  }
};

}  // namespace

std::unique_ptr<Pool> make_serial_pool() { return std::make_unique<SerialPool>(); }

}  // namespace growthuq
