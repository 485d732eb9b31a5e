// The viscous stabilisation's parts against independent references: the lumped masses against
// the areas they lump, the potential's gradient and Hessian against its finite differences, the
// first increment's damping factor and the adaptive cap against the rule's arithmetic done here.
#include <doctest/doctest.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "fe/mesh.hpp"
#include "fe/viscous_stabilisation.hpp"
#include "fe_test_geometry.hpp"

using namespace growthuq;

namespace {

// |x - y|_M^2 with the masses given, summed here rather than by the class.
double mass_norm(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& y, const Eigen::VectorXd& masses) {
  double sum = 0.0;
  for (Eigen::Index v = 0; v < x.cols(); ++v) sum += masses[v] * (x.col(v) - y.col(v)).squaredNorm();
  return sum;
}

struct Nodes {
  Eigen::VectorXd masses;
  Eigen::Matrix3Xd x0, x1, x2;
  std::vector<char> fixed;
};

// Five nodes, the last one's y fixed (a mirror node): it does not move.
Nodes five_nodes() {
  std::mt19937_64 rng(32);
  Nodes n;
  n.masses = (Eigen::VectorXd(5) << 0.3, 1.1, 0.7, 0.2, 0.9).finished();
  n.x0.resize(3, 5);
  n.x1.resize(3, 5);
  n.x2.resize(3, 5);
  for (int v = 0; v < 5; ++v) {
    n.x0.col(v) = fe::testing::random_vector(rng, 1.0);
    n.x1.col(v) = n.x0.col(v) + fe::testing::random_vector(rng, 0.01);
    n.x2.col(v) = n.x1.col(v) + fe::testing::random_vector(rng, 0.05);
  }
  n.x1(1, 4) = n.x2(1, 4) = n.x0(1, 4);
  n.fixed.assign(15, 0);
  n.fixed[13] = 1;
  return n;
}

}  // namespace

TEST_CASE("lumped masses: a third of each face's area times the thickness") {
  // The unit square in two triangles: the diagonal's ends carry two thirds of a half each.
  fe::TriangleMesh square;
  square.positions = (Eigen::Matrix3Xd(3, 4) << 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0).finished();
  square.faces = {{0, 1, 2}, {0, 2, 3}};
  const Eigen::VectorXd m = fe::lumped_masses(square, 0.1);
  CHECK(m[0] == doctest::Approx(2 * 0.5 / 3 * 0.1).epsilon(1e-15));
  CHECK(m[1] == doctest::Approx(0.5 / 3 * 0.1).epsilon(1e-15));
  CHECK(m[2] == doctest::Approx(2 * 0.5 / 3 * 0.1).epsilon(1e-15));
  CHECK(m[3] == doctest::Approx(0.5 / 3 * 0.1).epsilon(1e-15));

  // The half tube's wall: its volume h0 times the area of half a cylinder of diameter 1 and
  // length L - 1/2 with half a hemisphere, within the polyhedron's chord error (about 1e-3 on
  // the coarse mesh's circumference).
  const double length = 4.0, thickness = 0.03;
  const fe::TriangleMesh tube =
      fe::make_tube_mesh(length, 1.0, /*half_model=*/true, fe::mesh_sizing(ShellFeMesh::coarse, 0.1, thickness));
  const double area = 0.5 * (std::numbers::pi * (length - 0.5) + std::numbers::pi / 2);
  const double volume = fe::lumped_masses(tube, thickness).sum();
  CHECK(volume / (area * thickness) == doctest::Approx(1.0).epsilon(5e-3));
}

