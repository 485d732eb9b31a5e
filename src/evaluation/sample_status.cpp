#include "growthuq/evaluation/sample_status.hpp"

namespace growthuq {

std::string_view to_string(SampleStatus status) {
  switch (status) {
    case SampleStatus::ok: return "ok";
    case SampleStatus::invalid_input: return "invalid_input";
    case SampleStatus::lambda_not_above_one: return "lambda_not_above_one";
    case SampleStatus::beyond_membrane_limit: return "beyond_membrane_limit";
    case SampleStatus::burst: return "burst";
    case SampleStatus::no_growth: return "no_growth";
    case SampleStatus::fit_failed: return "fit_failed";
    case SampleStatus::stiffness_at_sensor_limit: return "stiffness_at_sensor_limit";
    case SampleStatus::out_of_range: return "out_of_range";
    case SampleStatus::unstable_branch: return "unstable_branch";
  }
  return "unknown";
}

std::string_view describe(SampleStatus status) {
  switch (status) {
    case SampleStatus::ok: return "evaluated";
    case SampleStatus::invalid_input: return "an input is not finite or outside its physical domain";
    case SampleStatus::lambda_not_above_one: return "turgid diameter not above plasmolysed diameter (lambda <= 1)";
    case SampleStatus::beyond_membrane_limit: return "(1 - nu^2) ln(lambda) >= 1: beyond the thin-membrane limit, turgor unbounded";
    case SampleStatus::burst: return "the wall cannot hold the pressure: c d0 > 1/e, no equilibrium diameter";
    case SampleStatus::no_growth: return "turgor at or below the yield pressure p0: no growth (v = 0)";
    case SampleStatus::fit_failed: return "the relaxation fit failed or is ill-conditioned";
    case SampleStatus::stiffness_at_sensor_limit: return "measured stiffness at or above the sensor stiffness k_sys";
    case SampleStatus::out_of_range: return "a result is beyond double precision range";
    case SampleStatus::unstable_branch: return "d/d0 > e: on the unstable branch of the hoop relation, the forward model gives a smaller diameter";
  }
  return "unknown status";
}

}  // namespace growthuq
