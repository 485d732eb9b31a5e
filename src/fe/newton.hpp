// Newton's method for the minimum of the total potential energy: a sparse Cholesky
// factorisation (CHOLMOD, simplicial LL^T, its symbolic analysis done once for the assembly's fixed
// pattern), an indefinite Hessian regularised by a diagonal shift grown until it factorises,
// and a backtracking line search on the energy (Armijo). Converged when the largest gradient
// entry is below a tolerance relative to the wall's nodal force scale.
#pragma once

#include <Eigen/Core>

#include <memory>
#include <vector>

#include "fe/assembly.hpp"

namespace growthuq::fe {

struct NewtonOptions {
  int max_iterations = 40;
  double gradient_tolerance = 1e-8;  // max |gradient| / force_scale
  double max_step = 0.25;            // largest nodal move of one iteration, / d0
  int max_line_search = 40;
  int max_shifts = 30;
  // Contact-aware line search (0: off). Newton's model does not see an obstacle that a node has
  // not touched yet, so its step can carry the node deep inside, and a plain backtracking line
  // search then cuts the whole step to almost nothing (the indentation's iterations were spent
  // so, at 1e-3 of a step each). With a floor > 0, every trial point has its nodes moved back
  // out of the obstacles to a penetration of at most max(floor, 1.5 times the deepest
  // penetration of the current iterate) (a projection onto that set, ShellAssembly::
  // limit_penetration) before its energy is compared; at a converged state with penetrations
  // below the floor the projection does nothing, so the minimiser is unchanged.
  double penetration_floor = 0.0;
};

enum class NewtonStatus { converged, max_iterations, line_search_failed, factorisation_failed, not_finite };

struct NewtonReport {
  NewtonStatus status = NewtonStatus::max_iterations;
  int iterations = 0;           // factorisations with a step taken
  int shifted = 0;              // iterations that needed a diagonal shift
  double energy = 0.0;
  double gradient_norm = 0.0;   // max |gradient| / force_scale at the end
  std::vector<double> gradient_history;  // the same at the start of each iteration
};

// Accumulated time of the parts, for the benchmark.
struct SolverTiming {
  double assembly = 0.0, factorisation = 0.0, contact = 0.0;
  int factorisations = 0;
};

class NewtonSolver {
 public:
  explicit NewtonSolver(const ShellAssembly& assembly);
  ~NewtonSolver();
  NewtonSolver(const NewtonSolver&) = delete;
  NewtonSolver& operator=(const NewtonSolver&) = delete;

  // Minimises from x (node positions; fixed dofs keep their values) in place.
  NewtonReport minimise(Eigen::Matrix3Xd& x, const NewtonOptions& options = {});
  const SolverTiming& timing() const { return timing_; }

 private:
  struct Factor;
  const ShellAssembly& assembly_;
  std::unique_ptr<Factor> factor_;
  Eigen::SparseMatrix<double> hessian_;
  SolverTiming timing_;
  double last_shift_ = 0.0;
};

}  // namespace growthuq::fe
