// Consistency of the indented tube: global force balance (probe force = substrate reaction +
// pinned-end reactions), the probe force from the contact forces against the derivative of the
// converged total energy with respect to the probe's position, and the half model (mirror plane
// y = 0) against the full model.
#include <doctest/doctest.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <vector>

#include "fe/assembly.hpp"
#include "fe/equilibrium.hpp"
#include "fe/forward.hpp"
#include "fe/mesh.hpp"
#include "fe/newton.hpp"
#include "fe/shell_objective.hpp"
#include "fe_validation_support.hpp"

using namespace growthuq;

namespace {

// A short tube (the balance does not depend on the length), wild-type-like wall: p/E = 0.009,
// h0/d0 = 0.03, nu = 0.2, Hencky; probe rho/d0 = 0.1 one diameter behind the apex.
constexpr double length = 4.0, probe_distance = 1.0, pressure = 0.009, thickness = 0.03, rho = 0.1;

struct IndentedTube {
  fe::ShellProblem problem;
  Eigen::Matrix3Xd x;
  Eigen::Vector3d probe_start;
  std::vector<int> ring;  // the pinned nodes (z = 0)
};

// Under either contact method (exact active set, penalty) the indented tube balances its forces
// and its probe force is the derivative of the converged energy with respect to the probe's
// position.
void check_balance(fe::ContactMethod method) {
  IndentedTube tube;
  fe::ShellProblem& problem = tube.problem;
  problem.mesh = fe::make_tube_mesh(length, probe_distance, /*half_model=*/true,
                                    fe::mesh_sizing(ShellFeMesh::coarse, rho, thickness));
  problem.material = fe::WallMaterial{ShellFeLaw::hencky, 1.0, 0.2, thickness};
  problem.mirror_y0 = true;
  problem.fixed = fe::mirror_and_end_ring_fixed(problem.mesh, true, true);
  for (Eigen::Index v = 0; v < problem.mesh.positions.cols(); ++v) {
    if (std::fabs(problem.mesh.positions(2, v)) <= 1e-12) tube.ring.push_back(static_cast<int>(v));
  }
  // A fixed penalty (not raised between the solves, so that the energy is one function).
  problem.loads.penalty = fe::PenaltyLaw{1e3 * thickness, 0.0};
  fe::ShellAssembly assembly(problem);
  fe::ShellObjective objective(assembly, {.method = method});
  fe::NewtonSolver solver(objective);
  tube.x = problem.mesh.positions;
  fe::LoadSteppingOptions inflation;
  const fe::EquilibriumResult inflated = fe::solve_equilibrium(
      objective, solver, tube.x, [](double t, fe::ShellLoads& loads) { loads.pressure = t * pressure; }, inflation);
  REQUIRE(inflated.status == SampleStatus::ok);

  // Probe over the node nearest the probe axis, substrate touching the lowest node.
  const double probe_z = tube.x.row(2).maxCoeff() - probe_distance;
  double touch = -1e300;
  for (Eigen::Index v = 0; v < tube.x.cols(); ++v) {
    const double lateral2 = std::pow(tube.x(1, v), 2) + std::pow(tube.x(2, v) - probe_z, 2);
    if (lateral2 < rho * rho) touch = std::max(touch, tube.x(0, v) + std::sqrt(rho * rho - lateral2));
  }
  REQUIRE(touch > 0);
  tube.probe_start = Eigen::Vector3d(touch, 0, probe_z);
  assembly.loads().obstacles.spheres = {fe::RigidSphere{tube.probe_start, rho}};
  assembly.loads().obstacles.planes = {fe::RigidPlane{Eigen::Vector3d(tube.x.row(0).minCoeff(), 0, 0), Eigen::Vector3d::UnitX()}};
  const double depth = 0.05;
  fe::LoadSteppingOptions indentation;
  indentation.first_step = 0.25;
  indentation.max_step = 0.25;
  indentation.newton.max_step = 0.25 * rho;
  indentation.newton.first_step_whole = method == fe::ContactMethod::active_set;
  const Eigen::Vector3d start = tube.probe_start;
  const fe::EquilibriumResult indented = fe::solve_equilibrium(
      objective, solver, tube.x,
      [&](double t, fe::ShellLoads& loads) { loads.obstacles.spheres.front().centre = start - Eigen::Vector3d(t * depth, 0, 0); },
      indentation);
  INFO(indented.message);
  REQUIRE(indented.status == SampleStatus::ok);

  const fe::ContactState contact = objective.contact_state(tube.x);
  const double probe_force = contact.sphere_force.at(0).x();       // wall on probe, +x
  const double substrate_force = contact.plane_force.at(0).x();    // wall on substrate, -x
  REQUIRE(probe_force > 0);

  {  // probe force = substrate reaction + pinned-end reactions
    // Reactions of the pinned ring: the gradient of the wall's own energy (membrane, bending,
    // -pV) at those nodes, from the same problem without supports or obstacles. In x the
    // pressure and the mirror plane add no net force (the closing faces of -pV, the end disk and
    // the mirror plane, have no x normal), so the x reactions alone close the balance.
    fe::ShellProblem unsupported = problem;
    unsupported.fixed.clear();
    unsupported.loads = fe::ShellLoads{};
    unsupported.loads.pressure = pressure;
    const fe::ShellAssembly wall(unsupported);
    Eigen::VectorXd gradient(wall.dofs());
    wall.evaluate(tube.x, gradient, nullptr);
    double ring_x = 0.0;
    for (int v : tube.ring) ring_x += gradient(3 * v);
    std::printf("balance: probe %.9e substrate %.9e ring %.9e (probe + substrate - ring) / probe = %.2e\n",
                probe_force, substrate_force, ring_x, (probe_force + substrate_force - ring_x) / probe_force);
    // Newton stops at max |gradient| <= 1e-9 E h0 (shortest edge) per dof; summed over the few
    // hundred free nodes that is below 1e-6 of the probe force here.
    CHECK(std::fabs(probe_force + substrate_force - ring_x) < 1e-6 * probe_force);
    // The substrate carries most of the probe force on a short tube, the ring the rest.
    CHECK(-substrate_force > 0.5 * probe_force);
  }

  {  // probe force = d(total energy) / d(depth), by central differences
    // E*(depth) is the converged total energy with the probe at start - depth e_x; as the wall is
    // at a minimum, dE*/d(depth) is the explicit derivative of the contact energy, i.e. the
    // force of the wall on the probe (envelope theorem). Step 1e-4 of the depth: the central
    // difference's error ~ F'' h^2 / 6 is ~1e-8 relative; Newton's energy error is quadratic in
    // its gradient tolerance, far below.
    const double h = 1e-4 * depth;
    fe::NewtonOptions options;
    options.max_step = 0.25 * rho;
    options.first_step_whole = method == fe::ContactMethod::active_set;  // the probe moved: lift the nodes out
    auto energy_at = [&](double d) {
      assembly.loads().obstacles.spheres.front().centre = start - Eigen::Vector3d(d, 0, 0);
      Eigen::Matrix3Xd y = tube.x;
      const fe::NewtonReport report = solver.minimise(y, options);
      REQUIRE(report.status == fe::NewtonStatus::converged);
      return report.energy;
    };
    const double derivative = (energy_at(depth + h) - energy_at(depth - h)) / (2 * h);
    std::printf("energy derivative: contact force %.9e dE/d(depth) %.9e relative gap %.2e\n", probe_force, derivative,
                derivative / probe_force - 1.0);
    CHECK(std::fabs(derivative / probe_force - 1.0) < 1e-5);
  }
  if (method == fe::ContactMethod::active_set) {
    // Exact contact: no node in the probe or the substrate beyond rounding, and the contact
    // forces are the multipliers of nodes on the surfaces only (complementarity).
    CHECK(contact.max_penetration <= 1e-13);
    CHECK(contact.sphere_contacts.at(0) >= 1);
  }
}

}  // namespace

