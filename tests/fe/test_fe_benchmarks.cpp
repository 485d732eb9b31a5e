// A published nonlinear shell benchmark: the clamped semi-cylinder under a point load at its
// free end (Sze, Liu and Lo 2004, section 3.7), large deflection and large rotation with small
// strain, within 2 % of the reference deflection at the final load.
//
// The model is the engine's shell as it is (membrane triangles, the face-and-neighbours
// bending element, St-VK wall: at strains below 1 % the law does not matter). The straight
// edges lie in the mirror plane y = 0, which is exactly the reference's boundary condition
// there (transverse displacement and the rotation about the axis blocked); the clamp fixes two
// rings (see semicylinder_benchmark.hpp). The load is dead and applied in force steps, each
// started from the previous solution, cut in half when Newton does not converge.
//
// Measured (2026-12-02, 48 x 48 cells, diagonals mirrored about the crown): within +3.2 % of the
// reference up to P/Pmax = 0.85 (+2.4 % at 0.25), then the path jumps (between 0.85 and 0.90)
// to a deeper branch, final deflection 2.219 against 1.715 (+29 %): the 2 % target is NOT met.
// On 24 x 24: +6 % at 0.25, a jump between 0.85 and 0.90, final +17 %. Without the free edge's
// condensation (bending.hpp) the 24 x 24 path moves by under 1 %. The tolerance stays at 2 %.
#include <doctest/doctest.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fe/assembly.hpp"
#include "fe/equilibrium.hpp"
#include "fe/newton.hpp"
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
  const testing::SemicylinderMesh built = testing::make_semicylinder_mesh(hoop_segments, axial_segments);
  fe::ShellProblem problem;
  problem.mesh = built.mesh;
  problem.material.law = fe::MaterialLaw::saint_venant_kirchhoff;
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
  fe::NewtonSolver solver(assembly);
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
  const fe::EquilibriumResult result = fe::solve_equilibrium(assembly, solver, x, set_loads, options, record);
  path.newton_iterations = result.newton_iterations;
  path.completed = result.status == fe::FeStatus::ok && result.reached >= 1.0 - 1e-12;
  path.message = result.message;
  return path;
}

// Linear interpolation of the path's deflection at a load fraction.
double deflection_at(const LoadPath& path, double fraction) {
  double f0 = 0.0, w0 = 0.0;
  for (std::size_t i = 0; i < path.load_fraction.size(); ++i) {
    const double f1 = path.load_fraction[i], w1 = path.deflection[i];
    if (f1 >= fraction - 1e-12) return w0 + (w1 - w0) * (fraction - f0) / (f1 - f0);
    f0 = f1, w0 = w1;
  }
  return NAN;
}

}  // namespace

TEST_CASE("the clamped semi-cylinder under a point load matches Sze et al. 2004 within 2 % at the final load") {
  const LoadPath path = run_semicylinder(48, 48);
  std::printf("semicylinder: %zu steps, %d Newton iterations, %s\n", path.load_fraction.size(), path.newton_iterations,
              path.message.c_str());
  REQUIRE(path.completed);
  for (const auto& reference : semicylinder_reference()) {
    const double w = deflection_at(path, reference.load_fraction);
    std::printf("semicylinder P/Pmax %.3f w %.5f reference %.5f (%+.2f %%)\n", reference.load_fraction, w,
                reference.deflection, 100.0 * (w / reference.deflection - 1.0));
  }
  const double final_deflection = path.deflection.back();
  const double reference = semicylinder_reference().back().deflection;
  CAPTURE(final_deflection);
  CHECK(std::fabs(final_deflection / reference - 1.0) < 0.02);
}
