// The exact contact method and Newton's physics-free interface on problems without a shell,
// whose answers are known: points drawn by springs into a sphere and a plane come to rest at
// their closest admissible points (an exact projection), with the springs' force as the
// multiplier; a chain of coupled points satisfies the contact conditions (Karush-Kuhn-Tucker:
// stationarity, non-penetration, non-negative multipliers, complementarity) to rounding.
#include <doctest/doctest.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cmath>
#include <vector>

#include "fe/active_set_contact.hpp"
#include "fe/newton.hpp"

using namespace growthuq::fe;

namespace {

// Energy sum_v (k/2) |x_v - a_v|^2 + sum_v (s/2) |(x_{v+1} - x_v) - (a_{v+1} - a_v)|^2: each
// point on a spring to its target a_v, neighbours coupled by springs of stiffness s (0: none).
class SpringProblem final : public NewtonProblem {
 public:
  SpringProblem(Eigen::Matrix3Xd targets, double k, double s, std::vector<char> fixed, Obstacles obstacles)
      : targets_(std::move(targets)), k_(k), s_(s), obstacles_(std::move(obstacles)),
        contact_(fixed, 1e-12, 1.0) {
    const Eigen::Index n = 3 * targets_.cols();
    std::vector<Eigen::Triplet<double>> entries;
    for (Eigen::Index v = 0; v < targets_.cols(); ++v) {
      for (int j = 0; j < 3; ++j) {
        for (int i = j; i < 3; ++i) entries.emplace_back(3 * v + i, 3 * v + j, 0.0);
        if (s_ > 0 && v + 1 < targets_.cols()) {
          for (int i = 0; i < 3; ++i) entries.emplace_back(3 * (v + 1) + i, 3 * v + j, 0.0);
        }
      }
    }
    pattern_.resize(n, n);
    pattern_.setFromTriplets(entries.begin(), entries.end());
    fixed_ = std::move(fixed);
  }

  Eigen::Index nodes() const override { return targets_.cols(); }
  const Eigen::SparseMatrix<double>& pattern() const override { return pattern_; }

  EnergyValue linearise(const Eigen::Matrix3Xd& x, Eigen::VectorXd& gradient, Eigen::SparseMatrix<double>& hessian,
                        double& stationarity) override {
    gradient_ = wall_gradient(x);
    gradient = gradient_;
    hessian = pattern_;
    for (Eigen::Index c = 0; c < hessian.outerSize(); ++c) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(hessian, c); it; ++it) {
        const Eigen::Index r = it.row();
        double value = 0.0;
        const Eigen::Index a = r / 3, b = c / 3;
        if (r % 3 == c % 3) {
          if (a == b) value = k_ + s_ * ((a > 0 ? 1 : 0) + (a + 1 < nodes() ? 1 : 0));
          else value = -s_;
        }
        if (is_fixed(r) || is_fixed(c)) value = r == c ? 1.0 : 0.0;
        it.valueRef() = value;
      }
    }
    stationarity = contact_.select(obstacles_, x, gradient, &hessian);
    contact_.reduce(hessian, gradient);
    return energy(x);
  }
  EnergyValue energy(const Eigen::Matrix3Xd& x) const override {
    double e = 0.0;
    for (Eigen::Index v = 0; v < x.cols(); ++v) {
      e += 0.5 * k_ * (x.col(v) - targets_.col(v)).squaredNorm();
      if (v + 1 < x.cols()) e += 0.5 * s_ * ((x.col(v + 1) - x.col(v)) - (targets_.col(v + 1) - targets_.col(v))).squaredNorm();
    }
    return {e, std::fabs(e)};
  }
  void to_nodal(Eigen::VectorXd& step) const override { contact_.to_nodal(step); }
  double slope(const Eigen::VectorXd& move) const override { return gradient_.dot(move); }
  void make_admissible(Eigen::Matrix3Xd& trial, double fraction) const override {
    contact_.settle(obstacles_, trial, fraction == 1.0);
  }

  Eigen::VectorXd wall_gradient(const Eigen::Matrix3Xd& x) const {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(3 * x.cols());
    for (Eigen::Index v = 0; v < x.cols(); ++v) {
      g.segment<3>(3 * v) += k_ * (x.col(v) - targets_.col(v));
      if (v + 1 < x.cols()) {
        const Eigen::Vector3d f = s_ * ((x.col(v + 1) - x.col(v)) - (targets_.col(v + 1) - targets_.col(v)));
        g.segment<3>(3 * (v + 1)) += f;
        g.segment<3>(3 * v) -= f;
      }
    }
    for (Eigen::Index d = 0; d < g.size(); ++d) {
      if (is_fixed(d)) g[d] = 0.0;
    }
    return g;
  }
  const Obstacles& obstacles() const { return obstacles_; }

 private:
  bool is_fixed(Eigen::Index d) const { return !fixed_.empty() && fixed_[static_cast<std::size_t>(d)]; }
  Eigen::Matrix3Xd targets_;
  double k_, s_;
  Obstacles obstacles_;
  ActiveSetContact contact_;
  std::vector<char> fixed_;
  Eigen::SparseMatrix<double> pattern_;
  Eigen::VectorXd gradient_;
};

Obstacles sphere_and_plane() {
  Obstacles o;
  o.spheres = {RigidSphere{Eigen::Vector3d(0.0, 0.0, 1.0), 0.5}};
  o.planes = {RigidPlane{Eigen::Vector3d(0.0, 0.0, -1.0), Eigen::Vector3d::UnitZ()}};
  return o;
}

}  // namespace

