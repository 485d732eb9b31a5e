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
  }
  return "unknown";
}

// The start of a step's Newton iterations: nodes that the obstacles' new positions put inside
// them, or that lie within a thin band of their surfaces, are placed at a penetration of twice
// the penalty's smoothing (radially for a sphere, along the normal for a plane). Otherwise the
// first Newton steps would fight penalty forces of the whole step's motion, and a node just
// touching (zero penetration, where the penalty's curvature vanishes) would be invisible to the
// Newton model: a tube resting on the substrate would be free to swing through it.
void project_out_of_obstacles(const ShellAssembly& assembly, Eigen::Matrix3Xd& x) {
  const ShellLoads& loads = assembly.loads();
  const double margin = 2 * loads.penalty.smoothing;
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    Eigen::Vector3d p = x.col(v);
    for (const RigidSphere& sphere : loads.spheres) {
      const Eigen::Vector3d r = p - sphere.centre;
      const double distance = r.norm();
      if (distance < sphere.radius + margin && distance > 0) p = sphere.centre + r * ((sphere.radius - margin) / distance);
    }
    for (const RigidPlane& plane : loads.planes) {
      const double gap = plane.normal.dot(p - plane.point);
      if (gap < margin) p -= (gap + margin) * plane.normal;
    }
    for (int k = 0; k < 3; ++k) {
      if (!assembly.is_fixed(3 * v + k)) x(k, v) = p[k];
    }
  }
}

}  // namespace

EquilibriumResult solve_equilibrium(ShellAssembly& assembly, NewtonSolver& solver, Eigen::Matrix3Xd& x,
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
      result.status = FeStatus::not_converged;
      result.message = "load stepping stopped after " + std::to_string(attempt) + " attempts at t = " +
                       std::to_string(t) + " (" + last_failure + ")";
      return result;
    }
    const double t_next = t + dt > 1.0 - 1e-9 ? 1.0 : t + dt;
    const double step = t_next - t;
    set_loads(t_next, assembly.loads());
    trial = x;
    if (previous_dt > 0) trial += (step / previous_dt) * previous_move;  // linear predictor
    project_out_of_obstacles(assembly, trial);
    NewtonReport report = solver.minimise(trial, options.newton);
    result.newton_iterations += report.iterations;
    bool converged = report.status == NewtonStatus::converged;
    // Penalty control: raise the stiffness until the deepest penetration is within tolerance
    // (penetration ~ force / stiffness, so the factor aims at half the tolerance).
    for (int raise = 0; converged && options.penetration_tolerance > 0; ++raise) {
      const double penetration = assembly.contact_state(trial).max_penetration;
      if (penetration <= options.penetration_tolerance) break;
      if (raise >= options.max_penalty_raises) {
        converged = false;
        last_failure = "penetration " + std::to_string(penetration) + " above tolerance after " +
                       std::to_string(raise) + " penalty raises";
        break;
      }
      assembly.loads().penalty.stiffness *= std::max(2.0, 2.0 * penetration / options.penetration_tolerance);
      ++result.penalty_raises;
      report = solver.minimise(trial, options.newton);
      result.newton_iterations += report.iterations;
      converged = report.status == NewtonStatus::converged;
    }
    if (!converged) {
      if (report.status != NewtonStatus::converged) last_failure = describe(report.status);
      ++result.cuts;
      dt = step / 2;
      if (dt < options.min_step) {
        result.status = FeStatus::not_converged;
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
    if (report.iterations <= 4) dt = std::min(options.max_step, 1.5 * step);
    else dt = std::min(options.max_step, step);
    if (on_step && !on_step(t, x)) return result;
  }
  return result;
}

}  // namespace growthuq::fe
