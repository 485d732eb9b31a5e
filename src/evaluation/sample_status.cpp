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
    case SampleStatus::not_converged: return "not_converged";
    case SampleStatus::contact_lost: return "contact_lost";
    case SampleStatus::probe_beyond_mesh: return "probe_beyond_mesh";
    case SampleStatus::window_not_reached: return "window_not_reached";
    case SampleStatus::no_inflation_state: return "no_inflation_state";
    case SampleStatus::no_modulus_root: return "no_modulus_root";
    case SampleStatus::outside_correction: return "outside_correction";
    case SampleStatus::probe_engulfed: return "probe_engulfed";
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
    case SampleStatus::not_converged: return "finite-element model: Newton's method did not converge, even with the load step cut";
    case SampleStatus::contact_lost: return "finite-element model: the probe lost contact with the wall";
    case SampleStatus::probe_beyond_mesh: return "finite-element model: the contact left the meshed region";
    case SampleStatus::window_not_reached: return "finite-element model: the force curve never reached the force window's top";
    case SampleStatus::no_inflation_state: return "finite-element model: no pressure gives the measured turgid diameter and thickness";
    case SampleStatus::no_modulus_root: return "finite-element model: no modulus gives the measured k over the force window";
    case SampleStatus::outside_correction: return "fidelity corrected: the tube lies outside the region the correction was fitted on";
    case SampleStatus::probe_engulfed:
      return "finite-element model: the load steps stall with the wall wrapped round the probe to its equator "
             "(contact radius >= 0.95 rho), before the force window's top";
  }
  return "unknown status";
}

}  // namespace growthuq
