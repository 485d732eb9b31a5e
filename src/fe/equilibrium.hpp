// Load stepping to equilibrium along a one-parameter load path t in [0, 1]: each step is a
// Newton minimisation from the previous state (with a linear predictor); a step that fails is
// halved, a step that converges easily lets the next one grow; the contact method may ask for a
// converged step to be tightened and solved again (the penalty raised). Bounded work: a status,
// never a hang.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <string>

#include "fe/newton.hpp"
#include "fe/shell_objective.hpp"
#include "growthuq/evaluation/sample_status.hpp"

namespace growthuq::fe {

struct LoadSteppingOptions {
  double first_step = 0.25;  // of t
  double max_step = 0.25;
  // Past t = max_step / relative_max_step the cap grows with the path, to this fraction of t: a
  // path that runs on past the depth its steps were sized from (an indentation that stops at a
  // force, not a depth) keeps a fixed number of steps per doubling of t.
  double relative_max_step = 0.0;
  double min_step = 1.0 / 4096;
  int max_attempts = 200;    // converged steps plus failed ones
  int easy_iterations = 6;   // a step converged within these lets the next one grow 1.5 times
  NewtonOptions newton;
};

struct EquilibriumResult {
  SampleStatus status = SampleStatus::ok;
  std::string message;
  double reached = 0.0;  // last converged load parameter
  int steps = 0, cuts = 0, newton_iterations = 0;
};

// `set_loads(t, loads)` sets the loads of parameter t (it must leave loads.penalty alone: the
// contact method raises it). `solver` minimises `objective`. `on_step(t, x)`, if given, runs after each converged step; returning false
// stops the path there (status ok). x: the start state on entry (equilibrium at t = 0, fixed dofs
// at their prescribed values), the last converged state on return.
EquilibriumResult solve_equilibrium(ShellObjective& objective, NewtonSolver& solver, Eigen::Matrix3Xd& x,
                                    const std::function<void(double, ShellLoads&)>& set_loads,
                                    const LoadSteppingOptions& options = {},
                                    const std::function<bool(double, const Eigen::Matrix3Xd&)>& on_step = {});

}  // namespace growthuq::fe
