// The checkpoint's files: chunk log records read back bit for bit, a torn or corrupted tail
// ignored and cut before appending, the manifest's round trip, and refusal to resume when an
// input file changed or vanished.
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_file.hpp"
#include "campaign/checkpoint_manifest.hpp"
#include "growthuq/rawdata/raw_line_file.hpp"
#include "campaign/chunk_log.hpp"
#include "growthuq/core/error.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

struct Chunk {
  std::uint32_t line;
  ChunkRange range;
  std::vector<double> values;
};

// Values with awkward bit patterns (NaN payloads, -0, infinities, subnormals) among random ones:
// the log must give back bits, not just numbers that compare equal.
std::vector<Chunk> sample_chunks() {
  std::mt19937_64 random(7);
  std::vector<Chunk> chunks;
  for (std::uint32_t line = 0; line < 3; ++line) {
    for (std::size_t begin = 0; begin < 100; begin += 37) {
      Chunk chunk{line, {begin, std::min<std::size_t>(100, begin + 37)}, {}};
      for (std::size_t i = 0; i < 5 * (chunk.range.end - chunk.range.begin); ++i) {
        chunk.values.push_back(std::bit_cast<double>(random()));
      }
      chunk.values[0] = -0.0;
      chunk.values[1] = std::numeric_limits<double>::infinity();
      chunk.values[2] = std::bit_cast<double>(std::uint64_t{0x7ff8dead0000beefULL});
      chunk.values[3] = std::numeric_limits<double>::denorm_min();
      chunks.push_back(chunk);
    }
  }
  return chunks;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  }
  return true;
}

void write_log(const std::string& path, const std::vector<Chunk>& chunks) {
  ChunkLogWriter writer(path, 0);
  for (const Chunk& chunk : chunks) writer.append(chunk.line, chunk.range, chunk.values);
}

void check_records(const std::string& path, const ChunkLogScan& scan, const std::vector<Chunk>& expected) {
  REQUIRE(scan.records.size() == expected.size());
  ChunkLogReader reader(path);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    CAPTURE(i);
    CHECK(scan.records[i].line == expected[i].line);
    CHECK(scan.records[i].range.begin == expected[i].range.begin);
    CHECK(scan.records[i].range.end == expected[i].range.end);
    CHECK(same_bits(reader.values(scan.records[i]), expected[i].values));
  }
}

}  // namespace

TEST_CASE("chunk log: every record comes back with its line, range and value bits") {
  ScratchDirectory scratch("checkpoint_round_trip");
  const std::string path = (scratch.root / "chunks.bin").string();
  const std::vector<Chunk> chunks = sample_chunks();
  write_log(path, chunks);
  const ChunkLogScan scan = scan_chunk_log(path);
  check_records(path, scan, chunks);
  // Size: 16-byte header, then per record 40 header bytes and 8 per value.
  std::uint64_t expected_bytes = 16;
  for (const Chunk& chunk : chunks) expected_bytes += 40 + 8 * chunk.values.size();
  CHECK(scan.intact_bytes == expected_bytes);
  CHECK(scan.file_bytes == expected_bytes);
}

TEST_CASE("chunk log: a torn tail is ignored wherever the write stopped, and cut before appending") {
  ScratchDirectory scratch("checkpoint_torn");
  const std::string path = (scratch.root / "chunks.bin").string();
  const std::vector<Chunk> chunks = sample_chunks();
  write_log(path, chunks);
  const std::string whole = slurp(path);
  const std::uint64_t last_start = whole.size() - (40 + 8 * chunks.back().values.size());
  const std::vector<Chunk> kept(chunks.begin(), chunks.end() - 1);

  // Cut inside the record header, at its end, inside the values, one byte short of complete.
  for (const std::uint64_t cut : {last_start + 1, last_start + 39, last_start + 40, last_start + 41, std::uint64_t(whole.size() - 1)}) {
    CAPTURE(cut);
    spit(path, whole.substr(0, cut));
    const ChunkLogScan scan = scan_chunk_log(path);
    check_records(path, scan, kept);
    CHECK(scan.intact_bytes == last_start);
    CHECK(scan.file_bytes == cut);
  }

  // Appending after a torn tail: the writer cuts it, and the new record reads back.
  spit(path, whole.substr(0, last_start + 100));
  {
    ChunkLogWriter writer(path, scan_chunk_log(path).intact_bytes);
    writer.append(chunks.back().line, chunks.back().range, chunks.back().values);
  }
  check_records(path, scan_chunk_log(path), chunks);
  CHECK(slurp(path) == whole);
}

