// The serial pool and the chunking every pool shares.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "growthuq/pool/pool.hpp"

using namespace growthuq;

TEST_CASE("chunks tile the range exactly") {
  for (std::size_t count : {0u, 1u, 7u, 100u, 101u}) {
    for (std::size_t size : {0u, 1u, 3u, 100u, 1000u}) {
      const auto chunks = split_into_chunks(count, size);
      std::size_t expected_begin = 0;
      for (const auto& chunk : chunks) {
        CHECK(chunk.begin == expected_begin);
        CHECK(chunk.end > chunk.begin);
        CHECK(chunk.end - chunk.begin <= std::max<std::size_t>(size, 1));
        expected_begin = chunk.end;
      }
      CHECK(expected_begin == count);
    }
  }
}

TEST_CASE("serial pool computes every item once, honours skip and reports failures") {
  auto pool = make_serial_pool();
  CHECK(pool->size() == 1);
  std::vector<double> result(50, -1.0);
  const ChunkWork square = [](ChunkRange range) {
    std::vector<double> values;
    for (std::size_t i = range.begin; i < range.end; ++i) values.push_back(double(i) * double(i));
    return values;
  };
  const ChunkSink place = [&](ChunkRange range, std::span<const double> values) {
    for (std::size_t i = range.begin; i < range.end; ++i) result[i] = values[i - range.begin];
  };
  pool->run(50, 8, square, place, [](ChunkRange range) { return range.begin == 8; });
  for (std::size_t i = 0; i < 50; ++i) CHECK(result[i] == ((i >= 8 && i < 16) ? -1.0 : double(i * i)));

  const ChunkWork failing = [](ChunkRange range) -> std::vector<double> {
    if (range.begin <= 20 && 20 < range.end) throw std::runtime_error("poisoned item 20");
    return std::vector<double>(range.end - range.begin, 0.0);
  };
  CHECK_THROWS_WITH_AS(pool->run(50, 8, failing, place), "rank 0 failed on items [16, 24): poisoned item 20", PoolError);
}

TEST_CASE("a stop request ends the serial run after the chunks already sunk; a skip run finishes it") {
  auto pool = make_serial_pool();
  const ChunkWork cube = [](ChunkRange range) {
    std::vector<double> values;
    for (std::size_t i = range.begin; i < range.end; ++i) values.push_back(double(i) * double(i) * double(i));
    return values;
  };
  std::vector<double> result(100, -1.0);
  std::vector<ChunkRange> sunk;
  const ChunkSink place = [&](ChunkRange range, std::span<const double> values) {
    for (std::size_t i = range.begin; i < range.end; ++i) result[i] = values[i - range.begin];
    sunk.push_back(range);
  };
  // The request turns on after the third chunk: the fourth never starts.
  pool->stop_when([&] { return sunk.size() >= 3 ? 15 : 0; });
  int reason = 0;
  try {
    pool->run(100, 9, cube, place);
  } catch (const PoolInterrupted& stopped) {
    reason = stopped.reason();
  }
  CHECK(reason == 15);
  REQUIRE(sunk.size() == 3);
  for (std::size_t i = 0; i < 100; ++i) CHECK(result[i] == (i < 27 ? double(i * i * i) : -1.0));

  // Resuming: the sunk chunks are skipped, the others computed; the whole equals one run.
  const std::vector<ChunkRange> done = sunk;
  pool->stop_when(nullptr);
  pool->run(100, 9, cube, place, [&](ChunkRange range) {
    for (const ChunkRange& d : done) {
      if (d.begin == range.begin && d.end == range.end) return true;
    }
    return false;
  });
  for (std::size_t i = 0; i < 100; ++i) CHECK(result[i] == double(i * i * i));
  CHECK(sunk.size() == split_into_chunks(100, 9).size());

  // A request that arrives after the last chunk does not turn a finished run into a stopped one.
  pool->stop_when([] { return 2; });
  CHECK_NOTHROW(pool->run(100, 9, cube, place, [](ChunkRange) { return true; }));
}
