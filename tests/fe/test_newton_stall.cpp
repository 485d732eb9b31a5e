// Newton's stall rule (newton.hpp, NewtonOptions::max_stalled) on a problem of one point whose
// energy changes only within the round-off of its terms: steps accepted as round-off that leave
// the gradient where it is end the minimisation `stalled` after max_stalled of them, where it
// used to run to the iteration cap; steps accepted as round-off that shrink the gradient (the
// last steps of a converging Newton) go on to convergence.
#include <doctest/doctest.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cmath>

#include "fe/newton.hpp"

using namespace growthuq::fe;

namespace {

// Energy M (1 + 1e-14 |x - start|): every move raises it, by far less than the round-off 1e-13 M
// that the line search allows, and by more than a double's resolution of M. The gradient it
// reports is a model of its own, not the energy's: `drawn` = x (towards the origin, the Newton
// system H = `curvature` I), else a constant, as an active set that cycles presents one.
class RoundOffProblem final : public NewtonProblem {
 public:
  RoundOffProblem(Eigen::Vector3d start, bool drawn, double curvature)
      : start_(std::move(start)), drawn_(drawn), curvature_(curvature) {
    pattern_.resize(3, 3);
    for (int i = 0; i < 3; ++i) pattern_.insert(i, i) = 0.0;
    pattern_.makeCompressed();
  }
  Eigen::Index nodes() const override { return 1; }
  const Eigen::SparseMatrix<double>& pattern() const override { return pattern_; }
  EnergyValue linearise(const Eigen::Matrix3Xd& x, Eigen::VectorXd& gradient, Eigen::SparseMatrix<double>& hessian,
                        double& stationarity) override {
    gradient_ = drawn_ ? Eigen::VectorXd(x.col(0)) : Eigen::VectorXd(Eigen::Vector3d::UnitX());
    gradient = gradient_;
    hessian = pattern_;
    for (int i = 0; i < 3; ++i) hessian.coeffRef(i, i) = curvature_;
    stationarity = gradient_.lpNorm<Eigen::Infinity>();
    return energy(x);
  }
  EnergyValue energy(const Eigen::Matrix3Xd& x) const override {
    return {scale * (1 + 1e-14 * (x.col(0) - start_).norm()), scale};
  }
  double slope(const Eigen::VectorXd& move) const override { return gradient_.dot(move); }

  static constexpr double scale = 1e4;

 private:
  Eigen::Vector3d start_;
  bool drawn_;
  double curvature_;
  Eigen::SparseMatrix<double> pattern_;
  Eigen::VectorXd gradient_;
};

}  // namespace

TEST_CASE("Newton: steps accepted as round-off that leave the gradient where it is stop as stalled") {
  const Eigen::Vector3d start(1.0, 0.0, 0.0);
  RoundOffProblem problem(start, false, 1.0);
  NewtonSolver solver(problem);
  Eigen::Matrix3Xd x = start;
  const NewtonReport report = solver.minimise(x);
  CHECK(report.status == NewtonStatus::stalled);
  CHECK(report.iterations == NewtonOptions{}.max_stalled);
  // Without the rule the same steps run to the cap.
  NewtonOptions options;
  options.max_stalled = 0;
  x = start;
  const NewtonReport capped = solver.minimise(x, options);
  CHECK(capped.status == NewtonStatus::max_iterations);
  CHECK(capped.iterations == options.max_iterations);
}

TEST_CASE("Newton: steps accepted as round-off that shrink the gradient go on to convergence") {
  // H = 1.25 I against the gradient x: each step takes x to x / 5. The first three moves (0.8,
  // 0.16, 0.032) raise the energy by 8e-11 to 3e-12, above its resolution (2e-12) and within the
  // round-off allowed (1e-9): three steps in a row accepted as round-off alone, each leaving a
  // fifth of the gradient.
  const Eigen::Vector3d start(1.0, 0.0, 0.0);
  RoundOffProblem problem(start, true, 1.25);
  NewtonSolver solver(problem);
  Eigen::Matrix3Xd x = start;
  NewtonOptions options;
  options.max_step = 10.0;  // the whole Newton step
  const NewtonReport report = solver.minimise(x, options);
  CHECK(report.status == NewtonStatus::converged);
  CHECK(report.gradient_norm <= options.gradient_tolerance);
  CHECK(report.iterations > options.max_stalled);
  CHECK(x.norm() <= options.gradient_tolerance);
}