TEST_CASE("chunk log: a record whose bits changed fails its checksum; reading stops before it") {
  ScratchDirectory scratch("checkpoint_corrupt");
  const std::string path = (scratch.root / "chunks.bin").string();
  const std::vector<Chunk> chunks = sample_chunks();
  write_log(path, chunks);
  const std::string whole = slurp(path);
  const std::uint64_t second_start = 16 + 40 + 8 * chunks[0].values.size();
  const std::vector<Chunk> first_only(chunks.begin(), chunks.begin() + 1);
  // One bit of a value, of the range, of the checksum itself.
  for (const std::uint64_t byte : {second_start + 40 + 123, second_start + 8, second_start + 32}) {
    CAPTURE(byte);
    std::string damaged = whole;
    damaged[byte] = static_cast<char>(damaged[byte] ^ 0x10);
    spit(path, damaged);
    const ChunkLogScan scan = scan_chunk_log(path);
    check_records(path, scan, first_only);
    CHECK(scan.intact_bytes == second_start);
  }
  spit(path, "GQCHUNKX" + whole.substr(8));
  CHECK_THROWS_AS(scan_chunk_log(path), InputError);
}

TEST_CASE("checksum64 changes with every single-bit flip and with the length") {
  std::vector<std::uint64_t> words{1, 2, 3, 0xffffffffffffffffULL, 0, 5, 6, 7, 8};
  const std::uint64_t reference = checksum64(words);
  int unchanged = 0;
  for (std::size_t w = 0; w < words.size(); ++w) {
    for (int bit = 0; bit < 64; ++bit) {
      std::vector<std::uint64_t> flipped = words;
      flipped[w] ^= std::uint64_t{1} << bit;
      unchanged += checksum64(flipped) == reference;
    }
  }
  CHECK(unchanged == 0);
  std::vector<std::uint64_t> longer = words;
  longer.push_back(0);
  CHECK(checksum64(longer) != reference);
  CHECK(checksum64(words, 1) != reference);
}

TEST_CASE("manifest: every field survives the text round trip, awkward characters included") {
  CheckpointManifest manifest;
  manifest.engine_version = "0.1.0";
  manifest.working_directory = "/home/user/study one";
  manifest.campaign_path = "campaigns/quick.ini";
  manifest.campaign_text = "[campaign]\r\nname = a \\n not a newline\n\n# = sign = here\n\\\\\n";
  manifest.command_line = "growthuq run campaigns/quick.ini --samples 100 --out 'a b'";
  manifest.overrides.samples = 100;
  manifest.overrides.seed = 18446744073709551615ULL;
  manifest.overrides.lines = "wild_type,pme48";
  manifest.overrides.formats = "csv";
  manifest.overrides.output_dir = "a b";
  manifest.inputs = {{"distributions/wild type.ini", 1921, 0xca997b41725f6985ULL}, {"m.csv", 0, 0}};
  const CheckpointManifest back = parse_manifest(format_manifest(manifest), "manifest.txt");
  CHECK(back.engine_version == manifest.engine_version);
  CHECK(back.working_directory == manifest.working_directory);
  CHECK(back.campaign_path == manifest.campaign_path);
  CHECK(back.campaign_text == manifest.campaign_text);
  CHECK(back.command_line == manifest.command_line);
  CHECK(back.overrides.samples == manifest.overrides.samples);
  CHECK(back.overrides.seed == manifest.overrides.seed);
  CHECK(back.overrides.lines == manifest.overrides.lines);
  CHECK(back.overrides.formats == manifest.overrides.formats);
  CHECK(back.overrides.output_dir == manifest.overrides.output_dir);
  CHECK(back.inputs == manifest.inputs);

  // Without overrides, none comes back.
  manifest.overrides = {};
  const CheckpointManifest plain = parse_manifest(format_manifest(manifest), "manifest.txt");
  CHECK_FALSE(plain.overrides.samples.has_value());
  CHECK_FALSE(plain.overrides.output_dir.has_value());
}

TEST_CASE("manifest: malformed text is refused naming the file and line") {
  const std::string good = "growthuq checkpoint 1\nengine_version = 1\nworking_directory = /\ncampaign_path = c.ini\n"
                           "command_line = growthuq run c.ini\ncampaign_text = x\n";
  CHECK_NOTHROW(parse_manifest(good, "m.txt"));
  CHECK_THROWS_WITH_AS(parse_manifest("growthuq checkpoint 2\n", "m.txt"), "m.txt:1: not a growthuq checkpoint manifest of format 1", InputError);
  CHECK_THROWS_WITH_AS(parse_manifest(good + "colour = red\n", "m.txt"), "m.txt:7: unknown key 'colour' in the checkpoint manifest", InputError);
  CHECK_THROWS_WITH_AS(parse_manifest(good + "seed = 1\n", "m.txt"), "m.txt:7: unknown key 'seed' in the checkpoint manifest", InputError);
  CHECK_THROWS_WITH_AS(parse_manifest(good + "campaign_text = y\n", "m.txt"), "m.txt:7: key 'campaign_text' repeats", InputError);
  CHECK_THROWS_WITH_AS(parse_manifest(good + "input = 12 3 f.ini\n", "m.txt"),
                       "m.txt:7: input = '12 3 f.ini': expected <16 hex digits> <bytes> <path>", InputError);
  CHECK_THROWS_WITH_AS(parse_manifest("growthuq checkpoint 1\nengine_version = 1\n", "m.txt"),
                       "m.txt: the checkpoint manifest lacks 'working_directory'", InputError);
}

