#include "fe/shell_objective.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace growthuq::fe {
namespace {

using Clock = std::chrono::steady_clock;

double magnitude(const EnergyParts& parts) {
  return std::fabs(parts.membrane) + std::fabs(parts.bending) + std::fabs(parts.pressure) +
         std::fabs(parts.contact) + std::fabs(parts.point_loads);
}

double strain(const EnergyParts& parts) { return parts.membrane + parts.bending; }
double stored(const EnergyParts& parts) { return parts.membrane + parts.bending + parts.pressure; }

}  // namespace

ShellObjective::ShellObjective(ShellAssembly& assembly, ContactOptions options)
    : assembly_(assembly), options_(options), active_set_(assembly.problem().fixed, options.band, options.reach) {
  if (options_.method == ContactMethod::active_set) assembly_.loads().penalty.stiffness = 0.0;
}

EnergyValue ShellObjective::linearise(const Eigen::Matrix3Xd& x, Eigen::VectorXd& gradient,
                                      Eigen::SparseMatrix<double>& hessian, double& stationarity) {
  const EnergyParts parts = assembly_.evaluate(x, gradient_, &hessian, &contact_seconds_);
  double viscous = 0.0;
  if (stabilisation_) {
    viscous = stabilisation_->energy(x);
    stabilisation_->add_gradient(x, gradient_);
    stabilisation_->add_hessian(hessian);
  }
  gradient = gradient_;
  const double scale = assembly_.force_scale();
  const Obstacles& obstacles = assembly_.loads().obstacles;
  if (options_.method == ContactMethod::active_set) {
    const auto start = Clock::now();
    stationarity = active_set_.select(obstacles, x, gradient, &hessian) / scale;
    active_set_.reduce(hessian, gradient);
    contact_seconds_ += std::chrono::duration<double>(Clock::now() - start).count();
  } else {
    stationarity = gradient.lpNorm<Eigen::Infinity>() / scale;
    cap_ = options_.penetration_floor > 0
               ? std::max(options_.penetration_floor, 1.5 * assembly_.contact_state(x).max_penetration)
               : 0.0;
  }
  return {parts.total() + viscous, magnitude(parts) + viscous};
}

EnergyValue ShellObjective::energy(const Eigen::Matrix3Xd& x) const {
  const EnergyParts parts = assembly_.energy(x);
  const double viscous = stabilisation_ ? stabilisation_->energy(x) : 0.0;
  return {parts.total() + viscous, magnitude(parts) + viscous};
}

void ShellObjective::stabilise(const ShellFeStabilisation& options) {
  const ShellProblem& problem = assembly_.problem();
  stabilisation_.emplace(options, lumped_masses(problem.mesh, problem.material.thickness), problem.fixed);
}

void ShellObjective::begin_step(const Eigen::Matrix3Xd& x, double step) {
  if (!stabilisation_) return;
  const EnergyParts parts = assembly_.energy(x);
  stabilisation_->begin_step(x, step, strain(parts), stored(parts));
}

void ShellObjective::to_nodal(Eigen::VectorXd& step) const {
  if (options_.method == ContactMethod::active_set) active_set_.to_nodal(step);
}

void ShellObjective::make_admissible(Eigen::Matrix3Xd& trial, double fraction) const {
  if (options_.method == ContactMethod::active_set) {
    active_set_.settle(assembly_.loads().obstacles, trial, fraction == 1.0);
  } else if (cap_ > 0) {
    assembly_.limit_penetration(trial, cap_);
  }
}

void ShellObjective::start_step(Eigen::Matrix3Xd& x) const {
  const Obstacles& obstacles = assembly_.loads().obstacles;
  // Active set: nothing; the first Newton step lifts the nodes the obstacles' move put inside
  // out of them, through the wall's stiffness (a tangent predictor), and is taken whole.
  if (options_.method == ContactMethod::active_set) return;
  // Penalty: otherwise the first Newton steps would fight penalty forces of the whole step's
  // motion, and a node just touching (zero penetration, where the penalty's curvature vanishes)
  // would be invisible to the Newton model: a tube resting on the substrate would be free to
  // swing through it.
  const double margin = std::max(2 * assembly_.loads().penalty.smoothing, options_.band);
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    Eigen::Vector3d p = x.col(v);
    for (std::size_t o = 0; o < obstacles.size(); ++o) {
      const ObstacleGap g = obstacles.gap(o, p);
      if (g.gap < margin && (o >= obstacles.spheres.size() || p != obstacles.spheres[o].centre)) {
        p -= (g.gap + margin) * g.normal;
      }
    }
    for (int k = 0; k < 3; ++k) {
      if (!assembly_.is_fixed(3 * v + k)) x(k, v) = p[k];
    }
  }
}

bool ShellObjective::accept(const Eigen::Matrix3Xd& x, int raises, std::string& failure) {
  const auto stabilised = [&] {
    if (!stabilisation_) return true;
    const EnergyParts parts = assembly_.energy(x);
    return stabilisation_->accept(x, strain(parts), stored(parts));
  };
  if (options_.method == ContactMethod::active_set || options_.penetration_tolerance <= 0) return stabilised();
  const double penetration = assembly_.contact_state(x).max_penetration;
  if (penetration <= options_.penetration_tolerance) return stabilised();
  if (raises >= options_.max_penalty_raises) {
    failure = "penetration " + std::to_string(penetration) + " above tolerance after " + std::to_string(raises) +
              " penalty raises";
    return false;
  }
  // penetration ~ force / stiffness, so the factor aims at half the tolerance.
  assembly_.loads().penalty.stiffness *= std::max(2.0, 2.0 * penetration / options_.penetration_tolerance);
  return false;
}

ContactState ShellObjective::contact_state(const Eigen::Matrix3Xd& x) {
  if (options_.method == ContactMethod::penalty) return assembly_.contact_state(x);
  const Obstacles& obstacles = assembly_.loads().obstacles;
  assembly_.evaluate(x, gradient_, nullptr);
  // The viscous force resists the probe as the wall's own does: the reaction includes it.
  if (stabilisation_) stabilisation_->add_gradient(x, gradient_);
  active_set_.select(obstacles, x, gradient_);
  const ContactReaction reaction = active_set_.reaction(obstacles, x);
  ContactState state;
  const std::size_t spheres = obstacles.spheres.size();
  state.sphere_force.assign(reaction.force.begin(), reaction.force.begin() + static_cast<std::ptrdiff_t>(spheres));
  state.plane_force.assign(reaction.force.begin() + static_cast<std::ptrdiff_t>(spheres), reaction.force.end());
  state.sphere_contacts.assign(reaction.contacts.begin(), reaction.contacts.begin() + static_cast<std::ptrdiff_t>(spheres));
  state.sphere_penetration.assign(reaction.penetration.begin(), reaction.penetration.begin() + static_cast<std::ptrdiff_t>(spheres));
  state.max_penetration = reaction.max_penetration;
  return state;
}

}  // namespace growthuq::fe
