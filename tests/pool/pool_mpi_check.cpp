// Runs under `mpirun -np K` (CTest registers K = 1, 2, 3): the MPI pool must give results
// bit-identical to a serial computation whatever K is, including K larger than the work, and
// a failing chunk must stop every rank with the rank, range and reason (never hang), and a stop
// request on the coordinator must stop every rank at the same point, and the coordinator must
// answer the workers while it computes a chunk of its own.
// Exits 0 when every check holds; prints the failed check and exits 1 otherwise.
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>

#include "growthuq/pool/pool.hpp"

using namespace growthuq;

namespace {

// An item's value: a pure function of its index; odd chunks are slower so that dynamic
// assignment actually reorders the work.
std::vector<double> compute(ChunkRange range) {
  if ((range.begin / 7) % 2 == 1) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  std::vector<double> values;
  for (std::size_t i = range.begin; i < range.end; ++i) values.push_back(std::sin(double(i)) * std::exp(1e-3 * double(i)));
  return values;
}

int failures = 0;

void check(bool condition, const std::string& what, int rank) {
  if (!condition) {
    std::fprintf(stderr, "rank %d: check failed: %s\n", rank, what.c_str());
    ++failures;
  }
}

}  // namespace

int main() {
  auto pool = make_pool();
  const int rank = pool->rank();

  for (const std::size_t count : {std::size_t{1}, std::size_t{2}, std::size_t{500}}) {
    std::vector<double> result(count, std::nan(""));
    std::size_t sunk_items = 0;
    pool->run(count, 7, compute, [&](ChunkRange range, std::span<const double> values) {
      check(values.size() == range.end - range.begin, "chunk size", rank);
      for (std::size_t i = range.begin; i < range.end; ++i) result[i] = values[i - range.begin];
      sunk_items += range.end - range.begin;
    });
    if (pool->is_coordinator()) {
      const std::vector<double> expected = compute({0, count});
      check(sunk_items == count, "every item sunk exactly once (count " + std::to_string(count) + ")", rank);
      for (std::size_t i = 0; i < count; ++i) {
        check(result[i] == expected[i], "item " + std::to_string(i) + " bit-identical to serial", rank);
      }
    } else {
      check(sunk_items == 0, "sink is called on rank 0 only", rank);
    }
  }

  // A poisoned chunk: every rank gets the same PoolError naming the failing range.
  bool thrown = false;
  try {
    pool->run(200, 10, [](ChunkRange range) {
      if (range.begin == 120) throw std::runtime_error("poisoned chunk");
      return compute(range);
    }, [](ChunkRange, std::span<const double>) {});
  } catch (const PoolError& error) {
    thrown = true;
    const std::string message = error.what();
    check(message.find("failed on items [120, 130): poisoned chunk") != std::string::npos, "failure message: " + message, rank);
  }
  check(thrown, "a failing chunk throws PoolError on every rank", rank);

  // A stop request on the coordinator (a signal there): every rank throws PoolInterrupted with its
  // value after the chunks in flight are sunk; a second run skipping the sunk chunks completes the
  // result bit-identically (resume). Workers' requests are ignored: theirs says stop at once.
  {
    const std::size_t count = 700;
    std::vector<double> result(count, std::nan(""));
    std::vector<ChunkRange> sunk;
    const ChunkSink place = [&](ChunkRange range, std::span<const double> values) {
      for (std::size_t i = range.begin; i < range.end; ++i) result[i] = values[i - range.begin];
      sunk.push_back(range);
    };
    pool->stop_when([&] { return rank == 0 ? (sunk.size() >= 10 ? 15 : 0) : 2; });
    int reason = 0;
    try {
      pool->run(count, 7, compute, place);
    } catch (const PoolInterrupted& stopped) {
      reason = stopped.reason();
    }
    check(reason == 15, "every rank stops with the coordinator's request (got " + std::to_string(reason) + ")", rank);
    std::string done = " ";  // " begin begin ... " of the sunk chunks, shared with every rank
    if (rank == 0) {
      check(sunk.size() >= 10 && sunk.size() < 100, "stopped after 10 chunks plus those in flight: " + std::to_string(sunk.size()), rank);
      for (const ChunkRange& range : sunk) done += std::to_string(range.begin) + " ";
    }
    done = pool->broadcast(done);
    pool->stop_when(nullptr);
    pool->run(count, 7, compute, place, [&](ChunkRange range) {
      return done.find(" " + std::to_string(range.begin) + " ") != std::string::npos;
    });
    if (rank == 0) {
      const std::vector<double> expected = compute({0, count});
      check(sunk.size() == 100, "every chunk sunk exactly once over the two runs", rank);
      bool identical = true;
      for (std::size_t i = 0; i < count; ++i) identical = identical && result[i] == expected[i];
      check(identical, "stopped then resumed run bit-identical to serial", rank);
    }
  }

  check(pool->broadcast(rank == 0 ? "campaign text" : "") == "campaign text", "broadcast", rank);

  // broadcast_bytes from every root: each process ends with the root's numbers, bit for bit.
  for (int root = 0; root < pool->size(); ++root) {
    std::vector<double> numbers;
    if (rank == root) numbers = compute({0, 3000});
    pool->broadcast_vector(numbers, 3000, root);
    check(numbers == compute({0, 3000}), "broadcast_bytes from rank " + std::to_string(root), rank);
  }
  // gather: rank 0 gets every process's numbers in rank order, the others nothing.
  std::vector<double> mine(static_cast<std::size_t>(rank) * 1000 + 1, static_cast<double>(rank) + 0.5);
  const std::vector<std::vector<double>> gathered = pool->gather(mine);
  if (rank == 0) {
    check(gathered.size() == static_cast<std::size_t>(pool->size()), "gather: one contribution per process", rank);
    for (std::size_t r = 0; r < gathered.size(); ++r) {
      check(gathered[r] == std::vector<double>(r * 1000 + 1, static_cast<double>(r) + 0.5), "gather from rank " + std::to_string(r), rank);
    }
  } else {
    check(gathered.empty(), "gather: nothing on a process other than 0", rank);
  }

  // Rank 0 answers the workers while it computes: its first chunk of a run of one-item chunks
  // (none queued) waits until the sink has taken 12 of the workers' chunks, which it can only if
  // rank 0 hands out and sinks chunks meanwhile (a rank 0 that serves only between its own chunks
  // would sink none: the wait's 30 s bound then ends it and the check fails).
  if (pool->size() > 1) {
    std::atomic<int> sunk_by_workers{0};
    std::atomic<bool> own_started{false};
    int seen_during_own = -1;
    pool->set_queued_chunks(1);
    pool->run(
        40, 1,
        [&](ChunkRange range) {
          if (rank == 0 && !own_started.exchange(true)) {
            const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
            while (sunk_by_workers.load() < 12 && std::chrono::steady_clock::now() < give_up) {
              std::this_thread::sleep_for(std::chrono::milliseconds(1));
            }
            seen_during_own = sunk_by_workers.load();
          } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
          }
          return compute(range);
        },
        [&](ChunkRange, std::span<const double>) { ++sunk_by_workers; });
    if (rank == 0) {
      check(seen_during_own >= 12, "rank 0 sank the workers' chunks while computing its own (saw " +
                                       std::to_string(seen_during_own) + " of 12)", rank);
    }
    pool->set_queued_chunks(3);
  }

  // run_items: item i is i + 1 numbers (uneven), all back on rank 0 in item order.
  std::size_t collected = 0;
  const auto item = [](std::size_t i) { return std::vector<double>(i + 1, 0.25 * static_cast<double>(i)); };
  const std::vector<std::vector<double>> items = run_items(*pool, 37, item, [&] { ++collected; });
  if (rank == 0) {
    check(items.size() == 37 && collected == 37, "run_items: every item collected once", rank);
    for (std::size_t i = 0; i < items.size(); ++i) check(items[i] == item(i), "run_items: item " + std::to_string(i), rank);
  } else {
    check(items.empty() && collected == 0, "run_items: nothing on a process other than 0", rank);
  }

  if (failures == 0 && rank == 0) std::printf("pool check passed on %d process(es)\n", pool->size());
  return failures == 0 ? 0 : 1;
}
