// Writing result files so that a failure never leaves a half-written file that looks
// complete, and an existing result is never overwritten unless the user asked for it.
#pragma once

#include <string>
#include <string_view>

namespace growthuq {

enum class Overwrite { refuse, allow };

// Writes `content` to `path` through "<path>.partial" and an atomic rename. With
// Overwrite::refuse an existing `path` is an InputError that names it and suggests --force.
// I/O failures are InputErrors naming the path and the system's reason.
void write_file_atomically(const std::string& path, std::string_view content,
                           Overwrite overwrite);

// InputError when `path` exists and overwriting was not allowed (checked before long work
// starts, so a run does not fail only at its end).
void check_can_write(const std::string& path, Overwrite overwrite);

}  // namespace growthuq
