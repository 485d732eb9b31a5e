// Automatic viscous stabilisation of a quasi-static load path, in the form of the commercial code
// the study's driver ran (Abaqus/Standard, "Automatic stabilization of unstable problems"):
// viscous forces F_v = c M* v added to the equilibrium, M* a mass matrix of unit density, v the
// nodal velocity over the increment, Delta x / Delta t. Here as the potential of a load step
//
//     D(x) = c / (2 Delta t) sum_i m_i |x_i - x_i^n|^2                                    (1)
//
// (m_i the node's lumped mass: its third of each adjacent face's unstressed area times h0; x^n
// the last converged step), whose gradient is F_v and whose Hessian the diagonal c / Delta t M*.
// The step dissipates (c / Delta t) |x - x^n|_M^2. Time is the load parameter t of the step
// (the driver's step time, the probe's depth in um, over its period): c depends on that unit,
// the forces and energies do not.
//
// The damping factor from a dissipated-energy fraction f, the first increment's rule: the first
// increment is solved without damping; c is then chosen so that the energy an increment like it
// would dissipate, extrapolated over the step, is f times the strain energy extrapolated over
// the step (both linearly in time):
//
//     c (|Delta x_1|_M^2 / Delta t_1) (T / Delta t_1) = f E_extrapolated                  (2)
//
// With an adaptive ratio R, a converged step after which the dissipated energy would exceed R
// times the strain energy is solved again with c lowered, and c stays lowered (the code's
// adaptive algorithm also raises c where Newton struggles; not needed here, not done).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

#include "growthuq/fe/shell_fe_vocabulary.hpp"

namespace growthuq::fe {

struct TriangleMesh;

// Lumped unit-density masses per node: a third of each adjacent face's area times `thickness`.
Eigen::VectorXd lumped_masses(const TriangleMesh& mesh, double thickness);

class ViscousStabilisation {
 public:
  // `fixed`: per dof, node-major (empty = none); their Hessian rows are the identity's and stay so.
  ViscousStabilisation(ShellFeStabilisation options, Eigen::VectorXd masses, std::vector<char> fixed);

  // A load step of `step` (in t, the step's whole period being 1) from the converged state
  // `converged`, whose strain energy (membrane + bending) and stored energy (strain energy and
  // -p V) are given.
  void begin_step(const Eigen::Matrix3Xd& converged, double step, double strain_energy, double stored_energy);

  // (1), its gradient added to `gradient`, its Hessian added to the diagonal of `hessian`.
  double energy(const Eigen::Matrix3Xd& x) const;
  void add_gradient(const Eigen::Matrix3Xd& x, Eigen::VectorXd& gradient) const;
  void add_hessian(Eigen::SparseMatrix<double>& hessian) const;

  // After a step converged at x: true to accept it (its dissipation is then counted; the first
  // increment sets c by (2)); false when the cap lowered c and the step must be solved again.
  bool accept(const Eigen::Matrix3Xd& x, double strain_energy, double stored_energy);

  double damping_factor() const { return damping_; }  // c of the steps to come
  double dissipated() const { return dissipated_; }  // over the accepted steps
  // The energy the fraction and the cap are measured against, at a state of these energies.
  double reference_energy(double strain_energy, double stored_energy) const;
  int lowerings() const { return lowerings_; }  // times the cap lowered c

 private:
  double moved_mass_norm(const Eigen::Matrix3Xd& x) const;  // |x - x^n|_M^2

  ShellFeStabilisation options_;
  Eigen::VectorXd masses_;
  std::vector<char> fixed_;
  Eigen::Matrix3Xd previous_;
  double step_ = 0.0;
  double previous_strain_ = 0.0, previous_stored_ = 0.0;
  double start_stored_ = 0.0;  // stored energy at the path's start (the step basis' zero)
  bool started_ = false, calibrated_ = false;
  double damping_ = 0.0, dissipated_ = 0.0;
  double step_damping_ = 0.0;  // c of the step begun (0 in the first increment)
  int lowerings_ = 0, redos_ = 0;
};

}  // namespace growthuq::fe
