#include "growthuq/campaign/run_footprint.hpp"

#include <sys/statvfs.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "growthuq/core/error.hpp"

namespace growthuq {

namespace {

constexpr std::uint64_t program_bytes = 40'000'000;             // code, libraries, HDF5's own buffers
constexpr std::uint64_t block_pool_bytes = std::uint64_t{1} << 29;  // most_bytes_kept, large_blocks.cpp

// 12 bytes per input (stratum rank and value), 8 per output, 1 for the status.
std::uint64_t line_bytes_per_sample(const RunShape& shape) {
  return 12 * shape.largest_inputs + 8 * shape.largest_outputs + 1;
}

// The largest samples per line whose estimate stays within `budget`, rounded down to two
// significant digits (a count to type, not to the sample; 0 when none fits).
std::uint64_t largest_fitting(std::uint64_t budget, std::uint64_t fixed, std::uint64_t per_sample) {
  if (budget <= fixed || per_sample == 0) return 0;
  const std::uint64_t exact = (budget - fixed) / per_sample;
  std::uint64_t step = 1;
  while (exact / step >= 100) step *= 10;
  return exact / step * step;
}

// "44.9 GB"
std::string gigabytes(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GB", static_cast<double>(bytes) / 1e9);
  return text;
}

}  // namespace

std::string readable_size(std::uint64_t bytes) {
  if (bytes >= 1'000'000'000) return gigabytes(bytes);
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / 1e6);
  return text;
}

RunShape run_shape(const PreparedCampaign& campaign, bool checkpoint) {
  RunShape shape;
  const Campaign& c = campaign.campaign();
  shape.samples = c.samples;
  shape.lines = campaign.lines().size();
  shape.largest_outputs = campaign.computed_outputs().size();
  for (const PreparedLine& line : campaign.lines()) {
    shape.largest_inputs = std::max(shape.largest_inputs, line.design_variables.variables.size());
    shape.longest_line_name = std::max(shape.longest_line_name, line.campaign_line.name.size());
  }
  shape.csv = c.formats.csv;
  shape.hdf5 = c.formats.hdf5;
  shape.checkpoint = checkpoint;
  return shape;
}

RunFootprint estimate_run_footprint(const RunShape& shape) {
  const std::uint64_t m = shape.largest_inputs;
  const std::uint64_t o = shape.largest_outputs;
  const std::uint64_t line = line_bytes_per_sample(shape);
  RunFootprint footprint;
  footprint.samples = shape.samples;
  footprint.what = std::to_string(shape.lines) + (shape.lines == 1 ? " line" : " lines") + " of up to " +
                   std::to_string(m) + " inputs and " + std::to_string(o) + " outputs";
  footprint.fixed_memory_bytes = program_bytes + block_pool_bytes;
  footprint.memory_bytes_per_sample = 20 * m + 4 * o + 36 + (shape.lines > 1 ? line * 3 / 5 : 0) + (shape.csv ? line : 0);
  footprint.memory_bytes = footprint.fixed_memory_bytes + footprint.memory_bytes_per_sample * shape.samples;
  std::uint64_t disk = 0;
  if (shape.hdf5) disk += 8 * (m + o) + 9;
  if (shape.csv) disk += 20 * (m + o) + 30 + shape.longest_line_name;
  if (shape.checkpoint) disk += 8 * (o + 1);
  footprint.disk_bytes_per_sample = disk * shape.lines;
  footprint.disk_bytes = footprint.disk_bytes_per_sample * shape.samples;
  return footprint;
}

RunFootprint estimate_design_footprint(std::size_t samples, std::size_t variables) {
  const std::uint64_t m = variables;
  RunFootprint footprint;
  footprint.samples = samples;
  footprint.what = "a design of " + std::to_string(m) + " variables";
  footprint.fixed_memory_bytes = program_bytes + block_pool_bytes;
  footprint.memory_bytes_per_sample = 16 * m + 16;
  footprint.memory_bytes = footprint.fixed_memory_bytes + footprint.memory_bytes_per_sample * samples;
  footprint.disk_bytes_per_sample = 19 * m + 2;
  footprint.disk_bytes = footprint.disk_bytes_per_sample * samples;
  return footprint;
}

std::optional<std::uint64_t> available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kilobytes = 0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit) {
    if (key == "MemAvailable:") return kilobytes * 1024;
  }
  return std::nullopt;
}

std::optional<std::uint64_t> available_disk_bytes(const std::string& directory) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::path at = fs::absolute(directory.empty() ? fs::path(".") : fs::path(directory), error);
  if (error) return std::nullopt;
  while (!fs::exists(at, error) && at.has_parent_path() && at.parent_path() != at) at = at.parent_path();
  struct statvfs space {};
  if (statvfs(at.c_str(), &space) != 0) return std::nullopt;
  // No blocks at all: /proc, /sys and their kind keep no files, and their "0 bytes free" would
  // read as a full disk.
  if (space.f_blocks == 0) {
    throw InputError(directory.empty() ? at.string() : directory,
                     "is on a pseudo file system that stores no files (such as /proc or /sys): expected a place on a disk");
  }
  return static_cast<std::uint64_t>(space.f_bavail) * space.f_frsize;
}

MachineRoom machine_room(int processes, const std::optional<std::string>& output_directory) {
  MachineRoom room;
  room.memory_bytes = available_memory_bytes();
  if (output_directory) room.disk_bytes = available_disk_bytes(*output_directory);
  room.processes = processes;
  return room;
}

void require_room(const RunFootprint& footprint, const MachineRoom& room, std::string_view location,
                  std::string_view samples_key) {
  const auto refuse = [&](const std::string& need, std::uint64_t fitting) {
    throw InputError(std::string(location),
                     std::string(samples_key) + " = '" + std::to_string(footprint.samples) + "': " + need + "; " +
                         (fitting == 0 ? std::string("not even one sample per line fits")
                                       : "at most " + std::to_string(fitting) + " samples per line fit"));
  };
  if (room.memory_bytes) {
    const int processes = std::max(room.processes, 1);
    // A tenth is kept back for the system and whatever else runs.
    const std::uint64_t budget = *room.memory_bytes / 10 * 9 / static_cast<std::uint64_t>(processes);
    if (footprint.memory_bytes > budget) {
      const std::string each = processes == 1 ? "" : " for each of the " + std::to_string(processes) + " processes on this machine";
      refuse("the run needs about " + gigabytes(footprint.memory_bytes) + " of memory" + each + " (" + footprint.what +
                 ", about " + std::to_string(footprint.memory_bytes_per_sample) +
                 " bytes per sample and line) and this machine has " + gigabytes(*room.memory_bytes) + " available",
             largest_fitting(budget, footprint.fixed_memory_bytes, footprint.memory_bytes_per_sample));
    }
  }
  if (room.disk_bytes && footprint.disk_bytes > *room.disk_bytes / 10 * 9) {
    refuse("the run writes about " + gigabytes(footprint.disk_bytes) + " (" + footprint.what +
               ") and the file system it writes to has " + gigabytes(*room.disk_bytes) + " free",
           largest_fitting(*room.disk_bytes / 10 * 9, 0, footprint.disk_bytes_per_sample));
  }
}

}  // namespace growthuq
