// The whole model through the public API (coarse mesh: these test the scaling and the
// inverse's consistency, not the mesh's accuracy): E x 10 at fixed p/E gives forces x 10, and
// the inverse recovers the p and E a forward simulation was run at.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "fe/force_window.hpp"
#include "fe/forward.hpp"
#include "arabidopsis_like_tube.hpp"
#include "growthuq/fe/indentation.hpp"

using namespace growthuq;
using growthuq::testing::arabidopsis_like;

namespace {

ShellFeOptions coarse() {
  ShellFeOptions options;
  options.mesh = ShellFeMesh::coarse;
  return options;
}

// The inverse of what a forward curve measures: its k and turgid diameter, the turgid h and the
// plasmolysed d0 as a lab records them.
ShellFeInverse invert_measured(const IndentationCurve& forward, const IndentationInput& input, const ShellFeOptions& options) {
  ShellFeMeasurement tube;
  tube.stiffness = forward.measured_stiffness;
  tube.thickness = input.thickness;  // turgid, as measured
  tube.diameter = forward.turgid_diameter;
  tube.plasmolysed_diameter = input.plasmolysed_diameter;
  return invert_indentation(tube, input.instrument, options);
}

}  // namespace

TEST_CASE("shell_fe model: E x 10 at fixed p/E gives forces x 10 (and the same diameter)") {
  IndentationInput input = arabidopsis_like();
  // The same depth for both, so both runs take the same dimensionless steps; 1 um is short of the
  // soft tube's window top (status window_not_reached: its path complete, but no k), not of the
  // stiff one's (status ok).
  input.depth = 1.0e-6;
  const ShellFeOptions options = coarse();
  const IndentationCurve soft = indent(input, options);
  input.pressure *= 10;
  input.young *= 10;
  const IndentationCurve stiff = indent(input, options);
  REQUIRE(soft.status == SampleStatus::window_not_reached);
  REQUIRE(stiff.status == SampleStatus::ok);
  REQUIRE(soft.depth.back() == doctest::Approx(1.0e-6).epsilon(1e-12));
  REQUIRE(soft.depth.size() == stiff.depth.size());
  // Both solve the same dimensionless problem: 10p and 10E are exact here, so p/E is the same
  // double, and the exact contact has no penalty whose raises could follow another path. The
  // forces are E d0^2 G (eq. 1 of src/fe/README.md) to the rounding of the conversion.
  for (std::size_t i = 1; i < soft.depth.size(); ++i) {
    CHECK(stiff.depth[i] == doctest::Approx(soft.depth[i]).epsilon(1e-12));
    CHECK(stiff.force[i] == doctest::Approx(10 * soft.force[i]).epsilon(1e-10));
  }
  CHECK(stiff.turgid_diameter == doctest::Approx(soft.turgid_diameter).epsilon(1e-9));
}

TEST_CASE("shell_fe model: the inverse recovers the p and E of a forward simulation") {
  const IndentationInput input = arabidopsis_like();
  ShellFeOptions options = coarse();
  // The inflation refinement stops at |d_FE/d - 1| <= tolerance; d ln(lambda)/d ln(p/E) is
  // about ln(lambda) ~ 0.18 here, so 1e-8 in d gives about 6e-8 in p/E.
  options.inflation_tolerance = 1e-8;
  std::vector<double> reported, targets;
  const IndentationCurve forward =
      indent(input, options, false, [&](double depth, double max_depth) { reported.push_back(depth), targets.push_back(max_depth); });
  REQUIRE(forward.status == SampleStatus::ok);
  REQUIRE(forward.stiffness > 0);
  // The progress follows the curve's steps: one report per recorded point after the first
  // (depth 0), the depths it reports and the curve's the same, each towards the deepest an
  // automatic curve may go (0.6 d0), which it stops short of at the window's top.
  REQUIRE_FALSE(reported.empty());
  REQUIRE(reported.size() + 1 == forward.depth.size());
  for (std::size_t i = 0; i < reported.size(); ++i) {
    CHECK(reported[i] == doctest::Approx(forward.depth[i + 1]).epsilon(1e-12));
    CHECK(targets[i] == doctest::Approx(fe::deepest_automatic_depth * input.plasmolysed_diameter).epsilon(1e-12));
  }
  CHECK(reported.back() < fe::deepest_automatic_depth * input.plasmolysed_diameter);

  const ShellFeInverse inverse = invert_measured(forward, input, options);
  INFO(inverse.message);
  REQUIRE(inverse.status == SampleStatus::ok);
  // What limits the round trip: (1) p/E from the inflation root, ~1e-7 (above); (2) E from
  // Brent, 1e-10; (3) the inverse's curve is solved to another depth than the forward's, so
  // its load steps differ, and k read from each curve carries the linear interpolation's
  // O(step^2) error (test_force_window.cpp bounds it: 3 e / L with e the chord's deviation).
  // (3) dominates; 2e-3 bounds it at the coarse mesh's steps (measured: see the commit).
  CHECK(inverse.young == doctest::Approx(input.young).epsilon(2e-3));
  CHECK(inverse.pressure == doctest::Approx(input.pressure).epsilon(2e-3));
  CHECK(inverse.pressure_over_young == doctest::Approx(input.pressure / input.young).epsilon(1e-6));
  CHECK(inverse.unstressed_thickness == doctest::Approx(forward.unstressed_thickness).epsilon(1e-6));
  CHECK(inverse.fitted_stiffness == doctest::Approx(forward.stiffness).epsilon(1e-8));
}

