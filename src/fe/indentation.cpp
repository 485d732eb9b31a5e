// indent(): one forward simulation in SI, around the dimensionless solver (fe/forward.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <span>
#include <string>

#include "fe/force_window.hpp"
#include "fe/forward.hpp"
#include "fe/geometry.hpp"
#include "fe/shell_fe_problem.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/fe/indentation.hpp"

namespace growthuq {
namespace {

bool positive_finite(double value) { return std::isfinite(value) && value > 0.0; }

void validate_input(const IndentationInput& input, std::string_view location) {
  validate(input.instrument, location);
  fe::check_shell_poisson(input.instrument.poisson_ratio, location);
  const auto check = [&](double value, std::string_view key, double unit, std::string_view expected) {
    if (!positive_finite(value)) throw_bad_value(location, key, format_double(value / unit), expected);
  };
  check(input.pressure, "p_MPa", 1e6, "a positive turgor in MPa");
  check(input.young, "E_MPa", 1e6, "a positive Young's modulus in MPa");
  check(input.thickness, "h_nm", 1e-9, "a positive wall thickness in nm");
  check(input.plasmolysed_diameter, "d0_um", 1e-6, "a positive plasmolysed diameter in um");
  if (!(std::isfinite(input.depth) && input.depth >= 0)) {
    throw_bad_value(location, "depth_um", format_double(input.depth * 1e6), "a non-negative depth in um (0: automatic)");
  }
  if (input.thickness >= 0.5 * input.plasmolysed_diameter) {
    throw_bad_value(location, "h_nm", format_double(input.thickness * 1e9), "a wall thinner than half the diameter d0");
  }
}

// The depth an automatic curve sizes its steps from: 1.5 times the depth at which the
// closed-form stiffness reaches the window's top, at least 5 % of d0 and at most
// fe::deepest_automatic_depth.
double estimated_depth(const IndentationInput& input, const ShellFeOptions& options) {
  const double d0 = input.plasmolysed_diameter;
  const auto closed = thin_shell_forward(input.pressure, input.young, input.thickness, d0, input.instrument);
  double depth = 0.2 * d0;
  if (closed.status == SampleStatus::ok && closed.k_measured > 0) depth = 1.5 * options.force_window[1] / closed.k_measured;
  return std::clamp(depth, 0.05 * d0, fe::deepest_automatic_depth * d0);
}

}  // namespace

IndentationCurve indent(const IndentationInput& input, const ShellFeOptions& options, bool keep_field,
                        const IndentationProgress& progress) {
  const auto start = std::chrono::steady_clock::now();
  const std::string location = "shell_fe indent";
  options.validate(location);
  validate_input(input, location);

  IndentationCurve curve;
  const double d0 = input.plasmolysed_diameter, E = input.young;
  fe::ForwardProblem problem = fe::make_problem(options, d0, input.instrument.probe_radius_m, input.instrument.poisson_ratio);
  problem.pressure = input.pressure / E;
  if (input.thickness_kind == ThicknessKind::unstressed) {
    problem.thickness = input.thickness / d0;
  } else if (fe::make_wall_geometry(problem)->has_far_field()) {
    // The measured h is the turgid wall's: h0 through the far field's thickness stretch (the
    // inverse maps h the same way, so forward and inverse agree).
    problem.thickness = fe::far_field_unstressed_thickness(options.law, problem.pressure, input.thickness / d0,
                                                           input.instrument.poisson_ratio);
    if (!(problem.thickness > 0)) {
      curve.status = SampleStatus::burst;
      curve.message = "the far-field tube bursts at this p/E and turgid thickness";
      return curve;
    }
  } else {
    // Sphere or file: the thickness stretch of the finite-element inflation, to a fixed point.
    problem.thickness = input.thickness / d0;
    for (int pass = 0; pass < 8; ++pass) {
      const fe::ForwardResult inflated = fe::simulate_inflation(problem);
      curve.newton_iterations += inflated.newton_iterations;
      if (inflated.status != SampleStatus::ok || !(inflated.thickness_stretch > 0)) {
        curve.status = inflated.status;
        curve.message = "inflation for the turgid thickness: " + inflated.message;
        return curve;
      }
      const double next = input.thickness / d0 / inflated.thickness_stretch;
      const bool settled = std::abs(next - problem.thickness) <= 1e-9 * next;
      problem.thickness = next;
      if (settled) break;
    }
  }
  curve.unstressed_thickness = problem.thickness * d0;

  const bool automatic = input.depth == 0;
  const double low = options.force_window[0], high = options.force_window[1];
  if (automatic) {
    // The curve runs until its force passes the window's top, bounded by
    // fe::deepest_automatic_depth: the fit reads the curve up to its first point past the top
    // and nothing beyond, so k is final there. Its steps are sized from the closed form's
    // estimate of the depth, and continue past it when the estimate falls short.
    const double top = high / (E * d0 * d0);
    problem.max_depth = fe::deepest_automatic_depth;
    problem.step_depth = estimated_depth(input, options) / d0;
    problem.long_enough = [top](std::span<const double>, std::span<const double> force) { return force.back() >= top; };
  } else {
    problem.max_depth = input.depth / d0;
  }
  if (progress) problem.on_depth = [&](double reached) { progress(reached * d0, problem.max_depth * d0); };
  const fe::ForwardResult result = fe::simulate_forward(problem);
  fe::curve_in_si(result, d0, E, curve);
  if (keep_field) curve.field = fe::field_in_si(result, d0, E);
  curve.status = result.status;
  curve.message = result.message;
  const fe::WindowFit fit = fe::fit_force_window(curve.depth, curve.force, low, high);
  if (fit.status == fe::WindowFitStatus::ok) {
    curve.stiffness = fit.slope;
    curve.measured_stiffness = measured_stiffness(fit.slope, input.instrument);
    // Contact radius at the window's top, interpolated as the force was.
    for (std::size_t i = 1; i < curve.depth.size() && i < curve.contact_radius.size(); ++i) {
      if (curve.depth[i] < fit.top_depth) continue;
      const double t = (fit.top_depth - curve.depth[i - 1]) / (curve.depth[i] - curve.depth[i - 1]);
      curve.window_contact_radius = curve.contact_radius[i - 1] + t * (curve.contact_radius[i] - curve.contact_radius[i - 1]);
      break;
    }
    // A solver failure beyond the window's top leaves k intact: k is the value, the curve
    // simply ends early (its status is kept in the message).
    if (curve.status != SampleStatus::ok) {
      curve.message = "k from the curve up to where the solver stopped (" + std::string(to_string(curve.status)) +
                      (curve.message.empty() ? "" : ": " + curve.message) + ")";
      curve.status = SampleStatus::ok;
    }
  } else if (curve.status == SampleStatus::ok) {  // else the solver's own failure, before the window's top
    curve.status = SampleStatus::window_not_reached;
    curve.message = "the force reached " + format_double(fit.max_force * 1e6) + " uN at " +
                    format_double(curve.depth.empty() ? 0.0 : curve.depth.back() * 1e6) + " um, below the window's top " +
                    format_double(high * 1e6) + " uN" + (automatic ? "" : " (a larger --depth-um reaches it)");
  }
  curve.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return curve;
}

}  // namespace growthuq
