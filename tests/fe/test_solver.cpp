// The assembled energy's gradient and Hessian against central differences; Newton's quadratic
// convergence; the inflated capped tube against the analytic far field of each law; the
// forward protocol's contact bound and statuses.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "fe/assembly.hpp"
#include "fe/equilibrium.hpp"
#include "fe/far_field.hpp"
#include "fe/forward.hpp"
#include "fe/newton.hpp"
#include "fe/shell_objective.hpp"

using namespace growthuq::fe;
using growthuq::SampleStatus;
using growthuq::ShellFeLaw;
using growthuq::ShellFeMesh;

namespace {

double hessian_entry(const Eigen::SparseMatrix<double>& lower, Eigen::Index i, Eigen::Index j) {
  return i >= j ? lower.coeff(i, j) : lower.coeff(j, i);
}

// A half sphere under pressure, a probe, a plane and a point load, at a perturbed state.
ShellProblem small_problem(ShellFeLaw law) {
  ShellProblem problem;
  MeshSizing uniform{0.25, 0.0, 1.0, 0.25};
  problem.mesh = make_sphere_mesh(true, uniform);
  problem.material = WallMaterial{law, 1.0, 0.3, 0.02};
  problem.mirror_y0 = true;
  problem.fixed = mirror_and_end_ring_fixed(problem.mesh, true, false);
  problem.loads.pressure = 0.01;
  problem.loads.obstacles.spheres = {RigidSphere{Eigen::Vector3d(0.62, 0.0, 0.0), 0.15}};
  problem.loads.obstacles.planes = {RigidPlane{Eigen::Vector3d(-0.49, 0, 0), Eigen::Vector3d::UnitX()}};
  problem.loads.penalty = PenaltyLaw{50.0, 0.01};
  problem.loads.point_loads = {PointLoad{3, Eigen::Vector3d(0.001, 0.0, -0.002)}};
  return problem;
}

}  // namespace

TEST_CASE("assembled gradient and Hessian agree with central differences of the total energy") {
  for (ShellFeLaw law : {ShellFeLaw::hencky, ShellFeLaw::saint_venant_kirchhoff}) {
    const ShellAssembly assembly(small_problem(law));
    std::mt19937 rng(3);
    std::normal_distribution<double> n(0.0, 1.0);
    Eigen::Matrix3Xd x = 1.05 * assembly.problem().mesh.positions;
    for (Eigen::Index v = 0; v < x.cols(); ++v) {
      for (int k = 0; k < 3; ++k) {
        if (!assembly.is_fixed(3 * v + k)) x(k, v) += 0.005 * n(rng);
      }
    }
    Eigen::VectorXd g, gp, gm;
    Eigen::SparseMatrix<double> h;
    const EnergyParts parts = assembly.evaluate(x, g, &h);
    REQUIRE(parts.contact > 0.0);  // the probe and the plane both press on some nodes
    const double step = 1e-6;
    double g_scale = g.lpNorm<Eigen::Infinity>(), h_scale = 0.0;
    for (Eigen::Index c = 0; c < h.outerSize(); ++c) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(h, c); it; ++it) h_scale = std::max(h_scale, std::fabs(it.value()));
    }
    int checked = 0;
    for (Eigen::Index d = 0; d < assembly.dofs(); d += 2) {
      if (assembly.is_fixed(d)) continue;
      Eigen::Matrix3Xd xp = x, xm = x;
      xp(d % 3, d / 3) += step;
      xm(d % 3, d / 3) -= step;
      const double fd = (assembly.energy(xp).total() - assembly.energy(xm).total()) / (2 * step);
      // Central differences: truncation ~ step^2 * E''' and round-off ~ 1e-16 |E| / step.
      CHECK(std::fabs(fd - g[d]) <= 1e-6 * g_scale);
      assembly.evaluate(xp, gp, nullptr);
      assembly.evaluate(xm, gm, nullptr);
      for (Eigen::Index i = 0; i < assembly.dofs(); ++i) {
        if (assembly.is_fixed(i)) continue;
        CHECK(std::fabs((gp[i] - gm[i]) / (2 * step) - hessian_entry(h, i, d)) <= 1e-5 * h_scale);
      }
      ++checked;
    }
    CHECK(checked > 40);
    // Fixed dofs: no gradient, identity rows.
    for (Eigen::Index d = 0; d < assembly.dofs(); ++d) {
      if (!assembly.is_fixed(d)) continue;
      CHECK(g[d] == 0.0);
      CHECK(hessian_entry(h, d, d) == 1.0);
    }
  }
}