TEST_CASE("shell_fe model: statuses, not exceptions, for measurements outside the model") {
  const IndentationInput input = arabidopsis_like();
  const ShellFeOptions options = coarse();
  ShellFeMeasurement tube{2.0, 200e-9, 5.0e-6, 5.35e-6};  // d < d0
  CHECK(invert_indentation(tube, input.instrument, options).status == SampleStatus::invalid_input);
  tube = {2.0, 200e-9, 6.56e-6, 5.35e-6};
  Instrument sensor = input.instrument;
  sensor.sensor_stiffness_N_per_m = 1.5;
  CHECK(invert_indentation(tube, sensor, options).status == SampleStatus::stiffness_at_sensor_limit);
  tube = {2.0, 200e-9, 6.56e-6 * 100, 5.35e-6};  // d/d0 = 123: beyond any inflated state
  CHECK(invert_indentation(tube, input.instrument, options).status == SampleStatus::no_inflation_state);
}

TEST_CASE("shell_fe model: a soft tube whose window's top lies deeper than 0.45 d0 is answered, and inverted") {
  // The Arabidopsis-like tube at p = 0.3 MPa, E = 30 MPa under a 0.5 um probe: its curve reaches
  // the window's top (4 uN) near 2.54 um = 0.47 d0 (measured: growthuq indent --p-MPa 0.3
  // --E-MPa 30 --h-nm 200 --d0-um 5.35 --rho-um 0.5 --mesh coarse), beyond the 0.45 d0 the
  // forward and the inverse were held to before (they ended window_not_reached there).
  IndentationInput input = arabidopsis_like();
  input.pressure = 0.3e6;
  input.young = 30e6;
  input.instrument.probe_radius_m = 0.5e-6;
  ShellFeOptions options = coarse();
  options.inflation_tolerance = 1e-8;
  const IndentationCurve forward = indent(input, options);
  INFO(forward.message);
  REQUIRE(forward.status == SampleStatus::ok);
  const fe::WindowFit fit = fe::fit_force_window(forward.depth, forward.force, options.force_window[0], options.force_window[1]);
  REQUIRE(fit.status == fe::WindowFitStatus::ok);
  CHECK(fit.top_depth > 0.45 * input.plasmolysed_diameter);
  CHECK(forward.depth.back() <= fe::deepest_automatic_depth * input.plasmolysed_diameter * (1 + 1e-12));

  const ShellFeInverse inverse = invert_measured(forward, input, options);
  INFO(inverse.message);
  REQUIRE(inverse.status == SampleStatus::ok);
  // The round trip's bound of the test above (the two curves' load steps differ).
  CHECK(inverse.young == doctest::Approx(input.young).epsilon(2e-3));
  CHECK(inverse.pressure == doctest::Approx(input.pressure).epsilon(2e-3));
}

TEST_CASE("shell_fe model: a soft thin wall under a small probe that wraps it is probe_engulfed, not not_converged") {
  // p = 0.3 MPa, E = 60 MPa, turgid h = 100 nm, d0 = 5 um, rho = 0.25 um: the wall wraps the
  // probe down to its equator at about 1.96 um, short of the window's top (4 uN) and of the
  // automatic depth, and the load steps stall there (src/fe/README.md, "Statuses and deep
  // curves": growthuq indent --p-MPa 0.3 --E-MPa 60 --h-nm 100 --d0-um 5 --rho-um 0.25 --mesh coarse).
  IndentationInput input = arabidopsis_like();
  input.pressure = 0.3e6;
  input.young = 60e6;
  input.thickness = 100e-9;
  input.plasmolysed_diameter = 5e-6;
  const ShellFeOptions options = coarse();
  const IndentationCurve curve = indent(input, options);
  INFO(curve.message);
  CHECK(curve.status == SampleStatus::probe_engulfed);
  REQUIRE(curve.contact_radius.size() == curve.force.size());
  REQUIRE(curve.force.size() > 2);
  // Short of the window's top: no k.
  CHECK(curve.force.back() < options.force_window[1]);
  CHECK(curve.stiffness == 0.0);
  // The contact reached the probe's equator: within 5 % of rho, and never beyond rho (a node held
  // on the sphere is at most rho from its axis), where at a quarter of the depth it was well
  // inside (measured 0.61 rho).
  const double rho = input.instrument.probe_radius_m;
  CHECK(curve.contact_radius.back() >= fe::engulfed_contact_fraction * rho);
  CHECK(curve.contact_radius.back() <= rho * (1 + 1e-9));
  std::size_t quarter = 0;
  while (curve.depth[quarter] < 0.25 * curve.depth.back()) ++quarter;
  CHECK(curve.contact_radius[quarter] < 0.8 * rho);
  CHECK(curve.message.find("wraps the probe") != std::string::npos);
}

TEST_CASE("shell_fe model: a tube near the Hencky wall's pressure maximum is no_inflation_state, not invalid_input") {
  // A draw of the shipped study (hoop strain 46 %). The far field inflates it, but the mesh (its
  // tip and end) tops out at the law's pressure maximum 0.35 % short of the measured diameter;
  // the secant iteration in the pressure creeps up to that maximum, and its trials past it have
  // no wall to solve. The model has no state there: not a fault of the input.
  const IndentationInput input = arabidopsis_like();
  Instrument instrument = input.instrument;
  instrument.probe_radius_m = 0.4585e-6;
  const ShellFeMeasurement tube{3.686, 164.73e-9, 6.2837e-6, 4.3174e-6};
  ShellFeOptions options = coarse();
  options.law = ShellFeLaw::hencky;  // the default, stated: the burst is the law's
  const ShellFeInverse inverse = invert_indentation(tube, instrument, options);
  CHECK(inverse.status == SampleStatus::no_inflation_state);
  CHECK(inverse.message.find("did not reach") != std::string::npos);
  CHECK(inverse.inflation_solves <= 6);
}
