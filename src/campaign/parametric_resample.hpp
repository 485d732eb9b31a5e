// The draws of the data-uncertainty bootstrap (growthuq/campaign/data_uncertainty.hpp): in
// replicate b, a line's variable is redrawn from its law, as many values as the tubes behind it,
// and refitted. Raw-data lines refit every candidate family by least AIC, as their campaign did
// (data_uncertainty.cpp); a line file's law that states `tubes = N` is refitted here, within its
// own family by maximum likelihood (Eqs. (D5), src/distributions/README.md): the file states the
// family, so no family was chosen from the data and none is chosen in a replicate.
// truncated_normal, uniform and empirical laws have no ML fit in the engine, so they cannot state
// tubes (line_file.cpp refuses it). Laws without `tubes` stay fixed in every replicate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "growthuq/distributions/line_file.hpp"

namespace growthuq {

// `count` values drawn from `law` by the stream of `variable` of `line` in the replicate of
// `replicate_key`: RandomStream(derive_key(replicate_key, line + "/" + variable)), so a
// replicate's draws depend on its key alone, whichever process draws them.
std::vector<double> parametric_resample(const Distribution& law, std::size_t count, std::uint64_t replicate_key,
                                        std::string_view line, std::string_view variable);

// Each value of `values` drawn within its measurement uncertainty (same unit, one per value), for
// a raw line whose k comes from force curves ([force_curves] measurement_error = bootstrap,
// src/forcecurves/README.md, Eq. (C11)): value_i + u_i z_i, z_i standard normal, a non-positive
// result drawn again (a normal truncated at 0). The stream is
// RandomStream(derive_key(replicate_key, line + "/" + variable + "/measurement_error")), apart from
// the resample's own, so u = 0 leaves the values exactly as they were.
void add_measurement_error(std::vector<double>& values, const std::vector<double>& uncertainties,
                           std::uint64_t replicate_key, std::string_view line, std::string_view variable);

// True when a variable of `line` states tubes (the line's laws move in the bootstrap).
bool states_tubes(const LineDistributions& line);

// `line` (of the campaign's line `line_name`) in the replicate of `replicate_key`: every variable
// with tubes = N has its law replaced by the ML fit of its own family to N values drawn from
// it; the others are unchanged. InputError (location "data uncertainty, line <name>") when a
// refit fails.
LineDistributions resampled_stated_line(const LineDistributions& line, std::string_view line_name,
                                        std::uint64_t replicate_key);

}  // namespace growthuq