TEST_CASE("the viscous potential's gradient and Hessian are its derivatives") {
  Nodes n = five_nodes();
  fe::ViscousStabilisation s({.fraction = 1e-2}, n.masses, n.fixed);
  s.begin_step(n.x0, 0.01, 1.0, 1.0);
  REQUIRE(s.accept(n.x1, 1.2, 1.1));  // the first increment, undamped, sets c
  REQUIRE(s.damping_factor() > 0);
  const double dt = 0.02;
  s.begin_step(n.x1, dt, 1.2, 1.1);
  // (1) by hand.
  const double c = s.damping_factor();
  CHECK(s.energy(n.x2) == doctest::Approx(0.5 * c / dt * mass_norm(n.x2, n.x1, n.masses)).epsilon(1e-14));
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(15);
  s.add_gradient(n.x2, gradient);
  Eigen::SparseMatrix<double> hessian(15, 15);
  for (int d = 0; d < 15; ++d) hessian.insert(d, d) = d == 13 ? 1.0 : 0.0;  // the fixed dof's identity row
  hessian.makeCompressed();
  s.add_hessian(hessian);
  const double h = 1e-6;
  for (int d = 0; d < 15; ++d) {
    if (n.fixed[static_cast<std::size_t>(d)]) {
      CHECK(gradient[d] == 0.0);
      CHECK(hessian.coeff(d, d) == 1.0);
      continue;
    }
    Eigen::Matrix3Xd plus = n.x2, minus = n.x2;
    plus(d % 3, d / 3) += h;
    minus(d % 3, d / 3) -= h;
    // Central differences of a quadratic: exact but for rounding.
    CHECK(gradient[d] == doctest::Approx((s.energy(plus) - s.energy(minus)) / (2 * h)).epsilon(1e-6));
    Eigen::VectorXd g_plus = Eigen::VectorXd::Zero(15), g_minus = Eigen::VectorXd::Zero(15);
    s.add_gradient(plus, g_plus);
    s.add_gradient(minus, g_minus);
    CHECK(hessian.coeff(d, d) == doctest::Approx((g_plus[d] - g_minus[d]) / (2 * h)).epsilon(1e-6));
  }
}

TEST_CASE("the first increment sets c so that increments like it dissipate the fraction of the extrapolated strain energy") {
  const double fraction = 2e-4, dt1 = 0.01;
  const double strain0 = 140.0, strain1 = 140.3, stored0 = 100.0, stored1 = 100.05;
  for (const auto energy : {ShellFeStabilisationEnergy::model, ShellFeStabilisationEnergy::step}) {
    Nodes n = five_nodes();
    fe::ViscousStabilisation s({.fraction = fraction, .energy = energy}, n.masses, n.fixed);
    s.begin_step(n.x0, dt1, strain0, stored0);
    CHECK(s.energy(n.x1) == 0.0);  // the first increment is undamped
    REQUIRE(s.accept(n.x1, strain1, stored1));
    CHECK(s.dissipated() == 0.0);
    // Over the step (period 1), 1 / dt1 increments like the first, each dissipating
    // c |dx_1|_M^2 / dt1; the strain energy extrapolated linearly from the first increment.
    const double per_increment = s.damping_factor() * mass_norm(n.x1, n.x0, n.masses) / dt1;
    const double extrapolated = energy == ShellFeStabilisationEnergy::model ? strain0 + (strain1 - strain0) / dt1
                                                                            : (stored1 - stored0) / dt1;
    CHECK(per_increment / dt1 / extrapolated == doctest::Approx(fraction).epsilon(1e-12));
  }
}

TEST_CASE("the adaptive cap lowers c and solves the step again until the dissipated energy is within the ratio") {
  const double ratio = 0.05;
  for (const auto energy : {ShellFeStabilisationEnergy::model, ShellFeStabilisationEnergy::step}) {
    Nodes n = five_nodes();
    // A fraction this large dissipates far more than the cap allows in the second step.
    fe::ViscousStabilisation s({.fraction = 0.5, .ratio = ratio, .energy = energy}, n.masses, n.fixed);
    s.begin_step(n.x0, 0.01, 1.0, 1.0);
    REQUIRE(s.accept(n.x1, 1.01, 1.01));
    const double dt = 0.01, strain2 = 1.02, stored2 = 1.02;
    s.begin_step(n.x1, dt, 1.01, 1.01);
    const double c = s.damping_factor();
    const double moved = mass_norm(n.x2, n.x1, n.masses);
    const double cap = ratio * (energy == ShellFeStabilisationEnergy::model ? strain2 : stored2 - 1.0);
    REQUIRE(c / dt * moved > cap);  // the cap binds
    CHECK_FALSE(s.accept(n.x2, strain2, stored2));
    CHECK(s.lowerings() == 1);
    CHECK(s.damping_factor() < c);
    // Solved again (here: the same state), the step dissipates within the cap, and counts it.
    CHECK(s.accept(n.x2, strain2, stored2));
    CHECK(s.dissipated() == doctest::Approx(s.damping_factor() / dt * moved).epsilon(1e-14));
    CHECK(s.dissipated() <= cap);
    CHECK(s.dissipated() > 0.5 * cap);  // lowered to the cap, not to nothing
  }
}
