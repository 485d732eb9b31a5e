#include "fe/assembly.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <stdexcept>

#include "fe/bending.hpp"
#include "fe/pressure.hpp"
#include "growthuq/core/error.hpp"

namespace growthuq::fe {
namespace {

using Clock = std::chrono::steady_clock;

Eigen::Matrix<double, 18, 1> stencil_state(const BendingStencil& stencil, const Eigen::Matrix3Xd& x) {
  Eigen::Matrix<double, 18, 1> s = Eigen::Matrix<double, 18, 1>::Zero();
  for (int k = 0; k < 6; ++k) {
    const int v = stencil.vertices[static_cast<std::size_t>(k)];
    if (v >= 0) s.segment<3>(3 * k) = x.col(v);
  }
  return s;
}

Eigen::Matrix<double, 9, 1> face_state(const std::array<int, 3>& f, const Eigen::Matrix3Xd& x) {
  Eigen::Matrix<double, 9, 1> s;
  for (int k = 0; k < 3; ++k) s.segment<3>(3 * k) = x.col(f[static_cast<std::size_t>(k)]);
  return s;
}

}  // namespace

std::vector<char> mirror_and_end_ring_fixed(const TriangleMesh& mesh, bool mirror_y0, bool pin_z0) {
  std::vector<char> fixed(static_cast<std::size_t>(3 * mesh.positions.cols()), 0);
  for (Eigen::Index v = 0; v < mesh.positions.cols(); ++v) {
    const auto base = static_cast<std::size_t>(3 * v);
    if (mirror_y0 && std::fabs(mesh.positions(1, v)) <= 1e-12) fixed[base + 1] = 1;
    if (pin_z0 && std::fabs(mesh.positions(2, v)) <= 1e-12) fixed[base] = fixed[base + 1] = fixed[base + 2] = 1;
  }
  return fixed;
}

ShellAssembly::ShellAssembly(ShellProblem problem) : problem_(std::move(problem)) {
  const TriangleMesh& mesh = problem_.mesh;
  const Eigen::Index nodes = mesh.positions.cols();
  if (!problem_.fixed.empty() && problem_.fixed.size() != static_cast<std::size_t>(3 * nodes)) {
    throw InputError("shell problem", "fixed: expected 3 flags per node");
  }
  topology_ = build_topology(mesh, problem_.mirror_y0);
  bending_thickness_ = problem_.bending_thickness > 0 ? problem_.bending_thickness : problem_.material.thickness;
  membrane_.reserve(mesh.faces.size());
  for (const auto& f : mesh.faces) {
    membrane_.push_back(make_membrane_reference(mesh.positions.col(f[0]), mesh.positions.col(f[1]),
                                                mesh.positions.col(f[2])));
  }
  if (problem_.bending) {
    bending_.reserve(mesh.faces.size());
    for (const auto& stencil : topology_.stencils) {
      bending_.push_back(make_bending_reference(stencil, stencil_state(stencil, mesh.positions)));
    }
  }
  // Node adjacency (a >= b) from the stencils (bending) or the faces (membrane alone).
  std::vector<std::vector<int>> below(static_cast<std::size_t>(nodes));
  const int span = problem_.bending ? 6 : 3;
  for (const auto& stencil : topology_.stencils) {
    for (int a = 0; a < span; ++a) {
      for (int b = 0; b < span; ++b) {
        const int va = stencil.vertices[static_cast<std::size_t>(a)], vb = stencil.vertices[static_cast<std::size_t>(b)];
        if (va >= 0 && vb >= 0 && va > vb) below[static_cast<std::size_t>(vb)].push_back(va);
      }
    }
  }
  for (auto& list : below) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  // Lower-triangle layout, column 3b + j: the diagonal block's rows 3b + i (i >= j), then three
  // rows for each neighbour a > b in increasing order.
  const Eigen::Index n = 3 * nodes;
  std::vector<int> column_start(static_cast<std::size_t>(n + 1), 0);
  for (Eigen::Index b = 0; b < nodes; ++b) {
    const int m = static_cast<int>(below[static_cast<std::size_t>(b)].size());
    for (int j = 0; j < 3; ++j) {
      const auto c = static_cast<std::size_t>(3 * b + j);
      column_start[c + 1] = column_start[c] + (3 - j) + 3 * m;
    }
  }
  const int nnz = column_start.back();
  pattern_.resize(n, n);
  pattern_.resizeNonZeros(nnz);
  std::copy(column_start.begin(), column_start.end(), pattern_.outerIndexPtr());
  int* rows = pattern_.innerIndexPtr();
  for (Eigen::Index b = 0; b < nodes; ++b) {
    for (int j = 0; j < 3; ++j) {
      int p = column_start[static_cast<std::size_t>(3 * b + j)];
      for (int i = j; i < 3; ++i) rows[p++] = static_cast<int>(3 * b + i);
      for (int a : below[static_cast<std::size_t>(b)]) {
        for (int i = 0; i < 3; ++i) rows[p++] = 3 * a + i;
      }
    }
  }
  std::fill(pattern_.valuePtr(), pattern_.valuePtr() + nnz, 0.0);
  column_start_ = column_start;
  // Per face, the rank of each vertex pair (a >= b) in b's list: 0 the diagonal block.
  face_rank_.resize(mesh.faces.size());
  for (std::size_t f = 0; f < topology_.stencils.size(); ++f) {
    const auto& vertices = topology_.stencils[f].vertices;
    for (int a = 0; a < 6; ++a) {
      for (int b = 0; b < 6; ++b) {
        int rank = -1;
        const int va = vertices[static_cast<std::size_t>(a)], vb = vertices[static_cast<std::size_t>(b)];
        if ((a < span && b < span) && va >= 0 && vb >= 0 && va >= vb) {
          if (va == vb) rank = 0;
          else {
            const auto& list = below[static_cast<std::size_t>(vb)];
            rank = 1 + static_cast<int>(std::lower_bound(list.begin(), list.end(), va) - list.begin());
          }
        }
        face_rank_[f][static_cast<std::size_t>(6 * a + b)] = rank;
      }
    }
  }
  // Fixed dofs: their rows and columns zeroed, their diagonal 1.
  for (Eigen::Index c = 0; c < n; ++c) {
    for (int p = column_start[static_cast<std::size_t>(c)]; p < column_start[static_cast<std::size_t>(c + 1)]; ++p) {
      const bool row_fixed = is_fixed(rows[p]), column_fixed = is_fixed(c);
      if (row_fixed || column_fixed) {
        if (rows[p] == c) fixed_diagonal_.push_back(p);
        else fixed_zero_.push_back(p);
      }
    }
  }
  const EdgeLengthRange range = edge_length_range(mesh);
  shortest_edge_ = range.shortest;
  force_scale_ = problem_.material.young * problem_.material.thickness * range.shortest;
}

int ShellAssembly::offset(int a, int b, int rank, int i, int j) const {
  (void)a;
  const int start = column_start_[static_cast<std::size_t>(3 * b + j)];
  return rank == 0 ? start + (i - j) : start + (3 - j) + 3 * (rank - 1) + i;
}

template <int N>
void ShellAssembly::scatter(std::size_t face, const Eigen::Matrix<double, 3 * N, 3 * N>& local,
                            double* values) const {
  const auto& vertices = topology_.stencils[face].vertices;
  const auto& ranks = face_rank_[face];
  for (int a = 0; a < N; ++a) {
    for (int b = 0; b < N; ++b) {
      const int rank = ranks[static_cast<std::size_t>(6 * a + b)];
      if (rank < 0) continue;
      const int va = vertices[static_cast<std::size_t>(a)], vb = vertices[static_cast<std::size_t>(b)];
      for (int j = 0; j < 3; ++j) {
        for (int i = rank == 0 ? j : 0; i < 3; ++i) {
          values[offset(va, vb, rank, i, j)] += local(3 * a + i, 3 * b + j);
        }
      }
    }
  }
}

EnergyParts ShellAssembly::energy(const Eigen::Matrix3Xd& x) const {
  return evaluate_impl(x, nullptr, nullptr, nullptr);
}

EnergyParts ShellAssembly::evaluate(const Eigen::Matrix3Xd& x, Eigen::VectorXd& gradient,
                                    Eigen::SparseMatrix<double>* hessian, double* contact_seconds) const {
  return evaluate_impl(x, &gradient, hessian, contact_seconds);
}

EnergyParts ShellAssembly::evaluate_impl(const Eigen::Matrix3Xd& x, Eigen::VectorXd* gradient,
                                         Eigen::SparseMatrix<double>* hessian, double* contact_seconds) const {
  const TriangleMesh& mesh = problem_.mesh;
  const ShellLoads& loads = problem_.loads;
  EnergyParts parts;
  double* values = nullptr;
  if (gradient) gradient->setZero(dofs());
  if (hessian) {
    if (hessian->nonZeros() != pattern_.nonZeros() || hessian->rows() != pattern_.rows()) *hessian = pattern_;
    values = hessian->valuePtr();
    std::fill(values, values + hessian->nonZeros(), 0.0);
  }
  Eigen::Matrix<double, 9, 1> g9;
  Eigen::Matrix<double, 9, 9> h9;
  Eigen::Matrix<double, 18, 1> g18;
  Eigen::Matrix<double, 18, 18> h18;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& face = mesh.faces[f];
    const Eigen::Matrix<double, 9, 1> xf = face_state(face, x);
    parts.membrane += membrane_energy(problem_.material, membrane_[f], xf, gradient ? &g9 : nullptr,
                                      values ? &h9 : nullptr);
    if (gradient) {
      for (int k = 0; k < 3; ++k) gradient->segment<3>(3 * face[static_cast<std::size_t>(k)]) += g9.segment<3>(3 * k);
    }
    if (values) scatter<3>(f, h9, values);
    if (loads.pressure != 0.0) {
      parts.pressure -= loads.pressure * face_volume(xf, gradient ? &g9 : nullptr, values ? &h9 : nullptr);
      if (gradient) {
        for (int k = 0; k < 3; ++k) {
          gradient->segment<3>(3 * face[static_cast<std::size_t>(k)]) -= loads.pressure * g9.segment<3>(3 * k);
        }
      }
      if (values) {
        h9 *= -loads.pressure;
        scatter<3>(f, h9, values);
      }
    }
    if (problem_.bending) {
      const BendingStencil& stencil = topology_.stencils[f];
      parts.bending += bending_energy(problem_.material, bending_thickness_, stencil, bending_[f],
                                      stencil_state(stencil, x), gradient ? &g18 : nullptr,
                                      values ? &h18 : nullptr);
      if (gradient) {
        for (int k = 0; k < 6; ++k) {
          const int v = stencil.vertices[static_cast<std::size_t>(k)];
          if (v >= 0) gradient->segment<3>(3 * v) += g18.segment<3>(3 * k);
        }
      }
      if (values) scatter<6>(f, h18, values);
    }
  }
  for (const PointLoad& load : loads.point_loads) {
    parts.point_loads -= load.force.dot(x.col(load.node));
    if (gradient) gradient->segment<3>(3 * load.node) -= load.force;
  }
  const auto contact_start = Clock::now();
  if (!loads.obstacles.empty() && loads.penalty.stiffness > 0) {
    Eigen::Vector3d g3;
    Eigen::Matrix3d h3;
    for (Eigen::Index v = 0; v < x.cols(); ++v) {
      const Eigen::Vector3d xv = x.col(v);
      for (std::size_t o = 0; o < loads.obstacles.size(); ++o) {
        const ObstacleGap gap = loads.obstacles.gap(o, xv);
        if (gap.gap >= 0) continue;
        if (o < loads.obstacles.spheres.size() && xv == loads.obstacles.spheres[o].centre) continue;
        const double e = obstacle_contact(gap, loads.penalty, gradient ? &g3 : nullptr, values ? &h3 : nullptr);
        parts.contact += e;
        if (gradient) gradient->segment<3>(3 * v) += g3;
        if (values) {
          for (int j = 0; j < 3; ++j) {
            for (int i = j; i < 3; ++i) values[offset(static_cast<int>(v), static_cast<int>(v), 0, i, j)] += h3(i, j);
          }
        }
      }
    }
  }
  if (contact_seconds) *contact_seconds += std::chrono::duration<double>(Clock::now() - contact_start).count();
  if (gradient && !problem_.fixed.empty()) {
    for (Eigen::Index d = 0; d < dofs(); ++d) {
      if (problem_.fixed[static_cast<std::size_t>(d)]) (*gradient)[d] = 0.0;
    }
  }
  if (values) {
    for (int p : fixed_zero_) values[p] = 0.0;
    for (int p : fixed_diagonal_) values[p] = 1.0;
  }
  return parts;
}

