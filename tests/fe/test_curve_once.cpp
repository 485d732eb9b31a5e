// An automatic depth computes the force curve once (src/fe/README.md, section 6): the forward
// and the inverse indent until the window's top is on the curve, not to a depth fixed up front
// and again deeper when it falls short. Coarse mesh, Arabidopsis-like tube, whose closed-form
// estimate of the depth (1.59 um) falls short of the window's top (1.87 um).
#include <doctest/doctest.h>

#include <cstdio>

#include "arabidopsis_like_tube.hpp"
#include "growthuq/fe/indentation.hpp"

using namespace growthuq;
using growthuq::testing::arabidopsis_like;

TEST_CASE("an automatic depth: one curve, ending at the window's top, with the k of an explicit deeper curve") {
  ShellFeOptions options;
  options.mesh = ShellFeMesh::coarse;
  IndentationInput input = arabidopsis_like();
  const IndentationCurve automatic = indent(input, options);
  INFO(automatic.message);
  REQUIRE(automatic.status == SampleStatus::ok);
  // It stops at its first point past the window's top: the fit reads nothing beyond it.
  const double top = options.force_window[1];
  REQUIRE(automatic.force.size() >= 3);
  CHECK(automatic.force.back() >= top);
  CHECK(automatic.force[automatic.force.size() - 2] < top);

  // The reference: the curve to an explicit depth past the window's top, its steps sized from
  // that depth (at most 0.30 um, against the automatic curve's 0.20-0.23 um near the top). The
  // window fit reads a curve linear between its points, so k moves with the steps: explicit
  // depths from 1.9 to 2.6 um give k within 5e-4 of each other (2.16825-2.16936 N/m).
  input.depth = 2.408e-6;
  const IndentationCurve explicit_depth = indent(input, options);
  REQUIRE(explicit_depth.status == SampleStatus::ok);
  CHECK(explicit_depth.depth.back() == doctest::Approx(input.depth).epsilon(1e-12));
  CHECK(automatic.depth.back() < explicit_depth.depth.back());
  std::printf("k automatic %.6f N/m (%d steps to %.4f um), explicit depth %.6f N/m (%d steps): %.2e relative\n",
              automatic.stiffness, automatic.indentation_load_steps, automatic.depth.back() * 1e6,
              explicit_depth.stiffness, explicit_depth.indentation_load_steps,
              automatic.stiffness / explicit_depth.stiffness - 1);
  CHECK(automatic.stiffness == doctest::Approx(explicit_depth.stiffness).epsilon(1e-3));

  // The inverse of the automatic curve's k: the p and E it came from within the round trip's
  // bound of test_shell_fe_model.cpp (two curves, two sets of load steps).
  options.inflation_tolerance = 1e-8;
  const ShellFeMeasurement tube{automatic.measured_stiffness, input.thickness, automatic.turgid_diameter,
                                input.plasmolysed_diameter};
  const ShellFeInverse inverse = invert_indentation(tube, input.instrument, options);
  INFO(inverse.message);
  REQUIRE(inverse.status == SampleStatus::ok);
  CHECK(inverse.young == doctest::Approx(input.young).epsilon(2e-3));
  CHECK(inverse.pressure == doctest::Approx(input.pressure).epsilon(2e-3));
}
