// Newton's method for the minimum of an energy over nodal positions, free of physics: the
// problem (NewtonProblem) gives the energy, the Newton system of a step in its own coordinates
// (constraints applied there), the nodal move of a solution and a step-feasibility projection.
// The solver factorises the system with a sparse Cholesky (CHOLMOD, simplicial LL^T, its
// symbolic analysis done once for the problem's fixed pattern), regularises an indefinite
// system by a diagonal shift grown until it factorises, and globalises by a backtracking
// (Armijo) search along the projected path (Bertsekas 1982, projected Newton).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <vector>

namespace growthuq::fe {

// An energy and the size of its terms (the round-off below which two energies are equal).
struct EnergyValue {
  double value = 0.0;
  double magnitude = 0.0;  // sum of the terms' absolute values
};

// What Newton needs of a problem. Positions are 3 x nodes; dofs are node-major (x, y, z).
class NewtonProblem {
 public:
  virtual ~NewtonProblem() = default;
  virtual Eigen::Index nodes() const = 0;
  // The system's sparsity (lower triangle); every linearise() fills exactly this pattern.
  virtual const Eigen::SparseMatrix<double>& pattern() const = 0;
  // At an admissible x: the energy, and (gradient, hessian) of the step's system H u = -g in the
  // problem's coordinates (u need not be the nodal move: see to_nodal). Also returns in
  // `stationarity` the largest entry of the constrained gradient (zero at a solution; infinite at
  // a state that is not admissible).
  virtual EnergyValue linearise(const Eigen::Matrix3Xd& x, Eigen::VectorXd& gradient,
                                Eigen::SparseMatrix<double>& hessian, double& stationarity) = 0;
  virtual EnergyValue energy(const Eigen::Matrix3Xd& x) const = 0;
  // The nodal move of a system's solution, in place (the identity by default).
  virtual void to_nodal(Eigen::VectorXd& /*step*/) const {}
  // The first-order change of the energy for a nodal move from the last linearised x.
  virtual double slope(const Eigen::VectorXd& move) const = 0;
  // A trial point, `fraction` of the way along the step (1: the whole step), moved into the
  // admissible set in place (nothing by default).
  virtual void make_admissible(Eigen::Matrix3Xd& /*trial*/, double /*fraction*/) const {}
};

struct NewtonOptions {
  int max_iterations = 40;
  double gradient_tolerance = 1e-8;  // largest entry of the constrained gradient, as the problem measures it
  double max_step = 0.25;            // largest nodal move of one iteration
  int max_line_search = 40;
  int max_shifts = 30;
  // A step the line search accepts only because its energy change is within the round-off of
  // the energy's terms (no sufficient decrease) is progress only if the stationarity after it
  // falls below half the best before it; this many such steps in a row end the minimisation
  // `stalled` (a load step then cut) instead of running on to max_iterations. 0: never.
  int max_stalled = 3;
  // Take the first step whole (after make_admissible), without the line search: for a start
  // that is not admissible, whose energy the line search cannot compare with (a load step's
  // predicted state, which the first step makes admissible).
  bool first_step_whole = false;
};

enum class NewtonStatus { converged, max_iterations, line_search_failed, factorisation_failed, not_finite, stalled };

struct NewtonReport {
  NewtonStatus status = NewtonStatus::max_iterations;
  int iterations = 0;           // factorisations with a step taken
  int shifted = 0;              // iterations that needed a diagonal shift
  double energy = 0.0;
  double gradient_norm = 0.0;   // stationarity at the end
  std::vector<double> gradient_history;  // the same at the start of each iteration
};

// Accumulated time of the parts, for the benchmark.
struct SolverTiming {
  double assembly = 0.0, factorisation = 0.0;  // assembly: linearise and the line search's energies
  int factorisations = 0;
};

class NewtonSolver {
 public:
  explicit NewtonSolver(NewtonProblem& problem);
  ~NewtonSolver();
  NewtonSolver(const NewtonSolver&) = delete;
  NewtonSolver& operator=(const NewtonSolver&) = delete;

  // Minimises from x (admissible) in place.
  NewtonReport minimise(Eigen::Matrix3Xd& x, const NewtonOptions& options = {});
  const SolverTiming& timing() const { return timing_; }

 private:
  struct Factor;
  NewtonProblem& problem_;
  std::unique_ptr<Factor> factor_;
  Eigen::SparseMatrix<double> hessian_;
  SolverTiming timing_;
  double last_shift_ = 0.0;
};

}  // namespace growthuq::fe
