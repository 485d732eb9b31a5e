#include "fe/active_set_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <limits>

namespace growthuq::fe {
namespace {

// A node touches its obstacle when its gap is below this (lengths are O(1) in units of d0, so
// this is far above the gap's rounding, 1e-16, and far below any length of the model).
constexpr double touching_gap = 1e-12;

// An orthonormal frame whose column `slot` is the unit normal m (zero along fixed axes), with
// every fixed axis kept as its own column, so that fixed dofs stay fixed dofs after rotation.
Eigen::Matrix3d frame_for(const Eigen::Vector3d& m, const std::array<bool, 3>& fixed, int& slot) {
  std::array<int, 3> free{};
  int free_count = 0;
  for (int k = 0; k < 3; ++k) {
    if (!fixed[static_cast<std::size_t>(k)]) free[static_cast<std::size_t>(free_count++)] = k;
  }
  slot = free[0];
  for (int f = 1; f < free_count; ++f) {
    if (std::fabs(m[free[static_cast<std::size_t>(f)]]) > std::fabs(m[slot])) slot = free[static_cast<std::size_t>(f)];
  }
  Eigen::Matrix3d q = Eigen::Matrix3d::Identity();
  if (free_count == 1) return q;
  q.col(slot) = m;
  if (free_count == 2) {
    const int held = fixed[0] ? 0 : fixed[1] ? 1 : 2;
    const int other = free[0] == slot ? free[1] : free[0];
    q.col(other) = Eigen::Vector3d::Unit(held).cross(m).normalized();
    return q;
  }
  const int k1 = (slot + 1) % 3, k2 = (slot + 2) % 3;
  const Eigen::Vector3d t1 = (Eigen::Vector3d::Unit(k1) - m[k1] * m).normalized();
  q.col(k1) = t1;
  q.col(k2) = m.cross(t1);
  return q;
}

}  // namespace

ActiveSetContact::ActiveSetContact(std::vector<char> fixed, double band, double reach)
    : fixed_(std::move(fixed)), band_(std::max(band, touching_gap)), reach_(reach) {}

double ActiveSetContact::select(const Obstacles& obstacles, const Eigen::Matrix3Xd& x, const Eigen::VectorXd& g,
                                const Eigen::SparseMatrix<double>* hessian) {
  active_.clear();
  // Nodes further than this from every obstacle are not examined (a Newton step moves no node
  // further than its cap); the band alone when no Hessian is given.
  const double reach = hessian ? std::max(band_, reach_) : band_;
  active_of_node_.assign(static_cast<std::size_t>(x.cols()), -1);
  double largest = 0.0;
  bool inside_any = false;
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    Eigen::Vector3d residual = g.segment<3>(3 * v);
    ObstacleGap gap;
    const int obstacle = obstacles.empty() ? -1 : obstacles.nearest(x.col(v), gap);
    if (obstacle >= 0 && gap.gap <= reach) {
      // The multiplier of the free directions: the obstacle's force lambda n balances the free
      // components of the gradient, so lambda = m.g / m.m with m = n less its fixed components.
      std::array<bool, 3> held{};
      Eigen::Vector3d m = gap.normal;
      for (int k = 0; k < 3; ++k) {
        held[static_cast<std::size_t>(k)] = fixed(3 * v + k);
        if (held[static_cast<std::size_t>(k)]) m[k] = 0.0;
      }
      const double mm = m.squaredNorm();
      const double multiplier = mm > 1e-12 ? m.dot(residual) / mm : 0.0;
      // Held when on or near the surface (the band), or when the wall pushes the node towards
      // the obstacle further than its gap: the semi-smooth Newton rule lambda - c gap > 0 with
      // c the node's own normal stiffness n^T K n (Hintermueller, Ito and Kunisch 2003), so the
      // Newton model sees a contact before the node has touched.
      double stiffness = 0.0;
      if (hessian && multiplier > 0 && gap.gap > band_) {
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) {
            const Eigen::Index r = 3 * v + std::max(i, j), c = 3 * v + std::min(i, j);
            stiffness += m[i] * m[j] * hessian->coeff(r, c);
          }
        }
        stiffness /= mm;
      }
      const bool near = gap.gap <= band_ || (stiffness > 0 && multiplier > stiffness * gap.gap);
      // A node inside an obstacle (a load step's start: the probe moved) is always held, and
      // lifted out by the step: Newton's model carries the obstacle's move into the wall.
      const bool inside = gap.gap < -touching_gap && mm > 1e-12;
      inside_any = inside_any || inside;
      if ((multiplier > 0 && near) || inside) {
        ActiveContact contact;
        contact.node = static_cast<int>(v);
        contact.obstacle = obstacle;
        contact.gap = gap;
        contact.multiplier = std::max(multiplier, 0.0);
        contact.frame = frame_for(m / std::sqrt(mm), held, contact.slot);
        active_of_node_[static_cast<std::size_t>(v)] = static_cast<int>(active_.size());
        active_.push_back(contact);
        // Complementarity: only a node on the surface may carry a normal force; one still in
        // the band keeps its whole gradient in the residual until the step has lifted it on.
        if (std::fabs(gap.gap) <= touching_gap) residual -= multiplier * m;
      }
    }
    largest = std::max(largest, residual.lpNorm<Eigen::Infinity>());
  }
  // A state with a node inside an obstacle is no solution, whatever its gradient.
  if (inside_any) largest = std::numeric_limits<double>::infinity();
  return largest;
}

