#include "fe/viscous_stabilisation.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "fe/mesh.hpp"

namespace growthuq::fe {
namespace {

// A step the cap rejects is solved again with c scaled to leave this share of the room under
// the cap to it (its dissipation is nearly linear in c), at most this many times before the
// step is solved undamped.
constexpr double cap_margin = 0.9;
constexpr int max_redos = 5;

}  // namespace

Eigen::VectorXd lumped_masses(const TriangleMesh& mesh, double thickness) {
  Eigen::VectorXd masses = Eigen::VectorXd::Zero(mesh.positions.cols());
  for (const auto& face : mesh.faces) {
    const Eigen::Vector3d a = mesh.positions.col(face[0]), b = mesh.positions.col(face[1]), c = mesh.positions.col(face[2]);
    const double third = (b - a).cross(c - a).norm() / 6.0 * thickness;
    for (int v : face) masses[v] += third;
  }
  return masses;
}

ViscousStabilisation::ViscousStabilisation(ShellFeStabilisation options, Eigen::VectorXd masses, std::vector<char> fixed)
    : options_(options), masses_(std::move(masses)), fixed_(std::move(fixed)) {}

void ViscousStabilisation::begin_step(const Eigen::Matrix3Xd& converged, double step, double strain_energy,
                                      double stored_energy) {
  if (!started_) start_stored_ = stored_energy;
  started_ = true;
  previous_ = converged;
  step_ = step;
  previous_strain_ = strain_energy;
  previous_stored_ = stored_energy;
  step_damping_ = damping_;
}

double ViscousStabilisation::moved_mass_norm(const Eigen::Matrix3Xd& x) const {
  return ((x - previous_).colwise().squaredNorm().transpose().array() * masses_.array()).sum();
}

double ViscousStabilisation::energy(const Eigen::Matrix3Xd& x) const {
  if (step_damping_ == 0.0) return 0.0;
  return 0.5 * step_damping_ / step_ * moved_mass_norm(x);
}

// Fixed dofs never move (x = x^n there), so their gradient entries stay zero.
void ViscousStabilisation::add_gradient(const Eigen::Matrix3Xd& x, Eigen::VectorXd& gradient) const {
  if (step_damping_ == 0.0) return;
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    gradient.segment<3>(3 * v) += step_damping_ / step_ * masses_[v] * (x.col(v) - previous_.col(v));
  }
}

void ViscousStabilisation::add_hessian(Eigen::SparseMatrix<double>& hessian) const {
  if (step_damping_ == 0.0) return;
  for (Eigen::Index d = 0; d < hessian.rows(); ++d) {
    if (!fixed_.empty() && fixed_[static_cast<std::size_t>(d)]) continue;
    hessian.coeffRef(d, d) += step_damping_ / step_ * masses_[d / 3];
  }
}

double ViscousStabilisation::reference_energy(double strain_energy, double stored_energy) const {
  return options_.energy == ShellFeStabilisationEnergy::model ? strain_energy : stored_energy - start_stored_;
}

bool ViscousStabilisation::accept(const Eigen::Matrix3Xd& x, double strain_energy, double stored_energy) {
  const double moved = moved_mass_norm(x);
  if (!calibrated_) {
    // (2) with T = 1: the first increment's strain energy extrapolated linearly over the step
    // (the model's: its value at the step's start plus the increment's change over 1/Delta t_1
    // increments; the step's: the change alone, so extrapolated).
    calibrated_ = true;
    const double model = previous_strain_ + (strain_energy - previous_strain_) / step_;
    const double extrapolated = options_.energy == ShellFeStabilisationEnergy::model
                                    ? model
                                    : (stored_energy - previous_stored_) / step_;
    // The increment itself stays undamped (its state, and the reaction read from it, are
    // those of the undamped equilibrium): c applies from the next step on.
    if (moved > 0 && extrapolated > 0) damping_ = options_.fraction * extrapolated * step_ * step_ / moved;
    return true;
  }
  const double step_dissipation = step_damping_ / step_ * moved;
  const double cap = options_.ratio * reference_energy(strain_energy, stored_energy);
  if (options_.ratio > 0 && step_damping_ > 0 && dissipated_ + step_dissipation > cap) {
    const double room = cap - dissipated_;
    damping_ = redos_ < max_redos && room > 0 ? step_damping_ * cap_margin * room / step_dissipation : 0.0;
    step_damping_ = damping_;
    ++lowerings_;
    ++redos_;
    return false;
  }
  dissipated_ += step_dissipation;
  redos_ = 0;
  return true;
}

}  // namespace growthuq::fe
