// The shell's total potential energy as Newton's problem (newton.hpp), with its contact method:
// the exact active set (default; active_set_contact.hpp) or the smooth penalty (contact.hpp),
// kept for comparison. The one place, with the obstacles' own file, that knows how contact is
// enforced: the load stepping and the protocols ask it for a step's start, for whether the
// solution must be tightened, and for the obstacles' reaction.
#pragma once

#include <optional>
#include <string>

#include "fe/active_set_contact.hpp"
#include "fe/assembly.hpp"
#include "fe/newton.hpp"
#include "fe/viscous_stabilisation.hpp"
#include "growthuq/fe/indentation.hpp"

namespace growthuq::fe {

// The public option's values (growthuq/fe/indentation.hpp), used as they are.
using ContactMethod = ShellFeContact;

struct ContactOptions {
  ContactMethod method = ContactMethod::active_set;
  // active set: nodes within this gap of an obstacle may be held on it (the step lifts them on).
  // penalty: nodes within it start a step at a penetration of this width (at least twice the
  // penalty's smoothing), so that Newton's model sees them.
  double band = 0.0;
  // active set: how far from an obstacle a node may be for the Newton model to hold it there
  // ahead of touching (the largest move of one Newton step is a fair choice).
  double reach = 0.0;
  // penalty only: the penetration the load stepping accepts (0: uncontrolled; the penalty is
  // raised until the deepest node is within it), and the floor of the line search's cap (0:
  // off). Newton's model does not see an obstacle a node has not touched, so its step can carry
  // the node deep inside; every trial point then has its nodes moved back to a penetration of at
  // most max(floor, 1.5 times the current deepest).
  double penetration_tolerance = 0.0;
  double penetration_floor = 0.0;
  int max_penalty_raises = 10;
};

class ShellObjective final : public NewtonProblem {
 public:
  ShellObjective(ShellAssembly& assembly, ContactOptions options = {});

  ShellAssembly& assembly() { return assembly_; }
  const ShellAssembly& assembly() const { return assembly_; }
  const ContactOptions& contact_options() const { return options_; }

  Eigen::Index nodes() const override { return assembly_.problem().mesh.positions.cols(); }
  const Eigen::SparseMatrix<double>& pattern() const override { return assembly_.pattern(); }
  EnergyValue linearise(const Eigen::Matrix3Xd& x, Eigen::VectorXd& gradient, Eigen::SparseMatrix<double>& hessian,
                        double& stationarity) override;
  EnergyValue energy(const Eigen::Matrix3Xd& x) const override;
  void to_nodal(Eigen::VectorXd& step) const override;
  double slope(const Eigen::VectorXd& move) const override { return gradient_.dot(move); }
  void make_admissible(Eigen::Matrix3Xd& trial, double fraction) const override;

  // The driver's viscous stabilisation (viscous_stabilisation.hpp) of the load steps from now on:
  // its potential joins the energy, its force the obstacles' reaction.
  void stabilise(const ShellFeStabilisation& options);
  const ViscousStabilisation* stabilisation() const { return stabilisation_ ? &*stabilisation_ : nullptr; }
  // A load step of `step` (in the path's parameter) begins from the converged state x.
  void begin_step(const Eigen::Matrix3Xd& x, double step);
  // The start of a load step from a predicted state: nodes put out of the obstacles (active
  // set), or into the penalty's band (penalty).
  void start_step(Eigen::Matrix3Xd& x) const;
  // After a converged step: false when the solution must be tightened and solved again (the
  // penalty raised because a node is deeper than the tolerance, or the stabilisation's damping
  // lowered under its cap); `failure` says why when it can no longer be.
  bool accept(const Eigen::Matrix3Xd& x, int raises, std::string& failure);
  // Forces of the wall on the obstacles and the deepest penetration at a solution.
  ContactState contact_state(const Eigen::Matrix3Xd& x);
  double contact_seconds() const { return contact_seconds_; }

 private:
  ShellAssembly& assembly_;
  ContactOptions options_;
  ActiveSetContact active_set_;
  std::optional<ViscousStabilisation> stabilisation_;
  Eigen::VectorXd gradient_;  // of the energy at the last linearised state
  double cap_ = 0.0;          // penalty: the line search's penetration cap
  double contact_seconds_ = 0.0;
};

}  // namespace growthuq::fe