void ActiveSetContact::reduce(Eigen::SparseMatrix<double>& hessian, Eigen::VectorXd& gradient) const {
  if (active_.empty()) return;
  const Eigen::Index n = hessian.rows();
  const int* outer = hessian.outerIndexPtr();
  const int* inner = hessian.innerIndexPtr();
  double* values = hessian.valuePtr();
  auto active_at = [&](Eigen::Index node) { return active_of_node_[static_cast<std::size_t>(node)]; };
  // The 3 x 3 blocks (a, b), a >= b, that touch a held node, gathered from the lower triangle.
  struct Block {
    Eigen::Matrix3d value = Eigen::Matrix3d::Zero();
    std::array<int, 9> position{-1, -1, -1, -1, -1, -1, -1, -1, -1};
  };
  std::unordered_map<long long, Block> blocks;
  const long long nodes = n / 3;
  for (Eigen::Index c = 0; c < n; ++c) {
    const Eigen::Index b = c / 3;
    for (int p = outer[c]; p < outer[c + 1]; ++p) {
      const Eigen::Index a = inner[p] / 3;
      if (active_at(a) < 0 && active_at(b) < 0) continue;
      Block& block = blocks[static_cast<long long>(a) * nodes + b];
      const auto i = static_cast<int>(inner[p] % 3), j = static_cast<int>(c % 3);
      block.value(i, j) = values[p];
      block.position[static_cast<std::size_t>(3 * i + j)] = p;
    }
  }
  for (auto& [key, block] : blocks) {
    const auto a = static_cast<Eigen::Index>(key / nodes), b = static_cast<Eigen::Index>(key % nodes);
    if (a == b) {
      block.value = block.value.selfadjointView<Eigen::Lower>();
      if (const int k = active_at(a); k >= 0) {
        // The Lagrangian's Hessian E'' - lambda gap'' on the held node (Wriggers 2006, ch. 5):
        // sliding along a curved obstacle lowers the energy at second order.
        const ActiveContact& contact = active_[static_cast<std::size_t>(k)];
        const Eigen::Vector3d& nrm = contact.gap.normal;
        Eigen::Matrix3d term = -contact.multiplier * contact.gap.curvature *
                               (Eigen::Matrix3d::Identity() - nrm * nrm.transpose());
        for (int d = 0; d < 3; ++d) {
          if (fixed(3 * a + d)) term.row(d).setZero(), term.col(d).setZero();
        }
        block.value += term;
      }
    }
    const int ka = active_at(a), kb = active_at(b);
    const Eigen::Matrix3d qa = ka >= 0 ? active_[static_cast<std::size_t>(ka)].frame : Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d qb = kb >= 0 ? active_[static_cast<std::size_t>(kb)].frame : Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d rotated = qa.transpose() * block.value * qb;
    for (int e = 0; e < 9; ++e) {
      const int p = block.position[static_cast<std::size_t>(e)];
      if (p >= 0) values[p] = rotated(e / 3, e % 3);
    }
  }
  // Gradient to the rotated frame; each held normal prescribed as u_n = -gap (the node lifted
  // onto the surface), its coupling moved to the right-hand side, its row and column those of
  // the identity.
  Eigen::VectorXd lift = Eigen::VectorXd::Zero(n);
  std::vector<char> held(static_cast<std::size_t>(n), 0);
  for (const ActiveContact& contact : active_) {
    gradient.segment<3>(3 * contact.node) = contact.frame.transpose() * gradient.segment<3>(3 * contact.node);
    const Eigen::Index dof = 3 * contact.node + contact.slot;
    lift[dof] = -contact.gap.gap;
    held[static_cast<std::size_t>(dof)] = 1;
  }
  const Eigen::VectorXd coupling = hessian.selfadjointView<Eigen::Lower>() * lift;
  for (Eigen::Index d = 0; d < n; ++d) {
    if (held[static_cast<std::size_t>(d)]) gradient[d] = -lift[d];
    else if (!fixed(d)) gradient[d] += coupling[d];
  }
  for (Eigen::Index c = 0; c < n; ++c) {
    for (int p = outer[c]; p < outer[c + 1]; ++p) {
      if (held[static_cast<std::size_t>(c)] || held[static_cast<std::size_t>(inner[p])]) values[p] = inner[p] == c ? 1.0 : 0.0;
    }
  }
}

