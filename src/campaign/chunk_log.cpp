#include "campaign/chunk_log.hpp"

#include <array>
#include <bit>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "growthuq/core/error.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/sampling/random_stream.hpp"

namespace growthuq {
namespace {

constexpr std::array<char, 8> file_magic{'G', 'Q', 'C', 'H', 'U', 'N', 'K', 'S'};
constexpr std::uint32_t format_version = 1;
constexpr std::uint32_t byte_order_marker = 0x01020304;
constexpr std::uint64_t header_bytes = 16;
constexpr std::uint64_t record_tag = 0x4743484BULL;  // "GCHK"
constexpr std::size_t record_words = 5;
constexpr std::uint64_t record_header_bytes = record_words * 8;

// Four independent lanes so the multiply chains of consecutive words overlap (about four times
// the throughput of one chain); the word count enters the final mix, so a prefix never checks
// as the whole.
class Checksum {
 public:
  explicit Checksum(std::uint64_t seed) noexcept
      : lanes_{mix64(seed ^ 1), mix64(seed ^ 2), mix64(seed ^ 3), mix64(seed ^ 4)} {}

  template <typename Word>
  void add(std::span<const Word> words) noexcept {
    std::size_t i = 0;
    for (; i < words.size() && count_ % 4 != 0; ++i) add_one(bits(words[i]));
    for (; i + 4 <= words.size(); i += 4) {
      lanes_[0] = mix64(lanes_[0] ^ bits(words[i]));
      lanes_[1] = mix64(lanes_[1] ^ bits(words[i + 1]));
      lanes_[2] = mix64(lanes_[2] ^ bits(words[i + 2]));
      lanes_[3] = mix64(lanes_[3] ^ bits(words[i + 3]));
      count_ += 4;
    }
    for (; i < words.size(); ++i) add_one(bits(words[i]));
  }

  std::uint64_t value() const noexcept {
    std::uint64_t h = mix64(count_);
    for (const std::uint64_t lane : lanes_) h = mix64(h ^ lane);
    return h;
  }

 private:
  static std::uint64_t bits(std::uint64_t word) noexcept { return word; }
  static std::uint64_t bits(double value) noexcept { return std::bit_cast<std::uint64_t>(value); }

  void add_one(std::uint64_t word) noexcept {
    lanes_[count_ % 4] = mix64(lanes_[count_ % 4] ^ word);
    ++count_;
  }

  std::array<std::uint64_t, 4> lanes_;
  std::uint64_t count_ = 0;
};

std::uint64_t record_checksum(std::span<const std::uint64_t> header, std::span<const double> values) noexcept {
  Checksum checksum(0);
  checksum.add(header);
  checksum.add(values);
  return checksum.value();
}

std::string system_reason() { return std::strerror(errno); }

std::array<char, header_bytes> file_header() {
  std::array<char, header_bytes> header{};
  std::memcpy(header.data(), file_magic.data(), file_magic.size());
  std::memcpy(header.data() + 8, &format_version, 4);
  std::memcpy(header.data() + 12, &byte_order_marker, 4);
  return header;
}

}  // namespace

std::uint64_t checksum64(std::span<const std::uint64_t> words, std::uint64_t seed) noexcept {
  Checksum checksum(seed);
  checksum.add(words);
  return checksum.value();
}

ChunkLogScan scan_chunk_log(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) throw InputError(path, "cannot open the checkpoint's chunk log: " + system_reason());
  ChunkLogScan scan;
  std::error_code size_error;
  scan.file_bytes = std::filesystem::file_size(path, size_error);
  std::array<char, header_bytes> header{};
  if (std::fread(header.data(), 1, header.size(), file) != header.size() || header != file_header()) {
    std::fclose(file);
    throw InputError(path, "not a growthuq chunk log of format 1 written on a machine of this byte order");
  }
  scan.intact_bytes = header_bytes;
  std::vector<double> values;
  for (;;) {
    std::array<std::uint64_t, record_words> words{};
    if (std::fread(words.data(), 8, record_words, file) != record_words) break;
    const std::uint64_t count = words[3];
    const bool plausible = (words[0] >> 32) == record_tag && words[1] < words[2] &&
                           count <= (scan.file_bytes - scan.intact_bytes - record_header_bytes) / 8;
    if (!plausible) break;
    values.resize(count);
    if (std::fread(values.data(), 8, count, file) != count) break;
    if (record_checksum(std::span(words).first(4), values) != words[4]) break;
    ChunkRecord record;
    record.line = static_cast<std::uint32_t>(words[0] & 0xffffffffULL);
    record.range = {words[1], words[2]};
    record.offset = scan.intact_bytes + record_header_bytes;
    record.count = count;
    scan.records.push_back(record);
    scan.intact_bytes += record_header_bytes + 8 * count;
  }
  std::fclose(file);
  return scan;
}

ChunkLogReader::ChunkLogReader(std::string path) : path_(std::move(path)), file_(std::fopen(path_.c_str(), "rb")) {
  if (file_ == nullptr) throw InputError(path_, "cannot open the checkpoint's chunk log: " + system_reason());
}

ChunkLogReader::~ChunkLogReader() { std::fclose(file_); }

std::vector<double> ChunkLogReader::values(const ChunkRecord& record) {
  std::vector<double> values(record.count);
  if (std::fseek(file_, static_cast<long>(record.offset), SEEK_SET) != 0 ||
      std::fread(values.data(), 8, values.size(), file_) != values.size()) {
    throw InputError(path_, "cannot read back the chunk at byte " + std::to_string(record.offset) + ": " + system_reason());
  }
  return values;
}

ChunkLogWriter::ChunkLogWriter(std::string path, std::uint64_t keep_bytes) : path_(std::move(path)) {
  if (keep_bytes == 0) {
    file_ = std::fopen(path_.c_str(), "wb");
    if (file_ == nullptr) throw WriteError(path_, "cannot create the checkpoint's chunk log: " + system_reason());
    const std::array<char, header_bytes> header = file_header();
    if (std::fwrite(header.data(), 1, header.size(), file_) != header.size() || std::fflush(file_) != 0) {
      const std::string reason = system_reason();
      close();
      throw WriteError(path_, "cannot write the checkpoint's chunk log: " + reason);
    }
    return;
  }
  std::error_code error;
  std::filesystem::resize_file(path_, keep_bytes, error);
  if (error) throw InputError(path_, "cannot cut the torn tail of the checkpoint's chunk log: " + error.message());
  file_ = std::fopen(path_.c_str(), "ab");
  if (file_ == nullptr) throw InputError(path_, "cannot open the checkpoint's chunk log: " + system_reason());
}

ChunkLogWriter::~ChunkLogWriter() { close(); }

void ChunkLogWriter::close() noexcept {
  if (file_ != nullptr) std::fclose(file_);
  file_ = nullptr;
}

void ChunkLogWriter::append(std::uint32_t line, ChunkRange range, std::span<const double> values) {
  if (file_ == nullptr) throw std::logic_error("ChunkLogWriter::append after close()");
  std::array<std::uint64_t, record_words> words{record_tag << 32 | line, range.begin, range.end, values.size(), 0};
  words[4] = record_checksum(std::span(words).first(4), values);
  if (std::fwrite(words.data(), 8, words.size(), file_) != words.size() ||
      std::fwrite(values.data(), 8, values.size(), file_) != values.size() || std::fflush(file_) != 0) {
    throw WriteError(path_, "cannot write the checkpoint (is the disk full?): " + system_reason());
  }
}

}  // namespace growthuq
