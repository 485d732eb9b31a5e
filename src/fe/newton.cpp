#include "fe/newton.hpp"

#include <Eigen/CholmodSupport>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace growthuq::fe {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

// CHOLMOD's simplicial LL^T (faster than its supernodal one with Debian's reference BLAS at
// these sizes: 18 against 34 ms for 1311 dofs, 76 against 127 ms for 2703, on a loaded machine) of the lower triangle; the symbolic analysis (fill-reducing
// ordering, supernodes) is done once for the assembly's pattern.
struct NewtonSolver::Factor {
  Eigen::CholmodSimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
};

NewtonSolver::NewtonSolver(const ShellAssembly& assembly)
    : assembly_(assembly), factor_(std::make_unique<Factor>()) {
  factor_->llt.cholmod().print = 0;  // a failed factorisation is expected (indefinite), not an error
  hessian_ = assembly_.pattern();
  factor_->llt.analyzePattern(hessian_);
}

NewtonSolver::~NewtonSolver() = default;

NewtonReport NewtonSolver::minimise(Eigen::Matrix3Xd& x, const NewtonOptions& options) {
  NewtonReport report;
  const Eigen::Index n = assembly_.dofs();
  Eigen::VectorXd gradient(n), step(n);
  Eigen::Matrix3Xd trial(3, x.cols());
  const double scale = assembly_.force_scale();
  for (int iteration = 0;; ++iteration) {
    auto start = Clock::now();
    const EnergyParts parts = assembly_.evaluate(x, gradient, &hessian_, &timing_.contact);
    timing_.assembly += seconds_since(start);
    report.energy = parts.total();
    report.gradient_norm = gradient.lpNorm<Eigen::Infinity>() / scale;
    report.gradient_history.push_back(report.gradient_norm);
    if (!std::isfinite(report.energy) || !std::isfinite(report.gradient_norm)) {
      report.status = NewtonStatus::not_finite;
      return report;
    }
    if (report.gradient_norm <= options.gradient_tolerance) {
      report.status = NewtonStatus::converged;
      return report;
    }
    if (iteration >= options.max_iterations) {
      report.status = NewtonStatus::max_iterations;
      return report;
    }
    // Factorise H + shift I, the shift grown tenfold from a small fraction of the mean
    // diagonal until the factorisation succeeds (Nocedal and Wright 2006, algorithm 3.3).
    start = Clock::now();
    double mean_diagonal = 0.0;
    for (Eigen::Index c = 0; c < n; ++c) mean_diagonal += std::fabs(hessian_.coeff(c, c));
    mean_diagonal = std::max(mean_diagonal / static_cast<double>(n), 1e-300);
    // The unshifted Hessian first (Newton's quadratic convergence where it is positive
    // definite); then a shift from a quarter of the last one that worked, grown tenfold.
    double shift = 0.0;
    bool factorised = false;
    for (int attempt = 0; attempt <= options.max_shifts; ++attempt) {
      factor_->llt.setShift(shift);
      factor_->llt.factorize(hessian_);
      ++timing_.factorisations;
      if (factor_->llt.info() == Eigen::Success) {
        factorised = true;
        break;
      }
      shift = shift == 0.0 ? std::max(last_shift_ / 4, 1e-8 * mean_diagonal) : 10 * shift;
    }
    if (!factorised) {
      timing_.factorisation += seconds_since(start);
      report.status = NewtonStatus::factorisation_failed;
      return report;
    }
    if (shift > 0) ++report.shifted;
    last_shift_ = shift;
    step = -factor_->llt.solve(gradient);
    timing_.factorisation += seconds_since(start);
    if (!step.allFinite()) {
      report.status = NewtonStatus::not_finite;
      return report;
    }
    const double largest = step.lpNorm<Eigen::Infinity>();
    if (largest > options.max_step) step *= options.max_step / largest;
    const double slope = gradient.dot(step);
    // Backtracking on the energy; energy changes below its round-off are accepted as no
    // change (near the minimum the decrease is below what double precision resolves).
    const double noise = 1e-13 * (std::fabs(parts.membrane) + std::fabs(parts.bending) +
                                  std::fabs(parts.pressure) + std::fabs(parts.contact) +
                                  std::fabs(parts.point_loads)) + 1e-300;
    double alpha = 1.0;
    bool accepted = false;
    start = Clock::now();
    const double cap = options.penetration_floor > 0
                           ? std::max(options.penetration_floor, 1.5 * assembly_.contact_state(x).max_penetration)
                           : 0.0;
    for (int k = 0; k < options.max_line_search; ++k) {
      trial = x + alpha * Eigen::Map<const Eigen::Matrix3Xd>(step.data(), 3, x.cols());
      if (cap > 0) assembly_.limit_penetration(trial, cap);
      const double energy = assembly_.energy(trial).total();
      if (std::isfinite(energy) && (energy <= report.energy + 1e-4 * alpha * slope ||
                                    std::fabs(energy - report.energy) <= noise)) {
        accepted = true;
        break;
      }
      alpha *= 0.5;
    }
    timing_.assembly += seconds_since(start);
    if (!accepted) {
      report.status = NewtonStatus::line_search_failed;
      return report;
    }
    x = trial;
    report.iterations = iteration + 1;
  }
}

}  // namespace growthuq::fe
