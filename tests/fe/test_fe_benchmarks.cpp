// A published nonlinear shell benchmark: the clamped semi-cylinder under a point load at its
// free end (Sze, Liu and Lo 2004, section 3.7), large deflection and large rotation with small
// strain: the deflection within 2 % of the reference at every tabulated load.
//
// The model is the engine's shell as it is (membrane triangles, the face-and-neighbours
// bending element, St-VK wall: at strains below 1 % the law does not matter). The straight
// edges lie in the mirror plane y = 0, which is exactly the reference's boundary condition
// there (transverse displacement and the rotation about the axis blocked); the clamp fixes two
// rings (see semicylinder_benchmark.hpp). The load is dead and applied in force steps, each
// started from the previous solution, cut in half when Newton does not converge.
//
// The mesh: 48 x 48 cells, graded in the hoop direction towards the straight edges and the
// crown and in the axial direction towards both ends (hoop_grading and axial_grading 0.6,
// semicylinder_benchmark.hpp says why). Measured deflection at P/Pmax = 0.05 and
// 1 against the reference 0.05421 and 1.71505:
//   48 x 48 uniform                 -        2.219 (+29 %: a jump to a deeper branch at 0.85-0.9)
//   hoop graded only:  24 x 24      0.0644   1.918 (+11.8 %)
//                      48 x 24      0.0656   1.760 (+2.6 %)
//                      48 x 48      0.0576   1.743 (+1.6 %)
//                      72 x 36      0.0603   1.733 (+1.1 %)
//                      96 x 48      0.0579   1.724 (+0.5 %)
//   both graded:       48 x 48      0.0540   1.743 (+1.6 %)
// so the path converges onto the reference from above at large loads, and the small loads need
// the axial cells near the loaded end (the hoop refinement alone leaves 0.05 at +6.7 %). On the
// mesh used every tabulated point is within 2 % in deflection at its load; the largest
// deviation is +1.84 % at P/Pmax = 0.65.
#include <doctest/doctest.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fe/assembly.hpp"
#include "fe/equilibrium.hpp"
#include "fe/newton.hpp"
#include "fe/shell_objective.hpp"
#include "semicylinder_benchmark.hpp"

using namespace growthuq;
using growthuq::testing::SemicylinderData;
using growthuq::testing::semicylinder_reference;

namespace {

struct LoadPath {
  std::vector<double> load_fraction, deflection;
  bool completed = false;
  int newton_iterations = 0;
  std::string message;
};

LoadPath run_semicylinder(int hoop_segments, int axial_segments) {
  const testing::SemicylinderMesh built =
      testing::make_semicylinder_mesh(hoop_segments, axial_segments, /*alternating=*/false, /*hoop_grading=*/0.6, /*axial_grading=*/0.6);
  fe::ShellProblem problem;
  problem.mesh = built.mesh;
  problem.material.law = ShellFeLaw::saint_venant_kirchhoff;
  problem.material.young = 1.0;  // forces below are P / E
  problem.material.poisson = SemicylinderData::poisson;
  problem.material.thickness = SemicylinderData::thickness;
  problem.bending = true;
  problem.mirror_y0 = true;
  problem.fixed = fe::mirror_and_end_ring_fixed(problem.mesh, /*mirror_y0=*/true, /*pin_z0=*/false);
  for (int v : built.clamped) {
    for (int k = 0; k < 3; ++k) problem.fixed[static_cast<std::size_t>(3 * v + k)] = 1;
  }
  problem.loads.point_loads = {fe::PointLoad{built.crown, Eigen::Vector3d::Zero()}};
  fe::ShellAssembly assembly(problem);
  fe::ShellObjective objective(assembly);
  fe::NewtonSolver solver(objective);
  fe::LoadSteppingOptions options;
  options.first_step = 0.025;
  options.max_step = 0.025;
  options.newton.max_iterations = 50;

  LoadPath path;
  Eigen::Matrix3Xd x = problem.mesh.positions;
  const double crown_y = x(1, built.crown);
  const auto set_loads = [](double t, fe::ShellLoads& loads) {
    loads.point_loads[0].force = Eigen::Vector3d(0, -t * SemicylinderData::max_load / SemicylinderData::young, 0);
  };
  const auto record = [&](double t, const Eigen::Matrix3Xd& state) {
    path.load_fraction.push_back(t);
    path.deflection.push_back(crown_y - state(1, built.crown));
    return true;
  };
  const fe::EquilibriumResult result = fe::solve_equilibrium(objective, solver, x, set_loads, options, record);
  path.newton_iterations = result.newton_iterations;
  path.completed = result.status == SampleStatus::ok && result.reached >= 1.0 - 1e-12;
  path.message = result.message;
  return path;
}

// Linear interpolation of a path y(x) given as samples with x increasing; NaN outside it.
double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  double x0 = 0.0, y0 = 0.0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double x1 = xs[i], y1 = ys[i];
    if (x1 >= x - 1e-12) return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
    x0 = x1, y0 = y1;
  }
  return NAN;
}

}  // namespace

TEST_CASE("the clamped semi-cylinder under a point load matches Sze et al. 2004 within 2 %") {
  const LoadPath path = run_semicylinder(48, 48);
  std::printf("semicylinder: %zu steps, %d Newton iterations, %s\n", path.load_fraction.size(), path.newton_iterations,
              path.message.c_str());
  REQUIRE(path.completed);
  for (const auto& reference : semicylinder_reference()) {
    const double w = interpolate(path.load_fraction, path.deflection, reference.load_fraction);
    std::printf("semicylinder P/Pmax %.3f w %.5f reference %.5f (%+.2f %%)\n", reference.load_fraction, w,
                reference.deflection, 100.0 * (w / reference.deflection - 1.0));
    CAPTURE(reference.load_fraction);
    CHECK(std::fabs(w / reference.deflection - 1.0) < 0.02);
  }
  const double final_deflection = path.deflection.back();
  const double reference = semicylinder_reference().back().deflection;
  CAPTURE(final_deflection);
  CHECK(std::fabs(final_deflection / reference - 1.0) < 0.02);
}