TEST_CASE("the indented tube balances its forces and its probe force is the energy's derivative: exact contact") {
  check_balance(fe::ContactMethod::active_set);
}

TEST_CASE("the indented tube balances its forces and its probe force is the energy's derivative: penalty") {
  check_balance(fe::ContactMethod::penalty);
}

TEST_CASE("the half model and the full model give the same stiffness within 0.5 %") {
  // Wild type (PHYSICS section 7 medians): h = 145 nm turgid, d0 = 5.35 um, p = 0.25 MPa,
  // E = 28 MPa, probe 0.5 um, the instrument's window 0.4-4 uN; h0 = 155 nm (the Hencky
  // thickness stretch ~0.93 at this inflation).
  const auto point = testing::dimensionless_point(0.25e6, 28e6, 155e-9, 5.35e-6, 0.5e-6);
  fe::ForwardProblem problem;
  problem.pressure = point.pressure;
  problem.thickness = point.thickness;
  problem.probe_radius = point.probe_radius;
  problem.tube_length = 100.0 / 5.35;
  problem.probe_distance = 10.0 / 5.35;
  problem.max_depth = 0.35;
  problem.mesh = ShellFeMesh::coarse;
  problem.half_model = true;
  const fe::ForwardResult half = fe::simulate_forward(problem);
  problem.half_model = false;
  const fe::ForwardResult full = fe::simulate_forward(problem);
  std::printf("half/full: status %d (%s) / %d (%s)\n", static_cast<int>(half.status), half.message.c_str(),
              static_cast<int>(full.status), full.message.c_str());
  REQUIRE(half.status == SampleStatus::ok);
  REQUIRE(full.status == SampleStatus::ok);
  const double k_half = testing::window_slope(half.depth, half.force, point.window_low, point.window_high);
  const double k_full = testing::window_slope(full.depth, full.force, point.window_low, point.window_high);
  std::printf("half/full: k_half %.6e k_full %.6e (E d0) relative %.2e; Newton %d / %d\n", k_half, k_full,
              k_half / k_full - 1.0, half.newton_iterations, full.newton_iterations);
  CHECK(std::fabs(k_half / k_full - 1.0) < 0.005);
}
