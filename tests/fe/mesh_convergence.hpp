// Mesh convergence of the apparent stiffness k at one point of the physiological envelope, for
// the tests test_fe_convergence*.cpp: k as indent() reads it (the instrument's linear fit over
// 0.4-4 uN, fe::fit_force_window) at three mesh levels, each sqrt(2) finer than the one before,
// their Richardson order and limit, and the default level within 1 % of the limit.
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

#include "fe/force_window.hpp"
#include "fe/forward.hpp"
#include "fe_validation_support.hpp"

namespace growthuq::testing {

struct EnvelopePoint {
  const char* name;
  double p, young, h0, d0, rho, depth;  // SI; depth: the deepest indentation, past the window's top
};

// The study's tube (100 um long, probed 10 um behind the apex) at a point, indented to `depth` (m).
inline fe::ForwardProblem study_tube(const DimensionlessPoint& point, double d0, double depth, ShellFeMesh level) {
  fe::ForwardProblem problem;
  problem.pressure = point.pressure;
  problem.thickness = point.thickness;
  problem.probe_radius = point.probe_radius;
  problem.tube_length = 100e-6 / d0;
  problem.probe_distance = 10e-6 / d0;
  problem.max_depth = depth / d0;
  problem.mesh = level;
  return problem;
}

inline double stiffness(const DimensionlessPoint& point, double d0, double depth, ShellFeMesh level, int& iterations) {
  const fe::ForwardResult result = fe::simulate_forward(study_tube(point, d0, depth, level));
  iterations = result.newton_iterations;
  // As indent() reads a curve: k counts if the curve got past the window's top, even when the
  // solver stopped later (measured once: the fine level stopped at 2.22 of 2.3 um, beyond the
  // top at about 2.1 um).
  const fe::WindowFit fit = fe::fit_force_window(result.depth, result.force, point.window_low, point.window_high);
  if (result.status != SampleStatus::ok) {
    std::printf("convergence: status %d: %s\n", static_cast<int>(result.status), result.message.c_str());
  }
  if (fit.status != fe::WindowFitStatus::ok) {
    std::printf("convergence: the curve did not reach the window's top\n");
    return NAN;
  }
  return fit.slope;
}

// Three levels of a point, their Richardson order and limit, the default level (one of the
// three) within 1 % of it.
inline void check_convergence(const EnvelopePoint& e, ShellFeMesh coarse_level, ShellFeMesh middle_level,
                              ShellFeMesh fine_level) {
  CAPTURE(e.name);
  const auto point = dimensionless_point(e.p, e.young, e.h0, e.d0, e.rho);
  int i1 = 0, i2 = 0, i3 = 0;
  const double coarse = stiffness(point, e.d0, e.depth, coarse_level, i1);
  const double middle = stiffness(point, e.d0, e.depth, middle_level, i2);
  const double fine = stiffness(point, e.d0, e.depth, fine_level, i3);
  const Richardson r = richardson(coarse, middle, fine, std::sqrt(2.0));
  const double standard = coarse_level == ShellFeMesh::standard   ? coarse
                          : middle_level == ShellFeMesh::standard ? middle
                                                                    : fine;
  const double force_scale = e.young * e.d0;  // k in N/m from k / (E d0)
  std::printf("convergence %s: k %.4f %.4f %.4f N/m; order %.2f limit %.4f N/m; default %+.3f %% "
              "finest %+.3f %% of the limit; Newton %d %d %d\n",
              e.name, coarse * force_scale, middle * force_scale, fine * force_scale, r.order, r.limit * force_scale,
              100 * (standard / r.limit - 1), 100 * (fine / r.limit - 1), i1, i2, i3);
  REQUIRE(std::isfinite(r.order));
  CHECK(r.order > 0.5);
  CHECK(std::fabs(standard / r.limit - 1.0) < 0.01);
}

}  // namespace growthuq::testing
