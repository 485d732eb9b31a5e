// A probe half the tube's radius wide (rho = R/2, 1.8 bending lengths) on the Arabidopsis-like
// tube: the exact contact's curve reaches the force window's top, in a bounded number of Newton
// iterations per load step, and its k agrees with the penalty contact's, a second method
// (src/fe/README.md, section 8, "Wide probes").
#include <doctest/doctest.h>

#include <cstdio>

#include "mesh_convergence.hpp"

using namespace growthuq;

namespace {

struct WideCurve {
  fe::ForwardResult result;
  fe::WindowFit fit;
};

WideCurve indent_wide(ShellFeContact contact) {
  // p = 0.45 MPa, E = 45 MPa, h0 = 211 nm, d0 = 5.35 um, rho = 1.3375 um (R/2); the curve
  // passes the window's top (4 uN) at about 1.5 um.
  const double d0 = 5.35e-6;
  const auto point = testing::dimensionless_point(0.45e6, 45e6, 211e-9, d0, 0.25 * d0);
  fe::ForwardProblem problem = testing::study_tube(point, d0, 1.6e-6, ShellFeMesh::coarse);
  problem.contact = contact;
  WideCurve curve;
  curve.result = fe::simulate_forward(problem);
  curve.fit = fe::fit_force_window(curve.result.depth, curve.result.force, point.window_low, point.window_high);
  std::printf("wide probe, %s contact: status %d, k %.5f N/m (E d0 units %.6e), %d load steps, %d Newton iterations\n",
              contact == ShellFeContact::active_set ? "exact" : "penalty", static_cast<int>(curve.result.status),
              curve.fit.slope * 45e6 * d0, curve.fit.slope, curve.result.load_steps, curve.result.indentation_iterations);
  return curve;
}

}  // namespace

TEST_CASE("a probe half the tube's radius wide: the curve reaches the window, k as the penalty contact gives it") {
  const WideCurve exact = indent_wide(ShellFeContact::active_set);
  REQUIRE(exact.result.status == SampleStatus::ok);
  REQUIRE(exact.fit.status == fe::WindowFitStatus::ok);
  // Measured 163 iterations in 21 steps; with the narrow probes' band (forward.cpp) the steps
  // took 15-40 and the curve stopped at 1.2 uN.
  CHECK(exact.result.indentation_iterations <= 12 * exact.result.load_steps);
  const WideCurve penalty = indent_wide(ShellFeContact::penalty);
  REQUIRE(penalty.fit.status == fe::WindowFitStatus::ok);
  // The penalty's compliance in series (0.27 % of k at the thick wall) and its load-path noise
  // (0.2 %, src/fe/README.md) bound the difference by 0.5 % (measured: 2.7555 against 2.7554 N/m).
  CHECK(exact.fit.slope == doctest::Approx(penalty.fit.slope).epsilon(0.005));
}