TEST_CASE("active set: points drawn into a sphere and a plane rest at their exact projections") {
  // Targets: inside the sphere (off-axis, on the axis), outside everything, below the plane,
  // and inside the sphere with y held (it may only move in its plane y = 0.2).
  Eigen::Matrix3Xd targets(3, 5);
  targets.col(0) = Eigen::Vector3d(0.1, -0.2, 0.8);
  targets.col(1) = Eigen::Vector3d(0.0, 0.0, 1.3);
  targets.col(2) = Eigen::Vector3d(2.0, 1.0, 0.0);
  targets.col(3) = Eigen::Vector3d(0.3, 0.4, -1.25);
  targets.col(4) = Eigen::Vector3d(0.1, 0.2, 1.1);
  std::vector<char> fixed(15, 0);
  fixed[3 * 4 + 1] = 1;
  const double k = 3.0;
  SpringProblem problem(targets, k, 0.0, fixed, sphere_and_plane());
  // Start: every point outside (admissible), y of point 4 at its held value.
  Eigen::Matrix3Xd x(3, 5);
  x.col(0) = Eigen::Vector3d(0.6, 0.0, 1.0);
  x.col(1) = Eigen::Vector3d(0.0, 0.0, 1.7);
  x.col(2) = Eigen::Vector3d(1.0, 1.0, 0.0);
  x.col(3) = Eigen::Vector3d(0.0, 0.0, 0.0);
  x.col(4) = Eigen::Vector3d(0.6, 0.2, 1.0);
  NewtonSolver solver(problem);
  NewtonOptions options;
  options.gradient_tolerance = 1e-13;
  options.max_step = 10.0;
  const NewtonReport report = solver.minimise(x, options);
  REQUIRE(report.status == NewtonStatus::converged);

  // References: the closest points of the admissible set.
  const Eigen::Vector3d c(0.0, 0.0, 1.0);
  const double r = 0.5;
  auto radial = [&](const Eigen::Vector3d& a) { return Eigen::Vector3d(c + r * (a - c).normalized()); };
  Eigen::Matrix3Xd expected = targets;
  expected.col(0) = radial(targets.col(0));
  expected.col(1) = radial(targets.col(1));
  expected.col(3).z() = -1.0;
  // In the plane y = 0.2 the sphere is a circle of radius sqrt(r^2 - 0.2^2) about (0, 0.2, 1).
  const double circle = std::sqrt(r * r - 0.04);
  const Eigen::Vector3d in_plane(targets(0, 4), 0.0, targets(2, 4) - 1.0);
  expected.col(4) = Eigen::Vector3d(0.0, 0.2, 1.0) + circle * in_plane.normalized();
  for (Eigen::Index v = 0; v < 5; ++v) {
    CAPTURE(v);
    CHECK((x.col(v) - expected.col(v)).norm() < 1e-12);
  }
  // No penetration, to rounding; multipliers k times the distance pulled, on the surfaces only.
  const Eigen::VectorXd g = problem.wall_gradient(x);
  for (Eigen::Index v = 0; v < 5; ++v) {
    ObstacleGap gap;
    problem.obstacles().nearest(x.col(v), gap);
    CHECK(gap.gap >= -1e-15);
  }
  CHECK(g.segment<3>(3 * 0).norm() == doctest::Approx(k * (r - (targets.col(0) - c).norm())).epsilon(1e-10));
  CHECK(g.segment<3>(3 * 3).norm() == doctest::Approx(k * 0.25).epsilon(1e-10));
  CHECK(g.segment<3>(3 * 2).norm() < 1e-12);  // free: no force
  // The energy is quadratic: once the active set is right, one step ends it. Measured: 7
  // iterations from a start far from every target (the set settles as points reach surfaces).
  CHECK(report.iterations <= 8);
}

TEST_CASE("active set: a coupled chain pressed into a sphere meets the contact conditions to rounding") {
  // Twenty points on a line through the sphere, each drawn to a target 0.3 deep in it and
  // coupled to its neighbours: some rest on the sphere, the ends do not touch it.
  const int n = 20;
  Eigen::Matrix3Xd targets(3, n), x(3, n);
  for (int v = 0; v < n; ++v) {
    const double s = -1.0 + 2.0 * v / (n - 1);
    targets.col(v) = Eigen::Vector3d(s, 0.05 * s, 1.6 - 0.3 - 0.2 * s * s);
    x.col(v) = Eigen::Vector3d(s, 0.05 * s, 1.6);
  }
  Obstacles obstacles;
  obstacles.spheres = {RigidSphere{Eigen::Vector3d(0.0, 0.0, 1.0), 0.5}};
  SpringProblem problem(targets, 1.0, 20.0, {}, obstacles);
  NewtonSolver solver(problem);
  NewtonOptions options;
  options.gradient_tolerance = 1e-12;
  options.max_step = 0.1;
  const NewtonReport report = solver.minimise(x, options);
  REQUIRE(report.status == NewtonStatus::converged);
  const Eigen::VectorXd g = problem.wall_gradient(x);
  int touching = 0;
  for (int v = 0; v < n; ++v) {
    CAPTURE(v);
    const ObstacleGap gap = gap_to(obstacles.spheres[0], x.col(v));
    CHECK(gap.gap >= -1e-15);                               // non-penetration
    const double multiplier = gap.normal.dot(g.segment<3>(3 * v));
    if (std::fabs(gap.gap) <= 1e-12) {
      ++touching;
      CHECK(multiplier >= -1e-12);                          // the obstacle only pushes
      CHECK((g.segment<3>(3 * v) - multiplier * gap.normal).norm() < 1e-11);  // stationarity
    } else {
      CHECK(g.segment<3>(3 * v).norm() < 1e-11);            // complementarity: no force off the surface
    }
  }
  CHECK(touching >= 3);
  CHECK(touching < n);
}
