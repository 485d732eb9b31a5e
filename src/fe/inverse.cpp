// invert_indentation(): (k, h, d, d0; rho, nu, k_sys) -> (p, E). Three steps (src/fe/README.md,
// "Inverse"): the series correction of the sensor; p/E and h0 from the turgid diameter and
// thickness (far field, refined by finite-element inflation of the mesh); E from one
// dimensionless force curve at that p/E (forces scale as E d0^2), a 1-D root in E.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "fe/far_field.hpp"
#include "fe/forward.hpp"
#include "fe/geometry.hpp"
#include "fe/modulus_from_curve.hpp"
#include "fe/shell_fe_problem.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/fe/indentation.hpp"
#include "growthuq/mechanics/thin_shell.hpp"

namespace growthuq {
namespace {

bool positive_finite(double value) { return std::isfinite(value) && value > 0.0; }

// What the inflation step found: the dimensionless state the force curve is computed at.
struct Inflated {
  SampleStatus status = SampleStatus::ok;
  std::string message;
  double pressure = 0.0;   // p/E
  double thickness = 0.0;  // h0/d0
};

// h0/d0 for the turgid h/d0 at P = (p/E)/(h0/d0): the far field's thickness stretch (tube),
// the mapping indent() uses too, so that forward and inverse agree.
double unstressed_at(ShellFeLaw law, double p_over_t, double turgid, double nu) {
  double thickness = turgid;
  for (int pass = 0; pass < 100; ++pass) {
    const fe::FarFieldInflation state = fe::far_field_inflation(fe::far_field_law(law), p_over_t * thickness, thickness, nu);
    if (state.burst || !(state.thickness_stretch > 0)) return 0.0;
    const double next = turgid / state.thickness_stretch;
    if (std::abs(next - thickness) <= 1e-13 * next) return next;
    thickness = next;
  }
  return 0.0;
}

// The far-field state, then, when the mesh's inflated diameter differs from the measured one
// by more than the options' tolerance, a secant iteration in ln P on finite-element inflations
// (the first slope from the far field), at most 6 solves.
Inflated inflate(const ShellFeMeasurement& m, const Instrument& instrument, const ShellFeOptions& options,
                 fe::ForwardProblem problem, ShellFeInverse& inverse) {
  Inflated inflated;
  const double d0 = m.plasmolysed_diameter, lambda = m.diameter / d0, turgid = m.thickness / d0;
  const double nu = instrument.poisson_ratio;
  // FE1's closed-form far-field inverse: the membrane state depends on p/E and h0/d0 only
  // through G = (p/E)/(h0/d0), and G follows explicitly from the hoop stretch.
  const fe::FarFieldInverse far = fe::far_field_inverse(fe::far_field_law(options.law), lambda, turgid, nu);
  if (far.status != fe::FarFieldInverseStatus::ok) {
    inflated.status = SampleStatus::no_inflation_state;
    inflated.message = std::string("far field at d/d0 = ") + format_double(lambda) + ": " +
                       (far.status == fe::FarFieldInverseStatus::beyond_pressure_maximum ? "past the pressure maximum (burst)"
                        : far.status == fe::FarFieldInverseStatus::thickness_collapsed
                            ? "the plane-stress thickness has vanished"
                            : "no positive pressure gives it");
    return inflated;
  }
  inverse.far_field_pressure_over_young = far.pressure_over_E;
  inflated.pressure = far.pressure_over_E;
  inflated.thickness = far.h0_over_d0;
  if (!std::isfinite(options.inflation_tolerance)) return inflated;

  const bool far_field = fe::make_wall_geometry(problem)->has_far_field();
  // State at u = ln P: thickness from the far field (tube) or the last inflation's stretch.
  double u = std::log(far.pressure_over_E / far.h0_over_d0);
  double thickness = far.h0_over_d0;
  const auto residual = [&](double at, double& h0, bool& failed) {
    if (far_field) h0 = unstressed_at(options.law, std::exp(at), turgid, nu);
    if (!(h0 > 0)) {
      // The trial pressure is past the far field's pressure maximum: no wall, so no solve.
      failed = true;
      inflated.status = SampleStatus::no_inflation_state;
      inflated.message = "finite-element inflation: the wall bursts at (p/E)/(h0/d0) = " + format_double(std::exp(at)) +
                         " before the mesh reaches d/d0 = " + format_double(lambda);
      return std::numeric_limits<double>::quiet_NaN();
    }
    problem.pressure = std::exp(at) * h0;
    problem.thickness = h0;
    const fe::ForwardResult result = fe::simulate_inflation(problem);
    ++inverse.inflation_solves;
    inverse.newton_iterations += result.newton_iterations;
    failed = result.status != SampleStatus::ok || !(result.turgid_diameter > 0);
    if (failed) {
      inflated.status = result.status == SampleStatus::ok ? SampleStatus::burst : result.status;
      inflated.message = "finite-element inflation: " + result.message;
      return std::numeric_limits<double>::quiet_NaN();
    }
    if (!far_field) h0 = turgid / result.thickness_stretch;
    return result.turgid_diameter / lambda - 1.0;
  };
  bool failed = false;
  double r = residual(u, thickness, failed);
  if (failed) return inflated;
  inverse.far_field_diameter_error = r;
  // The far field's slope d(ln lambda)/d(ln P), by a central difference of the closed solution.
  const auto far_lambda = [&](double at) {
    return fe::far_field_inflation(fe::far_field_law(options.law), std::exp(at) * far.h0_over_d0, far.h0_over_d0, nu).hoop_stretch;
  };
  double slope = (std::log(far_lambda(u + 1e-4)) - std::log(far_lambda(u - 1e-4))) / 2e-4;
  if (!(std::isfinite(slope) && slope > 0)) slope = 1.0;
  double previous_u = u, previous_r = r;
  for (int solve = 1; std::abs(r) > options.inflation_tolerance; ++solve) {
    if (solve >= 6) {
      inflated.status = SampleStatus::no_inflation_state;
      inflated.message = "finite-element inflation did not reach d/d0 = " + format_double(lambda) + " in 6 solves (off by " +
                         format_double(r) + ")";
      return inflated;
    }
    if (solve > 1 && r != previous_r) slope = (r - previous_r) / (u - previous_u);
    previous_u = u;
    previous_r = r;
    u -= r / slope;
    r = residual(u, thickness, failed);
    // Near the law's pressure maximum the diameter's slope in P grows without bound, and a
    // secant step can land past the burst: step back halfway towards the last state (a trial
    // past the burst costs no solve).
    for (int cut = 0; cut < 8 && failed && inflated.status == SampleStatus::no_inflation_state && u > previous_u; ++cut) {
      u = 0.5 * (u + previous_u);
      failed = false;
      r = residual(u, thickness, failed);
    }
    if (failed) return inflated;
  }
  inflated.pressure = std::exp(u) * thickness;
  inflated.thickness = thickness;
  return inflated;
}

}  // namespace

ShellFeInverse invert_indentation(const ShellFeMeasurement& m, const Instrument& instrument,
                                  const ShellFeOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  options.validate("shell_fe inverse");
  validate(instrument, "shell_fe inverse");
  fe::check_shell_poisson(instrument.poisson_ratio, "shell_fe inverse");
  ShellFeInverse inverse;
  const auto finish = [&](SampleStatus status, std::string message) {
    inverse.status = status;
    inverse.message = std::move(message);
    inverse.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return inverse;
  };
  if (!positive_finite(m.stiffness) || !positive_finite(m.thickness) || !positive_finite(m.diameter) ||
      !positive_finite(m.plasmolysed_diameter)) {
    return finish(SampleStatus::invalid_input, "k, h, d and d0 must be positive and finite");
  }
  if (!(m.diameter > m.plasmolysed_diameter)) return finish(SampleStatus::invalid_input, "d <= d0: no inflation");
  if (m.thickness >= 0.5 * m.plasmolysed_diameter) return finish(SampleStatus::invalid_input, "h >= d0/2: not a shell");
  // Probe and tube in series (Eq. (M8), src/mechanics/README.md).
  if (m.stiffness >= instrument.sensor_stiffness_N_per_m) {
    return finish(SampleStatus::stiffness_at_sensor_limit, "measured k >= k_sys");
  }
  const double k = tube_stiffness(m.stiffness, instrument);
  const double d0 = m.plasmolysed_diameter;

  // The closed form's E: the root's first estimate (any positive E would do; a good one saves
  // bracketing steps).
  const TurgorResult turgor = invert_turgor(m.stiffness, m.diameter, d0, instrument);
  if (turgor.status == SampleStatus::ok) {
    const ModulusResult modulus = invert_modulus(turgor.p, m.diameter, d0, m.thickness);
    if (modulus.status == SampleStatus::ok) inverse.closed_form_young = modulus.E;
  }

  fe::ForwardProblem problem = fe::make_problem(options, d0, instrument.probe_radius_m, instrument.poisson_ratio);
  const Inflated inflated = inflate(m, instrument, options, problem, inverse);
  if (inflated.status != SampleStatus::ok) return finish(inflated.status, inflated.message);
  inverse.pressure_over_young = inflated.pressure;
  inverse.unstressed_thickness = inflated.thickness * d0;
  problem.pressure = inflated.pressure;
  problem.thickness = inflated.thickness;

  const double estimate = inverse.closed_form_young > 0 ? inverse.closed_form_young : k / (0.05 * d0);
  const double low = options.force_window[0], high = options.force_window[1];
  // One curve, run until the root in E no longer needs more of it: until the window's top at
  // the E that k needs lies on it (k(E) reads the curve up to that top and nothing beyond, so E
  // is final there) or there is no such E, bounded by fe::deepest_automatic_depth. Its steps
  // are sized from 1.5 times the depth at which k reaches the window's top, within 5-60 % of
  // d0, and continue past it.
  problem.max_depth = fe::deepest_automatic_depth;
  problem.step_depth = std::clamp(1.5 * high / (k * d0), 0.05, fe::deepest_automatic_depth);
  problem.long_enough = [&](std::span<const double> depth, std::span<const double> force) {
    return fe::match_modulus(depth, force, k, d0, low, high, estimate).status != fe::ModulusMatchStatus::curve_too_short;
  };
  const fe::ForwardResult result = fe::simulate_forward(problem);
  inverse.newton_iterations += result.newton_iterations;
  const fe::ModulusMatch match = fe::match_modulus(result.depth, result.force, k, d0, low, high, estimate);
  if (match.status == fe::ModulusMatchStatus::ok) {
    inverse.young = match.young;
    inverse.pressure = inflated.pressure * match.young;
    inverse.fitted_stiffness = match.fitted_stiffness;
    return finish(SampleStatus::ok, result.status == SampleStatus::ok
                                         ? ""
                                         : "E from the curve up to where the solver stopped (" +
                                               std::string(to_string(result.status)) + ")");
  }
  if (result.status != SampleStatus::ok) return finish(result.status, "force curve: " + result.message);
  if (match.status != fe::ModulusMatchStatus::curve_too_short) {
    return finish(SampleStatus::no_modulus_root, "no E gives k = " + format_double(k) + " N/m over the window");
  }
  return finish(SampleStatus::window_not_reached, "the curve to " + format_double(problem.max_depth) +
                                                       " d0 is too short for the window at the E that k needs");
}

}  // namespace growthuq
