// Outcome of a finite-element solve: numerical failures are statuses, never exceptions.
#pragma once

#include <string_view>

namespace growthuq::fe {

enum class FeStatus { ok, not_converged, burst, contact_lost, probe_beyond_mesh, invalid_input };
std::string_view to_string(FeStatus);

}  // namespace growthuq::fe
