// The total potential energy of the wall under its loads, with its exact gradient and sparse
// Hessian over all nodal dofs: membrane + bending + pressure (-p V) + contact penalty + point
// loads (the contact penalty only when its stiffness is positive). Fixed dofs (mirror nodes' y, the pinned ring, supports) are held where they are: their
// gradient entries are zero and their Hessian rows and columns those of the identity. The
// sparsity pattern is built once; each evaluation refills its values.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

#include "fe/contact.hpp"
#include "fe/material_law.hpp"
#include "fe/membrane.hpp"
#include "fe/mesh.hpp"
#include "fe/topology.hpp"

namespace growthuq::fe {

// What changes along a load path.
struct ShellLoads {
  double pressure = 0.0;  // p/E, as the potential -p V
  std::vector<PointLoad> point_loads;
  Obstacles obstacles;  // frictionless rigid obstacles
  // The penalty of every obstacle (contact.hpp). Stiffness 0: the obstacles add no energy, as
  // under the active-set method, which holds them as constraints (active_set_contact.hpp).
  PenaltyLaw penalty;
};

// A shell and its loads, all dimensionless (lengths / d0, stresses / E).
struct ShellProblem {
  TriangleMesh mesh;           // reference (unstressed) mid-surface
  WallMaterial material;       // law, young (1 in the solver), poisson, thickness h0/d0
  bool bending = true;         // Kirchhoff-Love bending on top of the membrane
  double bending_thickness = 0.0;  // 0: the material's thickness
  bool mirror_y0 = false;      // boundary edges on y = 0 are mirror edges (half model)
  std::vector<char> fixed;     // per dof, node-major (x, y, z); empty = nothing fixed
  ShellLoads loads;
};

// The dofs a half model or a pinned ring needs fixed: y of every node on y = 0, all three of
// every node on the plane z = 0 (the tube's open end).
std::vector<char> mirror_and_end_ring_fixed(const TriangleMesh& mesh, bool mirror_y0, bool pin_z0);

struct EnergyParts {
  double membrane = 0, bending = 0, pressure = 0, contact = 0, point_loads = 0;
  double total() const { return membrane + bending + pressure + contact + point_loads; }
};

// What the obstacles feel at a state under the penalty.
struct ContactState {
  std::vector<Eigen::Vector3d> sphere_force;  // total force of the wall on each sphere
  std::vector<Eigen::Vector3d> plane_force;
  double max_penetration = 0.0;        // over all obstacles and nodes
  std::vector<double> sphere_penetration;  // deepest, per sphere
  std::vector<int> sphere_contacts;    // nodes in contact, per sphere
};

class ShellAssembly {
 public:
  explicit ShellAssembly(ShellProblem problem);

  const ShellProblem& problem() const { return problem_; }
  ShellLoads& loads() { return problem_.loads; }
  const ShellLoads& loads() const { return problem_.loads; }
  const MeshTopology& topology() const { return topology_; }
  Eigen::Index dofs() const { return 3 * problem_.mesh.positions.cols(); }
  bool is_fixed(Eigen::Index dof) const { return !problem_.fixed.empty() && problem_.fixed[static_cast<std::size_t>(dof)]; }

  // Energy alone (line search).
  EnergyParts energy(const Eigen::Matrix3Xd& x) const;
  // Energy, gradient (size dofs(), zero at fixed dofs) and, if given, the Hessian in the
  // assembly's pattern (lower triangle stored; fixed rows and columns of the identity).
  // `contact_seconds` accumulates the time spent in the contact terms.
  EnergyParts evaluate(const Eigen::Matrix3Xd& x, Eigen::VectorXd& gradient,
                       Eigen::SparseMatrix<double>* hessian, double* contact_seconds = nullptr) const;
  // A Hessian with the pattern and zero values, for the symbolic factorisation.
  const Eigen::SparseMatrix<double>& pattern() const { return pattern_; }

  ContactState contact_state(const Eigen::Matrix3Xd& x) const;
  // Moves every node that penetrates an obstacle by more than `cap` back to a penetration of
  // `cap` (radially for a sphere, along the normal for a plane), its fixed dofs untouched; returns
  // how many nodes moved. Newton's line search uses it (newton.hpp).
  int limit_penetration(Eigen::Matrix3Xd& x, double cap) const;
  // A typical nodal force of the wall, E h0 times the shortest edge: the gradient's scale.
  double force_scale() const { return force_scale_; }
  double shortest_edge() const { return shortest_edge_; }

 private:
  EnergyParts evaluate_impl(const Eigen::Matrix3Xd& x, Eigen::VectorXd* gradient,
                            Eigen::SparseMatrix<double>* hessian, double* contact_seconds) const;
  // Position of entry (3a + i, 3b + j), a >= b, of a vertex pair whose rank in b's list is
  // `rank` (0: the diagonal block, then i >= j).
  int offset(int a, int b, int rank, int i, int j) const;
  template <int N>
  void scatter(std::size_t face, const Eigen::Matrix<double, 3 * N, 3 * N>& local, double* values) const;

  ShellProblem problem_;
  MeshTopology topology_;
  std::vector<MembraneReference> membrane_;
  std::vector<BendingReference> bending_;
  double bending_thickness_ = 0.0;
  Eigen::SparseMatrix<double> pattern_;
  std::vector<int> column_start_;                // per dof column
  std::vector<std::array<int, 36>> face_rank_;   // per face: rank of stencil pair (a, b), -1 none
  std::vector<int> fixed_zero_;                  // value positions zeroed for fixed dofs
  std::vector<int> fixed_diagonal_;              // value positions set to 1
  double force_scale_ = 1.0;
  double shortest_edge_ = 1.0;
};

}  // namespace growthuq::fe
