#include "fe/equilibrium.hpp"

#include <algorithm>
#include <cmath>

namespace growthuq::fe {
namespace {

std::string describe(NewtonStatus status) {
  switch (status) {
    case NewtonStatus::converged: return "converged";
    case NewtonStatus::max_iterations: return "Newton iteration cap reached";
    case NewtonStatus::line_search_failed: return "line search found no decrease";
    case NewtonStatus::factorisation_failed: return "Hessian not factorisable with any shift";
    case NewtonStatus::not_finite: return "non-finite energy or step";
    case NewtonStatus::stalled: return "no progress: steps within the energy's round-off left the gradient where it was";
  }
  return "unknown";
}

}  // namespace

EquilibriumResult solve_equilibrium(ShellObjective& objective, NewtonSolver& solver, Eigen::Matrix3Xd& x,
                                    const std::function<void(double, ShellLoads&)>& set_loads,
                                    const LoadSteppingOptions& options,
                                    const std::function<bool(double, const Eigen::Matrix3Xd&)>& on_step) {
  EquilibriumResult result;
  double t = 0.0, dt = std::min(options.first_step, 1.0);
  double previous_dt = 0.0;
  Eigen::Matrix3Xd previous_move = Eigen::Matrix3Xd::Zero(3, x.cols());
  Eigen::Matrix3Xd trial;
  std::string last_failure = "no step tried";
  for (int attempt = 0; t < 1.0; ++attempt) {
    if (attempt >= options.max_attempts) {
      result.status = SampleStatus::not_converged;
      result.message = "load stepping stopped after " + std::to_string(attempt) + " attempts at t = " +
                       std::to_string(t) + " (" + last_failure + ")";
      return result;
    }
    const double t_next = t + dt > 1.0 - 1e-9 ? 1.0 : t + dt;
    const double step = t_next - t;
    set_loads(t_next, objective.assembly().loads());
    objective.begin_step(x, step);
    trial = x;
    if (previous_dt > 0) trial += (step / previous_dt) * previous_move;  // linear predictor
    objective.start_step(trial);
    NewtonReport report = solver.minimise(trial, options.newton);
    result.newton_iterations += report.iterations;
    bool converged = report.status == NewtonStatus::converged;
    for (int raise = 0; converged; ++raise) {
      std::string failure;
      if (objective.accept(trial, raise, failure)) break;
      if (!failure.empty()) {
        converged = false;
        last_failure = failure;
        break;
      }
      report = solver.minimise(trial, options.newton);
      result.newton_iterations += report.iterations;
      converged = report.status == NewtonStatus::converged;
    }
    if (!converged) {
      if (report.status != NewtonStatus::converged) last_failure = describe(report.status);
      ++result.cuts;
      dt = step / 2;
      if (dt < options.min_step) {
        result.status = SampleStatus::not_converged;
        result.message = "load step below " + std::to_string(options.min_step) + " at t = " +
                         std::to_string(t) + " (" + last_failure + ")";
        return result;
      }
      continue;
    }
    previous_move = trial - x;
    previous_dt = step;
    x = trial;
    t = t_next;
    result.reached = t;
    ++result.steps;
    // Grow the step after an easy convergence, up to the cap.
    const double cap = std::max(options.max_step, options.relative_max_step * t);
    if (report.iterations <= options.easy_iterations) dt = std::min(cap, 1.5 * step);
    else dt = std::min(cap, step);
    if (on_step && !on_step(t, x)) return result;
  }
  return result;
}

}  // namespace growthuq::fe
