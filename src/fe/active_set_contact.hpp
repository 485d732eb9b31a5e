// Exact frictionless contact of the wall's nodes with the rigid obstacles, by an active set
// (a projected Newton method, Bertsekas 1982; the primal-dual active set of Hintermueller, Ito
// and Kunisch 2003 in the form contact codes use it, e.g. Hueeber and Wohlmuth 2005): a node on
// an obstacle's surface that the wall pushes into it is held on the surface, its normal
// direction eliminated in a frame rotated to the obstacle's normal, so the system keeps its
// pattern and stays symmetric positive definite where the wall is; its multiplier (the normal
// force) is the normal component of the wall's gradient. Trial points are projected out of the
// obstacles, so no node ever penetrates, and there is no penalty parameter.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

#include "fe/obstacles.hpp"

namespace growthuq::fe {

// One node held on an obstacle.
struct ActiveContact {
  int node = 0;
  int obstacle = 0;                 // index into Obstacles (spheres first)
  ObstacleGap gap;                  // at the state the set was chosen at
  double multiplier = 0.0;          // normal force of the obstacle on the node (>= 0)
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();  // columns: the node's rotated axes
  int slot = 0;                     // the column of `frame` that is the constrained normal
};

// The reaction of the obstacles at a state: force of the wall on each obstacle, nodes in
// contact, the deepest penetration (zero to rounding under this method).
struct ContactReaction {
  std::vector<Eigen::Vector3d> force;  // per obstacle (spheres first)
  std::vector<int> contacts;           // nodes held, per obstacle
  std::vector<double> penetration;     // deepest, per obstacle
  double max_penetration = 0.0;
};

class ActiveSetContact {
 public:
  // `fixed`: per dof, node-major (as ShellProblem::fixed; empty = none). `band`: a node closer
  // than this to an obstacle may be held on it (it is lifted onto the surface by the step).
  ActiveSetContact(std::vector<char> fixed, double band, double reach = 0.0);

  // Chooses the active set at an admissible x with the wall's gradient g (zero at fixed dofs):
  // every node within the band of an obstacle whose gradient pushes it into the obstacle
  // (multiplier n.g > 0). Returns the largest entry of the constrained gradient (g less the
  // multipliers' forces).
  // With the wall's Hessian (lower triangle), a node further out is held too when the wall pushes
  // it towards the obstacle by more than its gap (see the .cpp).
  double select(const Obstacles&, const Eigen::Matrix3Xd& x, const Eigen::VectorXd& g,
                const Eigen::SparseMatrix<double>* hessian = nullptr);
  // Turns the wall's Newton system (H lower triangle, g) into the step's system in the rotated
  // frame: the multipliers' curvature term -lambda c (I - n n^T) added to the held nodes'
  // diagonal blocks, H -> R^T H R, g -> R^T g, and each held normal prescribed to lift the node
  // onto the surface (u_n = -gap). Keeps H's pattern.
  void reduce(Eigen::SparseMatrix<double>& hessian, Eigen::VectorXd& gradient) const;
  // The nodal move R u of a solution u of the reduced system, in place.
  void to_nodal(Eigen::VectorXd& u) const;
  // A trial point made admissible: the held nodes that touched put back on their obstacles'
  // surfaces (with `lifted`, those the step lifts too: for the whole step), then every node out
  // of every obstacle.
  void settle(const Obstacles&, Eigen::Matrix3Xd& x, bool lifted = true) const;
  // The obstacles' reaction at x with the wall's gradient g there (after select()).
  ContactReaction reaction(const Obstacles&, const Eigen::Matrix3Xd& x) const;

  const std::vector<ActiveContact>& active() const { return active_; }

 private:
  // Every node out of every obstacle (projected onto the surface), fixed dofs untouched.
  void project(const Obstacles&, Eigen::Matrix3Xd& x) const;
  bool fixed(Eigen::Index dof) const { return !fixed_.empty() && fixed_[static_cast<std::size_t>(dof)]; }

  std::vector<char> fixed_;
  double band_ = 0.0;
  double reach_ = 0.0;
  std::vector<ActiveContact> active_;
  std::vector<int> active_of_node_;  // index into active_, -1 free
};

}  // namespace growthuq::fe
