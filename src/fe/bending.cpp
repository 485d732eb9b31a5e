// Quadratic-patch Kirchhoff-Love bending element (see bending.hpp for the formulation).
//
// Derivatives. With p_k the six effective stencil points, e1 = p1 - p0, e2 = p2 - p0,
// m = e1 x e2, r = |m|, n = m / r, g_ab = sum_k fit(ab, k) p_k and v = g . n - II0:
//   dv/dp_k = fit(k) n + [k < 3] (dm/dp_k)^T (g - (g.n) n) / r,
//   dm/dp0 = [e2 - e1]x, dm/dp1 = -[e2]x, dm/dp2 = [e1]x.
// The Hessian of E = A/2 v^T D v is A J^T D J plus sum_ab sigma_ab d2v_ab (sigma = A D v), with
// d2(g.n) = fit (x) dn + its transpose (n depends on p0..p2 only) + g . d2n, and for a fixed G
//   d2(G . m/|m|)/dm2 = [ -(G n^T + n G^T) - (G.n) I + 3 (G.n) n n^T ] / r^2,
// the second derivative of m = e1 x e2 contracted with U: U . (a x b) = -a^T [U]x b.
#include "fe/bending.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "growthuq/core/error.hpp"

namespace growthuq::fe {

namespace {

using Vec18 = Eigen::Matrix<double, 18, 1>;
using Mat18 = Eigen::Matrix<double, 18, 18>;
using Points = std::array<Eigen::Vector3d, 6>;

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d m;
  m << 0.0, -a(2), a(1), a(2), 0.0, -a(0), -a(1), a(0), 0.0;
  return m;
}

// Reflection in the mirror plane y = 0.
Eigen::Vector3d reflect(const Eigen::Vector3d& a) { return {a(0), -a(1), a(2)}; }

// The six points the interpolant uses: the face, then each edge's neighbour vertex (interior),
// the mirror image of the opposite vertex (mirror) or the parallelogram point vj + vk - vi (free;
// an affine placeholder whose contribution the condensation removes).
Points effective_points(const BendingStencil& stencil, const Vec18& x) {
  Points p;
  for (int k = 0; k < 6; ++k) p[k] = x.segment<3>(3 * k);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (stencil.edges[i] == EdgeKind::mirror) p[3 + i] = reflect(p[i]);
    if (stencil.edges[i] == EdgeKind::free) p[3 + i] = p[j] + p[k] - p[i];
  }
  return p;
}

// The derivatives with respect to the effective points p, carried back to the stencil's dofs
// x (p = T x, so g_x = T^T g_p and H_x = T^T H_p T) block by block: the slot 3 + i of a mirror
// edge is R x_i (R = diag(1, -1, 1)), that of a free edge x_j + x_k - x_i; the slot itself then
// carries nothing.
struct Source {
  int vertex;
  double sign;  // the source's matrix is sign * I, or R for a mirror edge
};

void carry_back(const BendingStencil& stencil, Vec18* gradient, Mat18* hessian) {
  const Eigen::Array3d mirror(1.0, -1.0, 1.0);
  for (int i = 0; i < 3; ++i) {
    if (stencil.edges[i] == EdgeKind::interior) continue;
    const int slot = 9 + 3 * i;
    const bool is_mirror = stencil.edges[i] == EdgeKind::mirror;
    const std::array<Source, 3> sources = {Source{i, is_mirror ? 1.0 : -1.0}, Source{(i + 1) % 3, 1.0},
                                           Source{(i + 2) % 3, 1.0}};
    const int count = is_mirror ? 1 : 3;
    if (gradient != nullptr) {
      for (int c = 0; c < count; ++c) {
        const Eigen::Vector3d share = gradient->segment<3>(slot);
        gradient->segment<3>(3 * sources[c].vertex) +=
            is_mirror ? Eigen::Vector3d(mirror * share.array()) : Eigen::Vector3d(sources[c].sign * share);
      }
      gradient->segment<3>(slot).setZero();
    }
    if (hessian != nullptr) {
      // Columns first (every row, the slot's own included), then rows; then clear the slot.
      for (int c = 0; c < count; ++c) {
        const Eigen::Matrix<double, 18, 3> column = hessian->block<18, 3>(0, slot);
        hessian->block<18, 3>(0, 3 * sources[c].vertex) +=
            is_mirror ? Eigen::Matrix<double, 18, 3>(column * mirror.matrix().asDiagonal())
                      : Eigen::Matrix<double, 18, 3>(sources[c].sign * column);
      }
      for (int c = 0; c < count; ++c) {
        const Eigen::Matrix<double, 3, 18> row = hessian->block<3, 18>(slot, 0);
        hessian->block<3, 18>(3 * sources[c].vertex, 0) +=
            is_mirror ? Eigen::Matrix<double, 3, 18>(mirror.matrix().asDiagonal() * row)
                      : Eigen::Matrix<double, 3, 18>(sources[c].sign * row);
      }
      hessian->block<18, 3>(0, slot).setZero();
      hessian->block<3, 18>(slot, 0).setZero();
    }
  }
}

