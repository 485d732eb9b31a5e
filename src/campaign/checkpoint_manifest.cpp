#include "campaign/checkpoint_manifest.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "campaign/chunk_log.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/rawdata/raw_line_file.hpp"
#include "growthuq/io/read_text_file.hpp"

namespace growthuq {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view first_line = "growthuq checkpoint 1";

std::string escape(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (const char c : text) {
    if (c == '\\') {
      escaped += "\\\\";
    } else if (c == '\n') {
      escaped += "\\n";
    } else if (c == '\r') {
      escaped += "\\r";
    } else {
      escaped += c;
    }
  }
  return escaped;
}

std::string unescape(std::string_view text, const std::string& location) {
  std::string plain;
  plain.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\') {
      plain += text[i];
      continue;
    }
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (next == '\\') {
      plain += '\\';
    } else if (next == 'n') {
      plain += '\n';
    } else if (next == 'r') {
      plain += '\r';
    } else {
      throw InputError(location, "bad escape in the checkpoint manifest (expected \\\\, \\n or \\r)");
    }
    ++i;
  }
  return plain;
}

std::string hex16(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016" PRIx64, value);
  return text;
}

void add_line(std::string& text, std::string_view key, std::string_view value) {
  text.append(key).append(" = ").append(escape(value)).append("\n");
}

FileFingerprint parse_input(std::string_view value, const std::string& location) {
  const std::size_t first = value.find(' ');
  const std::size_t second = first == std::string_view::npos ? first : value.find(' ', first + 1);
  FileFingerprint fingerprint;
  if (second != std::string_view::npos && first == 16) {
    char* end = nullptr;
    const std::string checksum(value.substr(0, 16));
    fingerprint.checksum = std::strtoull(checksum.c_str(), &end, 16);
    const bool hex = end == checksum.c_str() + 16;
    fingerprint.bytes = parse_count(value.substr(first + 1, second - first - 1), location, "input");
    fingerprint.path = std::string(value.substr(second + 1));
    if (hex && !fingerprint.path.empty()) return fingerprint;
  }
  throw_bad_value(location, "input", value, "<16 hex digits> <bytes> <path>");
}

}  // namespace

FileFingerprint fingerprint_file(const std::string& path, const std::string& read_from) {
  const std::string content = detail::read_text_file(read_from);
  std::vector<std::uint64_t> words((content.size() + 7) / 8, 0);
  if (!content.empty()) std::memcpy(words.data(), content.data(), content.size());
  return {path, content.size(), checksum64(words, content.size())};
}

CheckpointManifest make_checkpoint_manifest(const Campaign& campaign, const CampaignOverrides& overrides,
                                            std::string command_line) {
  CheckpointManifest manifest;
  manifest.engine_version = GROWTHUQ_VERSION;
  manifest.working_directory = fs::current_path().string();
  manifest.campaign_path = campaign.path;
  manifest.campaign_text = campaign.text;
  manifest.command_line = std::move(command_line);
  manifest.overrides = overrides;
  auto add = [&](const std::string& path) {
    const bool seen = std::any_of(manifest.inputs.begin(), manifest.inputs.end(),
                                  [&](const FileFingerprint& input) { return input.path == path; });
    if (!seen) manifest.inputs.push_back(fingerprint_file(path));
  };
  for (const CampaignLine& line : campaign.lines) {
    if (!line.raw_path.empty()) {
      // A line fitted from raw data depends on its raw.ini and on every table and curve file
      // it names: a changed tube table would refit different distributions on resume.
      const RawLineFile raw = read_raw_line_file(line.raw_path);
      add(line.raw_path);
      for (const RawMeasurement& measurement : raw.measurements) add(measurement.file);
      if (raw.has_relaxation) {
        add(raw.relaxation.curves);
        if (!raw.relaxation.meta.empty()) add(raw.relaxation.meta);
      }
      if (raw.has_force_curves) {
        add(raw.force_curves.curves);
        add(raw.force_curves.sheet);
      }
    } else {
      add(line.distributions_path);
    }
    if (line.correlation == CorrelationSource::file) add(line.correlation_path);
  }
  return manifest;
}

std::string format_manifest(const CheckpointManifest& manifest) {
  std::string text(first_line);
  text += "\n";
  add_line(text, "engine_version", manifest.engine_version);
  add_line(text, "working_directory", manifest.working_directory);
  add_line(text, "campaign_path", manifest.campaign_path);
  add_line(text, "command_line", manifest.command_line);
  const CampaignOverrides& o = manifest.overrides;
  if (o.samples) add_line(text, "override_samples", std::to_string(*o.samples));
  if (o.seed) add_line(text, "override_seed", std::to_string(*o.seed));
  if (o.lines) add_line(text, "override_lines", *o.lines);
  if (o.formats) add_line(text, "override_formats", *o.formats);
  if (o.fidelity) add_line(text, "override_fidelity", *o.fidelity);
  if (o.output_dir) add_line(text, "override_output_dir", *o.output_dir);
  for (const FileFingerprint& input : manifest.inputs) {
    add_line(text, "input", hex16(input.checksum) + " " + std::to_string(input.bytes) + " " + input.path);
  }
  add_line(text, "campaign_text", manifest.campaign_text);
  return text;
}