TEST_CASE("Newton converges quadratically on the inflation of a capped tube") {
  ShellProblem problem;
  problem.mesh = make_tube_mesh(4.0, 1.0, true, mesh_sizing(ShellFeMesh::coarse, 0.1, 0.02));
  problem.material = WallMaterial{ShellFeLaw::hencky, 1.0, 0.2, 0.02};
  problem.mirror_y0 = true;
  problem.fixed = mirror_and_end_ring_fixed(problem.mesh, true, true);
  ShellAssembly assembly(problem);
  ShellObjective objective(assembly);
  NewtonSolver solver(objective);
  Eigen::Matrix3Xd x = problem.mesh.positions;
  // First to p/E = 0.002, then one Newton solve of a 20 % pressure increment: smooth, convex
  // near the solution, so the gradient's norm should square from one iteration to the next.
  assembly.loads().pressure = 0.002;
  NewtonOptions options;
  options.gradient_tolerance = 1e-10;
  REQUIRE(solver.minimise(x, options).status == NewtonStatus::converged);
  assembly.loads().pressure = 0.0024;
  const NewtonReport report = solver.minimise(x, options);
  REQUIRE(report.status == NewtonStatus::converged);
  const auto& g = report.gradient_history;
  REQUIRE(g.size() >= 3);
  // Quadratic convergence: g[k+1] <= C g[k]^2 with one constant C once g is small (the
  // measured ratios g[k+1]/g[k]^2 are 0.2 and 1.0 in units of the nodal force scale; linear
  // convergence at any fixed rate would make them grow without bound as g falls).
  int measured = 0;
  for (std::size_t k = 0; k + 1 < g.size(); ++k) {
    if (g[k] > 1e-1 || g[k + 1] < 1e-11) continue;
    MESSAGE("gradient " << g[k] << " -> " << g[k + 1] << ": g[k+1]/g[k]^2 = " << g[k + 1] / (g[k] * g[k]));
    CHECK(g[k + 1] / (g[k] * g[k]) < 3.0);
    ++measured;
  }
  CHECK(measured >= 1);
  CHECK(report.iterations <= 6);
}

TEST_CASE("inflated capped tube: turgid diameter, axial and thickness stretch of the far field within 0.2 %") {
  for (ShellFeLaw law : {ShellFeLaw::hencky, ShellFeLaw::saint_venant_kirchhoff}) {
    ForwardProblem p;
    p.pressure = 0.005;  // about 17 % hoop strain (Hencky) at h0/d0 = 0.02
    p.thickness = 0.02;
    p.poisson = 0.2;
    p.law = law;
    p.probe_radius = 0.05;
    p.tube_length = 10.0;
    p.probe_distance = 1.0;
    p.mesh = ShellFeMesh::standard;
    const ForwardResult r = simulate_inflation(p);
    REQUIRE(r.status == SampleStatus::ok);
    const FarFieldInflation far = far_field_inflation(far_field_law(law), p.pressure, p.thickness, p.poisson);
    MESSAGE("law " << static_cast<int>(law) << ": d " << r.turgid_diameter << " (far field " << far.hoop_stretch
                   << "), axial " << r.axial_stretch << " (" << far.axial_stretch << "), thickness "
                   << r.thickness_stretch << " (" << far.thickness_stretch << ")");
    CHECK(r.turgid_diameter == doctest::Approx(far.hoop_stretch).epsilon(2e-3));
    CHECK(r.axial_stretch == doctest::Approx(far.axial_stretch).epsilon(2e-3));
    CHECK(r.thickness_stretch == doctest::Approx(far.thickness_stretch).epsilon(2e-3));
  }
}