void ActiveSetContact::to_nodal(Eigen::VectorXd& u) const {
  for (const ActiveContact& contact : active_) {
    u.segment<3>(3 * contact.node) = contact.frame * u.segment<3>(3 * contact.node);
  }
}

void ActiveSetContact::settle(const Obstacles& obstacles, Eigen::Matrix3Xd& x, bool lifted) const {
  // A tangential step leaves a held node off a curved surface by t^2 / (2 r): put it back on,
  // along its constrained direction (its free directions only), so it stays in contact exactly.
  // Newton's iteration on the gap along that line converges quadratically; three passes take
  // the gap from O(t^2 / r) to rounding.
  // A node the step lifts onto the surface is settled for the whole step only: on a shortened
  // step it moves with the step's length, so that a short enough step is always a short move
  // (the line search's guarantee of a decrease).
  for (const ActiveContact& contact : active_) {
    if (!lifted && std::fabs(contact.gap.gap) > touching_gap) continue;
    const Eigen::Vector3d direction = contact.frame.col(contact.slot);
    for (int pass = 0; pass < 3; ++pass) {
      const ObstacleGap g = obstacles.gap(static_cast<std::size_t>(contact.obstacle), x.col(contact.node));
      const double along = direction.dot(g.normal);
      if (along <= 0.5 || std::fabs(g.gap) <= touching_gap) break;
      x.col(contact.node) -= (g.gap / along) * direction;
    }
  }
  project(obstacles, x);
}

void ActiveSetContact::project(const Obstacles& obstacles, Eigen::Matrix3Xd& x) const {
  if (obstacles.empty()) return;
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    const Eigen::Vector3d p = obstacles.limited(x.col(v), 0.0);
    if (p == x.col(v)) continue;
    for (int k = 0; k < 3; ++k) {
      if (!fixed(3 * v + k)) x(k, v) = p[k];
    }
  }
}

ContactReaction ActiveSetContact::reaction(const Obstacles& obstacles, const Eigen::Matrix3Xd& x) const {
  ContactReaction r;
  r.force.assign(obstacles.size(), Eigen::Vector3d::Zero());
  r.contacts.assign(obstacles.size(), 0);
  r.penetration.assign(obstacles.size(), 0.0);
  for (const ActiveContact& contact : active_) {
    // The obstacle pushes the node with lambda n; the wall pushes the obstacle back.
    r.force[static_cast<std::size_t>(contact.obstacle)] -= contact.multiplier * contact.gap.normal;
    ++r.contacts[static_cast<std::size_t>(contact.obstacle)];
  }
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    for (std::size_t o = 0; o < obstacles.size(); ++o) {
      r.penetration[o] = std::max(r.penetration[o], -obstacles.gap(o, x.col(v)).gap);
    }
  }
  for (double p : r.penetration) r.max_penetration = std::max(r.max_penetration, p);
  return r;
}

}  // namespace growthuq::fe
