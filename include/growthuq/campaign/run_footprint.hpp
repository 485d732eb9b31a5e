// What a campaign run will take of the machine, memory and disk, estimated before any sampling,
// so that a run too large for this machine is refused with one message instead of being
// killed by the kernel's out-of-memory killer (or filling the disk) part way through. The
// memory model was measured (tools/bench/README.md: peak resident memory against samples per
// line for campaigns of 3 to 7 inputs, 1 to 5 outputs, 1 and 5 lines, up to 1.6e7 samples);
// it errs high, never low, by design.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "growthuq/campaign/campaign_run.hpp"

namespace growthuq {

// The shape of a run the estimate depends on.
struct RunShape {
  std::size_t samples = 0;           // per line
  std::size_t lines = 0;
  std::size_t largest_inputs = 0;    // design variables of the widest line
  std::size_t largest_outputs = 0;   // computed outputs
  std::size_t longest_line_name = 0;
  bool csv = false;                  // samples.csv written
  bool hdf5 = false;                 // results.h5 written
  bool checkpoint = false;           // DIR/checkpoint kept while the run lasts
};

RunShape run_shape(const PreparedCampaign& campaign, bool checkpoint);

struct RunFootprint {
  std::uint64_t samples = 0;                  // per line
  std::string what;                           // "5 lines of up to 7 inputs and 4 outputs", for messages
  std::uint64_t fixed_memory_bytes = 0;       // what does not grow with the samples
  std::uint64_t memory_bytes_per_sample = 0;  // the growth per sample per line
  std::uint64_t memory_bytes = 0;             // peak resident memory of the coordinating process
  std::uint64_t disk_bytes_per_sample = 0;
  std::uint64_t disk_bytes = 0;               // result files and checkpoint at their largest
};

// The coordinator holds up to three lines at a time (one designed, one finished, one written,
// campaign_run.cpp), the others less; every process holds the whole of a line's design and
// outputs. Per sample of a line with m inputs and o outputs:
//   20 m + 4 o + 36 bytes    the line being designed (ranks, values, score columns, sort
//                            records) or analysed, whichever is larger
//   + 3/5 (12 m + 8 o + 1)   with more than one line: the previous lines still held
//   + (12 m + 8 o + 1)       when samples.csv is written (its rows are formatted a line at a time)
// plus 40 MB of program and 512 MiB for the pool of reused large blocks (large_vector.hpp).
// Disk: results.h5 8 (m + o) + 9 bytes, samples.csv 20 (m + o) + 30 + name bytes, checkpoint
// 8 (o + 1) bytes per sample and line.
RunFootprint estimate_run_footprint(const RunShape& shape);

// `growthuq sample`: the design of `variables` columns (12 bytes per value) and what computing
// and summarizing it needs besides, measured 112 bytes per sample for 7 variables: 16 m + 16
// bytes per sample, plus 40 MB and the block pool; disk its CSV text, about 19 bytes per value.
RunFootprint estimate_design_footprint(std::size_t samples, std::size_t variables);

// "12.3 MB" below a gigabyte, "44.9 GB" (as require_room's messages say it) from one on.
std::string readable_size(std::uint64_t bytes);

// MemAvailable of /proc/meminfo (what can be allocated without swapping), if readable.
std::optional<std::uint64_t> available_memory_bytes();

// Free space for an unprivileged writer on the file system that holds `directory` (or its
// nearest existing parent; a file to be written there works as well), if it can be asked.
// InputError naming `directory` when that file system stores no files at all (/proc, /sys: no
// blocks).
std::optional<std::uint64_t> available_disk_bytes(const std::string& directory);

// What the machine offers the run: memory for `processes` processes of the run on it, disk in
// the output directory. Unknown figures are not checked.
struct MachineRoom {
  std::optional<std::uint64_t> memory_bytes;
  std::optional<std::uint64_t> disk_bytes;
  int processes = 1;
};

// This machine's room: MemAvailable for `processes` processes of the run, and the free space
// where `output_directory` is (not checked when absent).
MachineRoom machine_room(int processes, const std::optional<std::string>& output_directory = std::nullopt);

// InputError "<location>: <samples_key> = '<samples>': the run needs about ..." (location and
// key as the user gave the count: "growthuq run" and "--samples", or the campaign file and
// "[campaign] samples") when the estimate, with a tenth kept back for everything else on the
// machine, does not fit: the message gives both figures and the largest sample count per line
// that fits (rounded down to two significant digits).
void require_room(const RunFootprint& footprint, const MachineRoom& room, std::string_view location,
                  std::string_view samples_key);

}  // namespace growthuq