CheckpointManifest parse_manifest(const std::string& text, const std::string& path) {
  CheckpointManifest manifest;
  std::vector<std::string> seen;
  std::size_t start = 0;
  long number = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = std::string_view(text).substr(start, end - start);
    start = end + 1;
    const std::string location = file_location(path, ++number);
    if (number == 1) {
      if (line != first_line) throw InputError(location, "not a growthuq checkpoint manifest of format 1");
      continue;
    }
    const std::size_t equals = line.find(" = ");
    if (equals == std::string_view::npos) throw InputError(location, "expected 'key = value'");
    const std::string key(line.substr(0, equals));
    const std::string value = unescape(line.substr(equals + 3), location);
    if (key != "input" && std::find(seen.begin(), seen.end(), key) != seen.end()) {
      throw InputError(location, "key '" + key + "' repeats");
    }
    seen.push_back(key);
    CampaignOverrides& o = manifest.overrides;
    if (key == "engine_version") {
      manifest.engine_version = value;
    } else if (key == "working_directory") {
      manifest.working_directory = value;
    } else if (key == "campaign_path") {
      manifest.campaign_path = value;
    } else if (key == "command_line") {
      manifest.command_line = value;
    } else if (key == "campaign_text") {
      manifest.campaign_text = value;
    } else if (key == "override_samples") {
      o.samples = parse_count(value, location, key, 1, 4294967295ULL);
    } else if (key == "override_seed") {
      o.seed = parse_count(value, location, key);
    } else if (key == "override_lines") {
      o.lines = value;
    } else if (key == "override_formats") {
      o.formats = value;
    } else if (key == "override_fidelity") {
      o.fidelity = value;
    } else if (key == "override_output_dir") {
      o.output_dir = value;
    } else if (key == "input") {
      manifest.inputs.push_back(parse_input(value, location));
    } else {
      throw InputError(location, "unknown key '" + key + "' in the checkpoint manifest");
    }
  }
  if (number == 0) throw InputError(path, "empty checkpoint manifest");
  for (const char* required : {"engine_version", "working_directory", "campaign_path", "command_line", "campaign_text"}) {
    if (std::find(seen.begin(), seen.end(), required) == seen.end()) {
      throw InputError(path, std::string("the checkpoint manifest lacks '") + required + "'");
    }
  }
  return manifest;
}

std::string locate(const CheckpointManifest& manifest, const std::string& path) {
  if (fs::path(path).is_absolute()) return path;
  std::error_code error;
  if (fs::equivalent(fs::current_path(error), manifest.working_directory, error)) return path;
  return (fs::path(manifest.working_directory) / path).lexically_normal().string();
}

void verify_manifest(const CheckpointManifest& manifest, const std::string& manifest_path) {
  if (manifest.engine_version != GROWTHUQ_VERSION) {
    throw InputError(manifest_path, "the interrupted run was made by growthuq " + manifest.engine_version +
                                        ", this is growthuq " + GROWTHUQ_VERSION +
                                        ": finish it with that version, or start the run again with --force");
  }
  for (const FileFingerprint& input : manifest.inputs) {
    const std::string now_at = locate(manifest, input.path);
    std::error_code error;
    if (!fs::is_regular_file(now_at, error)) {
      throw InputError(input.path, "read by the interrupted run, now missing (looked for " + now_at +
                                       "): restore it to resume, or start the run again with --force");
    }
    const FileFingerprint now = fingerprint_file(input.path, now_at);
    if (now != input) {
      throw InputError(input.path, "changed since the interrupted run (" + std::to_string(input.bytes) + " bytes, checksum " +
                                       hex16(input.checksum) + " then; " + std::to_string(now.bytes) + " bytes, checksum " +
                                       hex16(now.checksum) +
                                       " now): restore it to resume, or start the run again with --force");
    }
  }
}

CampaignFileNow campaign_file_now(const CheckpointManifest& manifest) {
  try {
    return detail::read_text_file(locate(manifest, manifest.campaign_path)) == manifest.campaign_text
               ? CampaignFileNow::unchanged
               : CampaignFileNow::changed;
  } catch (const InputError&) {  // removed, renamed or no longer readable
    return CampaignFileNow::unreadable;
  }
}

Campaign resumed_campaign(const CheckpointManifest& manifest, const std::string& output_dir) {
  Campaign campaign = parse_campaign(manifest.campaign_text, locate(manifest, manifest.campaign_path));
  campaign.path = manifest.campaign_path;  // results.h5 stores the path as first given
  CampaignOverrides overrides = manifest.overrides;
  overrides.output_dir = output_dir;
  apply_overrides(campaign, overrides);
  return campaign;
}

}  // namespace growthuq