int ShellAssembly::limit_penetration(Eigen::Matrix3Xd& x, double cap) const {
  int moved = 0;
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    const Eigen::Vector3d p = problem_.loads.obstacles.limited(x.col(v), cap);
    if (p == x.col(v)) continue;
    ++moved;
    for (int k = 0; k < 3; ++k) {
      if (!is_fixed(3 * v + k)) x(k, v) = p[k];
    }
  }
  return moved;
}

ContactState ShellAssembly::contact_state(const Eigen::Matrix3Xd& x) const {
  const ShellLoads& loads = problem_.loads;
  ContactState state;
  state.sphere_force.assign(loads.obstacles.spheres.size(), Eigen::Vector3d::Zero());
  state.plane_force.assign(loads.obstacles.planes.size(), Eigen::Vector3d::Zero());
  state.sphere_penetration.assign(loads.obstacles.spheres.size(), 0.0);
  state.sphere_contacts.assign(loads.obstacles.spheres.size(), 0);
  Eigen::Vector3d g;
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    for (std::size_t s = 0; s < loads.obstacles.spheres.size(); ++s) {
      double depth = 0.0;
      if (sphere_contact(loads.obstacles.spheres[s], loads.penalty, x.col(v), &g, nullptr, &depth) > 0 || depth > 0) {
        // The node feels -g; the sphere feels the opposite.
        state.sphere_force[s] += g;
        if (depth > 0) ++state.sphere_contacts[s];
        state.sphere_penetration[s] = std::max(state.sphere_penetration[s], depth);
        state.max_penetration = std::max(state.max_penetration, depth);
      }
    }
    for (std::size_t p = 0; p < loads.obstacles.planes.size(); ++p) {
      double depth = 0.0;
      plane_contact(loads.obstacles.planes[p], loads.penalty, x.col(v), &g, nullptr, &depth);
      if (depth > 0) {
        state.plane_force[p] += g;
        state.max_penetration = std::max(state.max_penetration, depth);
      }
    }
  }
  return state;
}

}  // namespace growthuq::fe