// Second fundamental form (11, 22, 12) of the interpolant with the face normal.
Eigen::Vector3d second_form(const Eigen::Matrix<double, 3, 6>& fit, const Points& p) {
  const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
  Eigen::Vector3d form;
  for (int m = 0; m < 3; ++m) {
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for (int k = 0; k < 6; ++k) g += fit(m, k) * p[k];
    form(m) = g.dot(n);
  }
  return form;
}

// Koiter's quadratic form on (M11, M22, M12) over B, condensed over the free directions.
Eigen::Matrix3d bending_form(double nu, const BendingReference& reference) {
  Eigen::Matrix3d d;
  d << 1.0, nu, 0.0, nu, 1.0, 0.0, 0.0, 0.0, 2.0 * (1.0 - nu);
  for (int f = 0; f < reference.free_count; ++f) {
    const Eigen::Vector3d dq = d * reference.free_directions[f];
    const double qdq = reference.free_directions[f].dot(dq);
    if (qdq > 1e-14 * d.trace() * reference.free_directions[f].squaredNorm()) {
      d -= dq * dq.transpose() / qdq;
    }
  }
  return d;
}

}  // namespace

BendingReference make_bending_reference(const BendingStencil& stencil, const Vec18& X) {
  const Points p = effective_points(stencil, X);
  const Eigen::Vector3d e1 = p[1] - p[0], e2 = p[2] - p[0];
  const Eigen::Vector3d normal = e1.cross(e2);
  const double twice_area = normal.norm();
  if (!(twice_area > 1e-14 * (e1.squaredNorm() + e2.squaredNorm()))) {
    throw InputError("bending element", "degenerate reference triangle (zero area)");
  }
  // Orthonormal frame of the face plane, origin at the centroid, coordinates over a length scale
  // so the 6x6 interpolation system is well conditioned.
  const Eigen::Vector3d t1 = e1.normalized();
  const Eigen::Vector3d t2 = (normal / twice_area).cross(t1);
  const Eigen::Vector3d centroid = (p[0] + p[1] + p[2]) / 3.0;
  const double length = std::sqrt(0.5 * twice_area);
  Eigen::Matrix<double, 6, 6> vandermonde;
  for (int k = 0; k < 6; ++k) {
    const double u = (p[k] - centroid).dot(t1) / length, w = (p[k] - centroid).dot(t2) / length;
    vandermonde.row(k) << 1.0, u, w, u * u, u * w, w * w;
  }
  const Eigen::PartialPivLU<Eigen::Matrix<double, 6, 6>> lu(vandermonde);
  if (!(lu.rcond() > 1e-10)) {
    throw InputError("bending element",
                     "the six vertices of a face's bending stencil lie on one conic (no quadratic interpolant)");
  }
  const Eigen::Matrix<double, 6, 6> inverse = lu.inverse();
  // phi = sum c_j monomial_j: phi_11 = 2 c3, phi_12 = c4, phi_22 = 2 c5 (over length^2).
  BendingReference reference;
  const double scale = 1.0 / (length * length);
  reference.fit.row(0) = 2.0 * scale * inverse.row(3);
  reference.fit.row(1) = 2.0 * scale * inverse.row(5);
  reference.fit.row(2) = scale * inverse.row(4);
  reference.reference_form = second_form(reference.fit, p);
  for (int i = 0; i < 3; ++i) {
    if (stencil.edges[i] == EdgeKind::free) reference.free_directions[reference.free_count++] = reference.fit.col(3 + i);
  }
  reference.area = 0.5 * twice_area;
  return reference;
}

