// The chunk log of a checkpoint (checkpoint.hpp): an append-only binary file of framed records,
// one per finished chunk (line, range, the values the sink received), each flushed to the
// operating system as it is written. A killed process loses at most the record it was writing;
// a reader stops at the first record that is short or fails its checksum (a torn tail) and the
// writer cuts the file back there before appending.
//
// Layout (native byte order, checked by a marker in the header):
//   file header  8 bytes "GQCHUNKS", uint32 version (1), uint32 0x01020304
//   record       uint64 (0x4743484B << 32 | line), uint64 begin, uint64 end, uint64 count,
//                uint64 checksum, then count float64 values; the checksum (checksum64) covers
//                the four words before it and the values' bits.
#pragma once

#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "growthuq/pool/pool.hpp"

namespace growthuq {

// A 64-bit checksum of `words` seeded with `seed`: four interleaved lanes of the SplitMix64
// finalizer (random_stream.hpp), combined with the word count. Detects torn and corrupted
// records; not a cryptographic hash.
std::uint64_t checksum64(std::span<const std::uint64_t> words, std::uint64_t seed = 0) noexcept;

// A record found by scan_chunk_log.
struct ChunkRecord {
  std::uint32_t line = 0;
  ChunkRange range;
  std::uint64_t offset = 0;  // of the first value in the file
  std::uint64_t count = 0;   // number of values
};

struct ChunkLogScan {
  std::vector<ChunkRecord> records;  // the intact records, in file order
  std::uint64_t intact_bytes = 0;    // header + intact records: where the next record goes
  std::uint64_t file_bytes = 0;      // the file's size; more than intact_bytes after a torn tail
};

// Reads every intact record of the log at `path`. InputError naming the file when it cannot be
// read or its header is not a chunk log of this version and byte order.
ChunkLogScan scan_chunk_log(const std::string& path);

// Reads the values of records found by scan_chunk_log (the scan verified their checksums).
class ChunkLogReader {
 public:
  // InputError naming the file when it cannot be opened.
  explicit ChunkLogReader(std::string path);
  ~ChunkLogReader();
  ChunkLogReader(const ChunkLogReader&) = delete;
  ChunkLogReader& operator=(const ChunkLogReader&) = delete;

  // InputError naming the file when the record cannot be read back.
  std::vector<double> values(const ChunkRecord& record);

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
};

// Appends records to a chunk log.
class ChunkLogWriter {
 public:
  // Creates the log (header only) when `keep_bytes` is 0; otherwise opens it and cuts it to
  // `keep_bytes` (ChunkLogScan::intact_bytes), dropping a torn tail. InputError naming the file.
  ChunkLogWriter(std::string path, std::uint64_t keep_bytes);
  ~ChunkLogWriter();
  ChunkLogWriter(const ChunkLogWriter&) = delete;
  ChunkLogWriter& operator=(const ChunkLogWriter&) = delete;

  // Writes one record and flushes it to the operating system (no fsync: the page cache
  // survives the death of the process, which is what a checkpoint guards against).
  // InputError naming the file when the write fails (disk full).
  void append(std::uint32_t line, ChunkRange range, std::span<const double> values);

  // Closes the file (idempotent); the destructor does it too.
  void close() noexcept;

  const std::string& path() const noexcept { return path_; }

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
};

}  // namespace growthuq