TEST_CASE("resuming is refused when an input file changed or vanished, and allowed when restored") {
  ScratchDirectory scratch("checkpoint_fingerprints");
  const fs::path line = scratch.root / "line.ini";
  const fs::path matrix = scratch.root / "matrix.csv";
  const std::string line_text = "[k]\nfamily = lognormal\nmedian = 2.87\n";
  spit(line, line_text);
  spit(matrix, "k,h\n1,0.3\n0.3,1\n");
  CheckpointManifest manifest;
  manifest.engine_version = GROWTHUQ_VERSION;
  manifest.working_directory = fs::current_path().string();
  manifest.inputs = {fingerprint_file(line.string()), fingerprint_file(matrix.string())};
  CHECK(manifest.inputs[0].bytes == line_text.size());
  CHECK_NOTHROW(verify_manifest(manifest, "m.txt"));

  // One character changed, same length: the checksum tells.
  spit(line, "[k]\nfamily = lognormal\nmedian = 2.88\n");
  CHECK(fingerprint_file(line.string()).bytes == manifest.inputs[0].bytes);
  try {
    verify_manifest(manifest, "m.txt");
    FAIL("a changed line file was accepted");
  } catch (const InputError& error) {
    CHECK(error.location() == line.string());
    CHECK(error.problem().find("changed since the interrupted run") != std::string::npos);
  }
  spit(line, line_text);
  CHECK_NOTHROW(verify_manifest(manifest, "m.txt"));

  fs::remove(matrix);
  try {
    verify_manifest(manifest, "m.txt");
    FAIL("a vanished matrix file was accepted");
  } catch (const InputError& error) {
    CHECK(error.location() == matrix.string());
    CHECK(error.problem().find("now missing") != std::string::npos);
  }

  manifest.inputs.pop_back();
  manifest.engine_version = "0.0.0-other";
  CHECK_THROWS_WITH_AS(verify_manifest(manifest, "m.txt"),
                       doctest::Contains("the interrupted run was made by growthuq 0.0.0-other"), InputError);
}

TEST_CASE("the campaign file is compared byte for byte with the stored text, from another directory too") {
  ScratchDirectory scratch("campaign_file_now");
  const std::string text = "[campaign]\nname = c\nseed = 11\n";
  spit(scratch.root / "c.ini", text);
  CheckpointManifest manifest;
  manifest.working_directory = scratch.root.string();  // the run started there, with a relative path
  manifest.campaign_path = "c.ini";
  manifest.campaign_text = text;
  CHECK(campaign_file_now(manifest) == CampaignFileNow::unchanged);
  spit(scratch.root / "c.ini", "[campaign]\nname = c\nseed = 12\n");  // same length
  CHECK(campaign_file_now(manifest) == CampaignFileNow::changed);
  spit(scratch.root / "c.ini", text + "\n");
  CHECK(campaign_file_now(manifest) == CampaignFileNow::changed);
  fs::remove(scratch.root / "c.ini");
  CHECK(campaign_file_now(manifest) == CampaignFileNow::unreadable);
}

TEST_CASE("relative paths of a run are found from another working directory") {
  CheckpointManifest manifest;
  manifest.working_directory = "/somewhere/else";
  CHECK(locate(manifest, "campaigns/q.ini") == "/somewhere/else/campaigns/q.ini");
  CHECK(locate(manifest, "../distributions/w.ini") == "/somewhere/distributions/w.ini");
  CHECK(locate(manifest, "/abs/w.ini") == "/abs/w.ini");
  manifest.working_directory = fs::current_path().string();
  CHECK(locate(manifest, "campaigns/q.ini") == "campaigns/q.ini");
}

TEST_CASE("a line fitted from raw data fingerprints its raw.ini and every table and curve file it names") {
  const std::string path = std::string(GROWTHUQ_SOURCE_DIR) + "/tests/campaign/data/raw_campaign.ini";
  const Campaign campaign = read_campaign(path);
  const CheckpointManifest manifest = make_checkpoint_manifest(campaign, CampaignOverrides{}, "growthuq run");
  const RawLineFile raw = read_raw_line_file(campaign.lines[0].raw_path);
  std::vector<std::string> expected{raw.path};
  for (const RawMeasurement& measurement : raw.measurements) expected.push_back(measurement.file);
  REQUIRE(raw.has_relaxation);
  expected.push_back(raw.relaxation.curves);
  if (!raw.relaxation.meta.empty()) expected.push_back(raw.relaxation.meta);
  std::vector<std::string> fingerprinted;
  for (const FileFingerprint& input : manifest.inputs) fingerprinted.push_back(input.path);
  for (const std::string& file : expected) {
    INFO(file);
    CHECK(std::count(fingerprinted.begin(), fingerprinted.end(), file) == 1);
    CHECK(fs::file_size(file) == manifest.inputs[static_cast<std::size_t>(
                                     std::find(fingerprinted.begin(), fingerprinted.end(), file) - fingerprinted.begin())].bytes);
  }
  CHECK(std::count(fingerprinted.begin(), fingerprinted.end(), campaign.lines[1].distributions_path) == 1);
}
