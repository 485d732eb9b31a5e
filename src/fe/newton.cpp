#include "fe/newton.hpp"

#include <Eigen/CholmodSupport>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>


namespace growthuq::fe {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

// CHOLMOD's simplicial LL^T (faster than its supernodal one with Debian's reference BLAS at
// these sizes: 18 against 34 ms for 1311 dofs, 76 against 127 ms for 2703, on a loaded machine)
// of the lower triangle; the symbolic analysis (fill-reducing ordering) is done once.
struct NewtonSolver::Factor {
  explicit Factor(const Eigen::SparseMatrix<double>& pattern) {
    llt.cholmod().print = 0;  // a failed factorisation is expected (indefinite), not an error
    llt.analyzePattern(pattern);
  }
  Eigen::CholmodSimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
};

NewtonSolver::NewtonSolver(NewtonProblem& problem)
    : problem_(problem), factor_(std::make_unique<Factor>(problem.pattern())) {
  hessian_ = problem_.pattern();
}

NewtonSolver::~NewtonSolver() = default;

NewtonReport NewtonSolver::minimise(Eigen::Matrix3Xd& x, const NewtonOptions& options) {
  NewtonReport report;
  const Eigen::Index n = 3 * problem_.nodes();
  Eigen::VectorXd gradient(n), step(n), move(n);
  Eigen::Matrix3Xd trial(3, x.cols());
  double best = std::numeric_limits<double>::infinity();  // the least stationarity so far
  bool within_noise = false;                             // the last step was accepted only as noise
  int stalled = 0;
  for (int iteration = 0;; ++iteration) {
    auto start = Clock::now();
    double stationarity = 0.0;
    const EnergyValue here = problem_.linearise(x, gradient, hessian_, stationarity);
    timing_.assembly += seconds_since(start);
    report.energy = here.value;
    report.gradient_norm = stationarity;
    report.gradient_history.push_back(stationarity);
    if (!std::isfinite(here.value) || std::isnan(stationarity)) {
      report.status = NewtonStatus::not_finite;
      return report;
    }
    if (stationarity <= options.gradient_tolerance) {
      report.status = NewtonStatus::converged;
      return report;
    }
    // A stall: steps accepted as round-off (the energy unchanged to its last digits) while the
    // gradient stays where it was. Near a minimum such steps are Newton's last ones and the
    // gradient falls by orders of magnitude each; where they leave it, the iterate is stuck (the
    // sphere's stall of src/fe/README.md section 8: steps uphill by 5e-14 to 1e-13 of the
    // energy, the gradient the same to 4 digits, until the iteration cap).
    stalled = within_noise && !(stationarity < 0.5 * best) ? stalled + 1 : 0;
    best = std::min(best, stationarity);
    if (options.max_stalled > 0 && stalled >= options.max_stalled) {
      report.status = NewtonStatus::stalled;
      return report;
    }
    if (iteration >= options.max_iterations) {
      report.status = NewtonStatus::max_iterations;
      return report;
    }
    start = Clock::now();
    double shift = 0.0;
    // H + shift I: the unshifted system first (Newton's quadratic convergence where it is
    // positive definite), then a shift from a quarter of the last nonzero one that worked (the
    // indefinite states of a path are alike: starting again from the smallest shift cost three
    // failed factorisations per shifted iteration), grown tenfold (Nocedal and Wright 2006,
    // algorithm 3.3).
    double mean_diagonal = 0.0;
    for (Eigen::Index c = 0; c < n; ++c) mean_diagonal += std::fabs(hessian_.coeff(c, c));
    mean_diagonal = std::max(mean_diagonal / static_cast<double>(n), 1e-300);
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
    if (shift > 0) last_shift_ = shift;
    step = -factor_->llt.solve(gradient);
    timing_.factorisation += seconds_since(start);
    problem_.to_nodal(step);
    if (!step.allFinite()) {
      report.status = NewtonStatus::not_finite;
      return report;
    }
    const double largest = step.lpNorm<Eigen::Infinity>();
    if (largest > options.max_step) step *= options.max_step / largest;
    // Backtracking along the projected path x(alpha) = P(x + alpha step) with the sufficient
    // decrease measured on the move actually made (Bertsekas 1982); energy changes below the
    // round-off of its terms count as no change (near the minimum double precision cannot
    // resolve the decrease).
    const double noise = 1e-13 * here.magnitude + 1e-300;
    double alpha = 1.0;
    bool accepted = false;
    start = Clock::now();
    const bool whole = iteration == 0 && options.first_step_whole;
    for (int k = 0; k < options.max_line_search; ++k) {
      trial = x + alpha * Eigen::Map<const Eigen::Matrix3Xd>(step.data(), 3, x.cols());
      problem_.make_admissible(trial, alpha);
      move = Eigen::Map<const Eigen::VectorXd>(trial.data(), n) - Eigen::Map<const Eigen::VectorXd>(x.data(), n);
      const double energy = problem_.energy(trial).value;
      const bool decrease = energy <= here.value + 1e-4 * std::min(0.0, problem_.slope(move));
      if (std::isfinite(energy) && (whole || decrease || std::fabs(energy - here.value) <= noise)) {
        accepted = true;
        within_noise = !whole && !decrease;
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
