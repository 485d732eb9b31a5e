#include "campaign/checkpoint.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <utility>

#include "growthuq/core/error.hpp"
#include "growthuq/io/output_file.hpp"
#include "campaign/chunk_values.hpp"
#include "growthuq/io/read_text_file.hpp"

namespace growthuq {
namespace {

namespace fs = std::filesystem;

bool by_begin(const ChunkRecord& a, const ChunkRecord& b) { return a.range.begin < b.range.begin; }

// The held chunks as (line, begin, end) triples of 64-bit words, for Pool::broadcast.
std::string encode_held(const std::vector<std::vector<ChunkRecord>>& held) {
  std::string bytes;
  for (const std::vector<ChunkRecord>& line : held) {
    for (const ChunkRecord& record : line) {
      const std::array<std::uint64_t, 3> words{record.line, record.range.begin, record.range.end};
      bytes.append(reinterpret_cast<const char*>(words.data()), sizeof words);
    }
  }
  return bytes;
}

void decode_held(const std::string& bytes, std::vector<std::vector<ChunkRecord>>& held) {
  std::array<std::uint64_t, 3> words{};
  for (std::size_t at = 0; at + sizeof words <= bytes.size(); at += sizeof words) {
    std::memcpy(words.data(), bytes.data() + at, sizeof words);
    ChunkRecord record;
    record.line = static_cast<std::uint32_t>(words[0]);
    record.range = {words[1], words[2]};
    held.at(record.line).push_back(record);
  }
}

}  // namespace

std::string checkpoint_directory(const std::string& output_dir) { return (fs::path(output_dir) / "checkpoint").string(); }

std::string checkpoint_manifest_path(const std::string& output_dir) {
  return (fs::path(checkpoint_directory(output_dir)) / "manifest.txt").string();
}

std::string checkpoint_chunk_log_path(const std::string& output_dir) {
  return (fs::path(checkpoint_directory(output_dir)) / "chunks.bin").string();
}

bool has_checkpoint(const std::string& output_dir) {
  std::error_code error;
  return fs::is_regular_file(checkpoint_manifest_path(output_dir), error);
}

std::string read_checkpoint_manifest_text(const std::string& output_dir) {
  std::error_code error;
  if (!fs::is_directory(output_dir, error)) throw InputError(output_dir, "no such output directory to resume");
  if (!has_checkpoint(output_dir)) {
    throw InputError(output_dir, "holds no checkpoint (" + checkpoint_manifest_path(output_dir) +
                                     "): nothing to resume (a completed run removes its checkpoint)");
  }
  return detail::read_text_file(checkpoint_manifest_path(output_dir));
}

std::string checkpoint_audit_log_path(const std::string& output_dir) {
  return (fs::path(checkpoint_directory(output_dir)) / "audit.bin").string();
}

RunCheckpoint::RunCheckpoint(std::string output_dir, std::string log_path, std::size_t lines)
    : output_dir_(std::move(output_dir)), log_path_(std::move(log_path)), held_(lines) {}

std::unique_ptr<RunCheckpoint> RunCheckpoint::start(Pool& pool, const PreparedCampaign& campaign,
                                                    const CheckpointManifest& manifest) {
  const std::string& output_dir = campaign.campaign().output_dir;
  std::unique_ptr<RunCheckpoint> checkpoint(
      new RunCheckpoint(output_dir, checkpoint_chunk_log_path(output_dir), campaign.lines().size()));
  on_coordinator(pool, [&] {
    const std::string directory = checkpoint_directory(output_dir);
    std::error_code error;
    fs::remove_all(directory, error);  // a stale checkpoint in a directory reused with --force
    fs::create_directories(directory, error);
    if (error) throw InputError(directory, "cannot create the checkpoint directory: " + error.message());
    // The chunk log first: a manifest is what marks a directory as resumable.
    checkpoint->writer_.emplace(checkpoint->log_path_, 0);
    write_file_atomically(checkpoint_manifest_path(output_dir), format_manifest(manifest), Overwrite::allow);
  });
  return checkpoint;
}

std::unique_ptr<RunCheckpoint> RunCheckpoint::resume(Pool& pool, const PreparedCampaign& campaign) {
  const std::string& output_dir = campaign.campaign().output_dir;
  std::unique_ptr<RunCheckpoint> checkpoint(
      new RunCheckpoint(output_dir, checkpoint_chunk_log_path(output_dir), campaign.lines().size()));
  ChunkShape shape;
  shape.samples = campaign.campaign().samples;
  for (const PreparedLine& line : campaign.lines()) shape.chunk_sizes.push_back(campaign.chunk_size_of(line));
  shape.values_per_sample = ChunkValues::values_per_sample(campaign.computed_outputs().size());
  std::string held;
  on_coordinator(pool, [&] { held = checkpoint->continue_log(shape); });
  checkpoint->share_held(pool, held);
  return checkpoint;
}

std::unique_ptr<RunCheckpoint> RunCheckpoint::open_audit(Pool& pool, const std::string& output_dir, const ChunkShape& shape,
                                                         bool resuming) {
  std::unique_ptr<RunCheckpoint> checkpoint(
      new RunCheckpoint(output_dir, checkpoint_audit_log_path(output_dir), shape.chunk_sizes.size()));
  std::string held;
  on_coordinator(pool, [&] {
    std::error_code error;
    if (resuming && fs::is_regular_file(checkpoint->log_path_, error)) {
      held = checkpoint->continue_log(shape);
    } else {
      checkpoint->writer_.emplace(checkpoint->log_path_, 0);
    }
  });
  checkpoint->share_held(pool, held);
  return checkpoint;
}

std::string RunCheckpoint::continue_log(const ChunkShape& shape) {
  const ChunkLogScan scan = scan_chunk_log(log_path_);
  for (const ChunkRecord& record : scan.records) {
    const std::size_t size = record.range.end - record.range.begin;
    const bool known_line = record.line < held_.size();
    const std::size_t chunk_size = known_line ? shape.chunk_sizes[record.line] : 1;
    const bool fits = known_line && record.range.begin % chunk_size == 0 &&
                      record.range.end == std::min(shape.samples, record.range.begin + chunk_size) &&
                      record.count == shape.values_per_sample * size;
    if (!fits) {
      throw InputError(log_path_, "the chunk at byte " + std::to_string(record.offset) + " (line " + std::to_string(record.line) +
                                      ", samples [" + std::to_string(record.range.begin) + ", " + std::to_string(record.range.end) +
                                      ")) does not fit the campaign of the manifest: the checkpoint is damaged; start "
                                      "the run again with --force");
    }
    std::vector<ChunkRecord>& line = held_[record.line];
    const auto place = std::lower_bound(line.begin(), line.end(), record, by_begin);
    if (place != line.end() && place->range.begin == record.range.begin) continue;  // kept twice: the first copy
    line.insert(place, record);
    samples_held_ += size;
  }
  writer_.emplace(log_path_, scan.intact_bytes);
  reader_.emplace(log_path_);
  return encode_held(held_);
}

void RunCheckpoint::share_held(Pool& pool, std::string held) {
  held = pool.broadcast(held);
  if (!pool.is_coordinator()) decode_held(held, held_);
}

bool RunCheckpoint::holds(std::size_t line, ChunkRange range) const {
  const std::vector<ChunkRecord>& records = held_.at(line);
  ChunkRecord probe;
  probe.range = range;
  const auto found = std::lower_bound(records.begin(), records.end(), probe, by_begin);
  return found != records.end() && found->range.begin == range.begin && found->range.end == range.end;
}

void RunCheckpoint::replay(std::size_t line, const ChunkSink& sink) {
  if (!reader_) return;
  for (const ChunkRecord& record : held_.at(line)) {
    const std::vector<double> values = reader_->values(record);
    sink(record.range, values);
  }
}

void RunCheckpoint::record(std::size_t line, ChunkRange range, std::span<const double> values) {
  if (!writer_) throw std::logic_error("RunCheckpoint::record on a process that does not coordinate, or after remove()");
  writer_->append(static_cast<std::uint32_t>(line), range, values);
  samples_held_ += range.end - range.begin;
}

void RunCheckpoint::remove() {
  writer_.reset();
  reader_.reset();
  std::error_code error;
  fs::remove_all(checkpoint_directory(output_dir_), error);
}

}  // namespace growthuq
