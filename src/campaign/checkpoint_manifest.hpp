// The manifest of a checkpoint (checkpoint.hpp): what `growthuq run --resume DIR` needs to finish
// an interrupted run exactly as the uninterrupted run would have: the campaign text and where it
// was read from, the command-line overrides, the original command line (results.h5 stores it),
// the engine version, and a fingerprint of every input file the run reads (line files, matrix
// files, raw-data files and the tables they name), so that a resume whose inputs changed is
// refused rather than mixing two campaigns.
//
// Text format, one `key = value` per line after the first line "growthuq checkpoint 1";
// values escape backslash, newline and carriage return as \\, \n, \r:
//   engine_version, working_directory, campaign_path, command_line, campaign_text (required);
//   override_samples, override_seed, override_lines, override_formats, override_output_dir
//   (when given on the command line); input = <checksum, 16 hex digits> <bytes> <path> (repeated).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_file.hpp"

namespace growthuq {

// The size and checksum64 (chunk_log.hpp) of a file's bytes.
struct FileFingerprint {
  std::string path;  // as the campaign names it (relative paths start at the working directory)
  std::uint64_t bytes = 0;
  std::uint64_t checksum = 0;

  bool operator==(const FileFingerprint&) const = default;
};

// InputError naming the file when it cannot be read.
FileFingerprint fingerprint_file(const std::string& path, const std::string& read_from);
inline FileFingerprint fingerprint_file(const std::string& path) { return fingerprint_file(path, path); }

struct CheckpointManifest {
  std::string engine_version;
  std::string working_directory;  // absolute; the run's relative paths start here
  std::string campaign_path;      // as given on the command line
  std::string campaign_text;
  std::string command_line;       // "growthuq run ..." as results.h5 stores it
  CampaignOverrides overrides;
  std::vector<FileFingerprint> inputs;
};

// The manifest of a new run of `campaign` (overrides applied) started in the current directory.
// InputError naming an input file that cannot be read.
CheckpointManifest make_checkpoint_manifest(const Campaign& campaign, const CampaignOverrides& overrides,
                                            std::string command_line);

std::string format_manifest(const CheckpointManifest& manifest);

// InputError naming `path` and the line for anything malformed, unknown or missing.
CheckpointManifest parse_manifest(const std::string& text, const std::string& path);

// Refuses to resume when the engine version differs or an input file changed or vanished since
// the interrupted run; each an InputError naming the file (or `manifest_path`) and saying what
// to do.
void verify_manifest(const CheckpointManifest& manifest, const std::string& manifest_path);

// The campaign file where the interrupted run read it (located as below), compared with the
// stored campaign_text. A resume uses the stored text in every case, so that it finishes the
// run as started; the caller tells the user when the file no longer holds that text.
enum class CampaignFileNow { unchanged, changed, unreadable };
CampaignFileNow campaign_file_now(const CheckpointManifest& manifest);

// Where the run's `path` is now: unchanged when absolute or when the current directory is the
// manifest's working directory, otherwise resolved against the working directory.
std::string locate(const CheckpointManifest& manifest, const std::string& path);

// The interrupted run's campaign: the stored text parsed as from its original place, the stored
// overrides applied, results going to `output_dir`. Validated like a new campaign.
Campaign resumed_campaign(const CheckpointManifest& manifest, const std::string& output_dir);

}  // namespace growthuq
