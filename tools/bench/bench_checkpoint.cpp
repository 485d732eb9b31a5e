// Benchmark (not a test): what checkpointing costs a run. Writes the chunk log a campaign of
// --lines lines x --samples samples with --outputs computed outputs would write (chunks of
// --chunk-size samples, values = outputs + status per sample, as the sink receives them),
// then scans it (what --resume does first), reads every chunk back (the replay), and removes
// it (what a completed run does). Prints each step's time, best of --repeats, and the log's
// size. Compare the total with the run's own time (tools/bench/bench-checkpoint runs both).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "growthuq/campaign/chunk_log.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"

using namespace growthuq;

namespace {

struct Options {
  std::uint64_t samples = 1'000'000;
  std::uint64_t lines = 5;
  std::uint64_t outputs = 4;
  std::uint64_t chunk_size = 4096;
  std::uint64_t repeats = 3;
  std::string directory = std::filesystem::temp_directory_path().string();
};

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const std::string value = argv[i + 1];
    if (key == "--samples") {
      options.samples = parse_count(value, "bench_checkpoint", key, 1);
    } else if (key == "--lines") {
      options.lines = parse_count(value, "bench_checkpoint", key, 1, 1000);
    } else if (key == "--outputs") {
      options.outputs = parse_count(value, "bench_checkpoint", key, 1, 100);
    } else if (key == "--chunk-size") {
      options.chunk_size = parse_count(value, "bench_checkpoint", key, 1);
    } else if (key == "--repeats") {
      options.repeats = parse_count(value, "bench_checkpoint", key, 1, 100);
    } else if (key == "--dir") {
      options.directory = value;
    } else {
      throw InputError("bench_checkpoint", "unknown option " + key +
                                               " (--samples N --lines L --outputs K --chunk-size C --repeats R --dir D)");
    }
  }
  return options;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) try {
  const Options options = parse(argc, argv);
  const std::string path = (std::filesystem::path(options.directory) / "bench_checkpoint_chunks.bin").string();
  const std::size_t values_per_sample = options.outputs + 1;
  std::vector<double> values(values_per_sample * options.chunk_size);
  std::mt19937_64 random(2022);
  for (double& value : values) value = std::uniform_real_distribution<double>(0.1, 10.0)(random);

  double append = std::numeric_limits<double>::infinity(), scan = append, replay = append, remove = append;
  std::uintmax_t bytes = 0;
  std::size_t records = 0;
  for (std::uint64_t repeat = 0; repeat < options.repeats; ++repeat) {
    auto start = std::chrono::steady_clock::now();
    {
      ChunkLogWriter writer(path, 0);
      for (std::uint32_t line = 0; line < options.lines; ++line) {
        for (std::uint64_t begin = 0; begin < options.samples; begin += options.chunk_size) {
          const std::uint64_t end = std::min(options.samples, begin + options.chunk_size);
          writer.append(line, {begin, end}, std::span<const double>(values).first(values_per_sample * (end - begin)));
        }
      }
    }
    append = std::min(append, seconds_since(start));
    bytes = std::filesystem::file_size(path);

    start = std::chrono::steady_clock::now();
    const ChunkLogScan found = scan_chunk_log(path);
    scan = std::min(scan, seconds_since(start));
    records = found.records.size();

    start = std::chrono::steady_clock::now();
    double sum = 0;
    ChunkLogReader reader(path);
    for (const ChunkRecord& record : found.records) sum += reader.values(record).front();
    replay = std::min(replay, seconds_since(start));
    if (!(sum > 0)) std::printf("unexpected values\n");

    start = std::chrono::steady_clock::now();
    std::filesystem::remove(path);
    remove = std::min(remove, seconds_since(start));
  }
  std::printf("chunk log of %llu lines x %llu samples, %zu values per sample, chunks of %llu: %zu records, %.1f MB\n",
              static_cast<unsigned long long>(options.lines), static_cast<unsigned long long>(options.samples),
              values_per_sample, static_cast<unsigned long long>(options.chunk_size), records, static_cast<double>(bytes) / 1e6);
  std::printf("best of %llu:  append (a run) %.3f s (%.0f MB/s)  remove (run completed) %.3f s  |  "
              "scan (resume) %.3f s  replay %.3f s\n",
              static_cast<unsigned long long>(options.repeats), append, static_cast<double>(bytes) / 1e6 / append, remove, scan, replay);
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "bench_checkpoint: %s\n", error.what());
  return 2;
}