Eigen::Vector3d bending_curvature_change(const BendingStencil& stencil, const BendingReference& reference,
                                         const Vec18& x) {
  return second_form(reference.fit, effective_points(stencil, x)) - reference.reference_form;
}

double bending_energy(const WallMaterial& material, double bending_thickness, const BendingStencil& stencil,
                      const BendingReference& reference, const Vec18& x, Vec18* gradient, Mat18* hessian) {
  const double nu = material.poisson;
  const double modulus = material.young * bending_thickness * bending_thickness * bending_thickness /
                         (12.0 * (1.0 - nu * nu));
  const Eigen::Matrix3d d = modulus * bending_form(nu, reference);
  const Points p = effective_points(stencil, x);
  const Eigen::Vector3d e1 = p[1] - p[0], e2 = p[2] - p[0];
  const Eigen::Vector3d m = e1.cross(e2);
  const double r = m.norm();
  const Eigen::Vector3d n = m / r;
  std::array<Eigen::Vector3d, 3> g;
  Eigen::Vector3d v;
  for (int a = 0; a < 3; ++a) {
    g[a].setZero();
    for (int k = 0; k < 6; ++k) g[a] += reference.fit(a, k) * p[k];
    v(a) = g[a].dot(n) - reference.reference_form(a);
  }
  const double energy = 0.5 * reference.area * v.dot(d * v);
  if (gradient == nullptr && hessian == nullptr) return energy;

  // dm/dp_k for the face's three vertices.
  const std::array<Eigen::Matrix3d, 3> dm = {cross_matrix(e2 - e1), -cross_matrix(e2), cross_matrix(e1)};
  const Eigen::Vector3d sigma = reference.area * (d * v);
  // Jacobian J = dv/dp (3 x 18).
  Eigen::Matrix<double, 3, 18> jacobian;
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3d u = (g[a] - g[a].dot(n) * n) / r;
    for (int k = 0; k < 6; ++k) {
      Eigen::Vector3d row = reference.fit(a, k) * n;
      if (k < 3) row += dm[k].transpose() * u;
      jacobian.block<1, 3>(a, 3 * k) = row.transpose();
    }
  }
  if (gradient != nullptr) gradient->noalias() = jacobian.transpose() * sigma;
  if (hessian != nullptr) {
    Mat18& h = *hessian;
    const Eigen::Matrix<double, 3, 18> weighted = reference.area * (d * jacobian);
    h.noalias() = jacobian.transpose() * weighted;
    // Stress-weighted combinations: G = sum sigma_ab g_ab, fit_sigma(k) = sum sigma_ab fit(ab, k).
    Eigen::Vector3d big_g = Eigen::Vector3d::Zero();
    for (int a = 0; a < 3; ++a) big_g += sigma(a) * g[a];
    const Eigen::Matrix<double, 1, 6> fit_sigma = sigma.transpose() * reference.fit;
    const Eigen::Matrix3d projector = (Eigen::Matrix3d::Identity() - n * n.transpose()) / r;
    // fit (x) dn and transpose: d n / d p_a = projector dm_a.
    for (int a = 0; a < 3; ++a) {
      const Eigen::Matrix3d dn = projector * dm[a];
      for (int k = 0; k < 6; ++k) {
        h.block<3, 3>(3 * k, 3 * a) += fit_sigma(k) * dn;
        h.block<3, 3>(3 * a, 3 * k) += fit_sigma(k) * dn.transpose();
      }
    }
    // G . d2n: through m (second derivative of the unit vector) and through m's own bilinearity.
    const double gn = big_g.dot(n);
    const Eigen::Matrix3d hm = (-(big_g * n.transpose() + n * big_g.transpose()) - gn * Eigen::Matrix3d::Identity() +
                                3.0 * gn * n * n.transpose()) / (r * r);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) h.block<3, 3>(3 * a, 3 * b) += dm[a].transpose() * hm * dm[b];
    const Eigen::Matrix3d k_cross = -cross_matrix((big_g - gn * n) / r);
    h.block<3, 3>(0, 3) += k_cross;
    h.block<3, 3>(0, 6) -= k_cross;
    h.block<3, 3>(3, 0) -= k_cross;
    h.block<3, 3>(3, 6) += k_cross;
    h.block<3, 3>(6, 0) += k_cross;
    h.block<3, 3>(6, 3) -= k_cross;
  }
  carry_back(stencil, gradient, hessian);
  return energy;
}

}  // namespace growthuq::fe
