#include "fe/status.hpp"

namespace growthuq::fe {

std::string_view to_string(FeStatus status) {
  switch (status) {
    case FeStatus::ok: return "ok";
    case FeStatus::not_converged: return "not_converged";
    case FeStatus::burst: return "burst";
    case FeStatus::contact_lost: return "contact_lost";
    case FeStatus::probe_beyond_mesh: return "probe_beyond_mesh";
    case FeStatus::invalid_input: return "invalid_input";
  }
  return "unknown";
}

}  // namespace growthuq::fe