TEST_CASE("forward protocol: rising force, penetration within 1e-3 rho, statuses for bad input and burst") {
  ForwardProblem p;
  p.pressure = 0.005;
  p.thickness = 0.02;
  p.probe_radius = 0.1;
  p.tube_length = 6.0;
  p.probe_distance = 1.0;
  p.max_depth = 0.03;
  p.mesh = ShellFeMesh::coarse;
  const ForwardResult r = simulate_forward(p);
  REQUIRE(r.status == SampleStatus::ok);
  REQUIRE(r.depth.size() >= 3);
  CHECK(r.depth.back() == doctest::Approx(p.max_depth));
  for (std::size_t k = 1; k < r.force.size(); ++k) CHECK(r.force[k] > r.force[k - 1]);
  CHECK(r.max_penetration <= 1e-3 * p.probe_radius);
  CHECK(r.max_penetration > 0.0);
  CHECK(r.deformed.cols() == r.mesh.positions.cols());
  CHECK(r.face_stress.size() == r.mesh.faces.size());

  ForwardProblem bad = p;
  bad.thickness = -1;
  CHECK(simulate_forward(bad).status == SampleStatus::invalid_input);
  bad = p;
  bad.probe_distance = 20;
  CHECK(simulate_forward(bad).status == SampleStatus::probe_beyond_mesh);
  ForwardProblem burst = p;
  burst.pressure = 0.01;  // beyond the Hencky tube's pressure maximum at h0/d0 = 0.02 (G_max ~ 0.35)
  const ForwardResult b = simulate_inflation(burst);
  CHECK(b.status == SampleStatus::burst);
  CHECK(!b.message.empty());
}

// The line search's projection (newton.hpp, penetration_floor): nodes deeper than the cap in the
// probe or the substrate come back to exactly the cap, along the sphere's radius or the plane's
// normal; nodes within it, and fixed dofs, stay where they are.
TEST_CASE("limit_penetration puts nodes deeper than the cap back at the cap, fixed dofs untouched") {
  ShellProblem problem;
  problem.mesh.positions.resize(3, 4);  // a unit square: the reference only has to be valid
  problem.mesh.positions << 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0;
  problem.mesh.faces = {{0, 1, 2}, {0, 2, 3}};
  problem.bending = false;
  problem.fixed.assign(12, 0);
  problem.fixed[3 * 2 + 1] = 1;  // node 2 held in y
  problem.loads.obstacles.spheres = {RigidSphere{Eigen::Vector3d(0, 0, 1), 0.5}};
  problem.loads.obstacles.planes = {RigidPlane{Eigen::Vector3d(0, 0, -1), Eigen::Vector3d::UnitZ()}};
  const ShellAssembly assembly(problem);
  Eigen::Matrix3Xd x(3, 4);
  x.col(0) = Eigen::Vector3d(0.0, 0.0, 0.7);     // 0.3 inside the sphere
  x.col(1) = Eigen::Vector3d(0.1, 0.0, 0.5005);  // inside the sphere by less than the cap
  x.col(2) = Eigen::Vector3d(0.3, 0.2, 0.9);     // inside the sphere, y held
  x.col(3) = Eigen::Vector3d(2.0, 0.0, -1.4);    // 0.4 below the plane
  const Eigen::Matrix3Xd before = x;
  const double cap = 0.01;
  CHECK(assembly.limit_penetration(x, cap) == 3);
  CHECK((x.col(0) - Eigen::Vector3d(0, 0, 1)).norm() == doctest::Approx(0.5 - cap).epsilon(1e-14));
  CHECK(x(0, 0) == 0.0);
  CHECK(x.col(1) == before.col(1));
  CHECK(x(1, 2) == before(1, 2));  // the fixed dof
  CHECK(x(0, 2) != before(0, 2));
  CHECK(x(2, 3) == doctest::Approx(-1.0 - cap).epsilon(1e-14));
  CHECK(x(0, 3) == before(0, 3));
}
