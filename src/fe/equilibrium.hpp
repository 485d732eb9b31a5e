// Load stepping to equilibrium along a one-parameter load path t in [0, 1]: each step is a
// Newton minimisation from the previous state (with a linear predictor); a step that fails is
// halved, a step that converges easily lets the next one grow; a contact penalty is raised until
// the deepest penetration is below its tolerance. Bounded work: a status, never a hang.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <string>

#include "fe/assembly.hpp"
#include "fe/newton.hpp"
#include "fe/status.hpp"

namespace growthuq::fe {

struct LoadSteppingOptions {
  double first_step = 0.25;  // of t
  double max_step = 0.25;
  double min_step = 1.0 / 4096;
  int max_attempts = 200;    // converged steps plus failed ones
  NewtonOptions newton;
  double penetration_tolerance = 0.0;  // absolute (/ d0); 0: the penalty is not controlled
  int max_penalty_raises = 10;
};

struct EquilibriumResult {
  FeStatus status = FeStatus::ok;
  std::string message;
  double reached = 0.0;  // last converged load parameter
  int steps = 0, cuts = 0, newton_iterations = 0, penalty_raises = 0;
};

// `set_loads(t, loads)` sets the loads of parameter t (it must leave loads.penalty alone: the
// stepping raises it). `on_step(t, x)`, if given, runs after each converged step; returning false
// stops the path there (status ok). x: the start state on entry (equilibrium at t = 0, fixed dofs
// at their prescribed values), the last converged state on return.
EquilibriumResult solve_equilibrium(ShellAssembly& assembly, NewtonSolver& solver, Eigen::Matrix3Xd& x,
                                    const std::function<void(double, ShellLoads&)>& set_loads,
                                    const LoadSteppingOptions& options = {},
                                    const std::function<bool(double, const Eigen::Matrix3Xd&)>& on_step = {});

}  // namespace growthuq::fe
