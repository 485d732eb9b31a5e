// The membrane triangle: derivatives against central differences on random triangles and states,
// zero energy and force under rigid motions, and the nodal forces and wall stresses of a uniform
// stretch against the laws' analytic stresses (P = F S, Cauchy = tau / J).
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "fe/membrane.hpp"
#include "fe_test_geometry.hpp"
#include "growthuq/core/error.hpp"

using namespace growthuq::fe;
using growthuq::ShellFeLaw;
using namespace growthuq::fe::testing;
using growthuq::testing::unit_uniform;
using Vec9 = Eigen::Matrix<double, 9, 1>;
using Mat9 = Eigen::Matrix<double, 9, 9>;

namespace {

WallMaterial wall(ShellFeLaw law, double nu = 0.3, double t = 0.02) {
  WallMaterial m;
  m.law = law;
  m.poisson = nu;
  m.thickness = t;
  return m;
}

// A random non-degenerate triangle of size ~0.1 (the tube's elements are ~0.01-0.1 d0).
void random_triangle(std::mt19937_64& rng, Eigen::Vector3d& X0, Eigen::Vector3d& X1, Eigen::Vector3d& X2) {
  do {
    X0 = random_vector(rng, 1.0);
    X1 = X0 + random_vector(rng, 0.1);
    X2 = X0 + random_vector(rng, 0.1);
  } while ((X1 - X0).cross(X2 - X0).norm() < 0.2 * (X1 - X0).norm() * (X2 - X0).norm());
}

Vec9 stack(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  Vec9 x;
  x << a, b, c;
  return x;
}

}  // namespace

TEST_CASE("membrane: gradient and Hessian against central differences") {
  // Step 1e-7 on positions ~1 (edges ~0.1): truncation ~1e-14/edge^2 relative, rounding ~eps
  // x/step ~ 1e-9 of the gradient; 1e-6 of the largest entry catches any wrong term.
  std::mt19937_64 rng(3);
  for (ShellFeLaw law : {ShellFeLaw::saint_venant_kirchhoff, ShellFeLaw::hencky}) {
    const WallMaterial m = wall(law);
    for (int trial = 0; trial < 40; ++trial) {
      Eigen::Vector3d X0, X1, X2;
      random_triangle(rng, X0, X1, X2);
      const MembraneReference ref = make_membrane_reference(X0, X1, X2);
      // Deformed: a random rotation of a stretched copy plus nodal noise (stretches 0.7-1.4).
      const Eigen::Matrix3d rotation = random_rotation(rng);
      Vec9 x = stack(rotation * X0, rotation * X1, rotation * X2);
      for (int i = 0; i < 9; ++i) x(i) += 0.03 * (2 * unit_uniform(rng) - 1);
      Vec9 g;
      Mat9 h;
      membrane_energy(m, ref, x, &g, &h);
      Vec9 g_fd;
      Mat9 h_fd;
      central_differences<9>(
          x, 1e-7, [&](const Vec9& y) { return membrane_energy(m, ref, y, nullptr, nullptr); },
          [&](const Vec9& y) {
            Vec9 gy;
            membrane_energy(m, ref, y, &gy, nullptr);
            return gy;
          },
          g_fd, h_fd);
      CHECK((g - g_fd).cwiseAbs().maxCoeff() <= 1e-6 * g.cwiseAbs().maxCoeff());
      CHECK((h - h_fd).cwiseAbs().maxCoeff() <= 1e-6 * h.cwiseAbs().maxCoeff());
      CHECK((h - h.transpose()).cwiseAbs().maxCoeff() <= 1e-14 * h.cwiseAbs().maxCoeff());
    }
  }
}

TEST_CASE("membrane: rigid motions give zero energy and zero force") {
  std::mt19937_64 rng(4);
  for (ShellFeLaw law : {ShellFeLaw::saint_venant_kirchhoff, ShellFeLaw::hencky}) {
    const WallMaterial m = wall(law);
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::Vector3d X0, X1, X2;
      random_triangle(rng, X0, X1, X2);
      const MembraneReference ref = make_membrane_reference(X0, X1, X2);
      const Eigen::Matrix3d rotation = random_rotation(rng);
      const Eigen::Vector3d shift = random_vector(rng, 5.0);
      const Vec9 x = stack(rotation * X0 + shift, rotation * X1 + shift, rotation * X2 + shift);
      Vec9 g;
      const double energy = membrane_energy(m, ref, x, &g, nullptr);
      // Scale of a unit strain: energy k area ~ 1e-4, force k edge ~ 1e-3. Rounding of C is
      // ~1e-15, so energy ~k area 1e-30 and force ~k edge 1e-15.
      CHECK(std::fabs(energy) < 1e-20);
      CHECK(g.cwiseAbs().maxCoeff() < 1e-15);
    }
  }
}

TEST_CASE("membrane: a uniform stretch gives the law's stress") {
  // Reference triangle in the plane z = 0; deformation x = Q diag(U, 1) X with U a symmetric
  // stretch (principal stretches l1, l2 at angle theta) and Q a rotation. The nodal forces of a
  // constant-strain triangle are A P grad N_a, with P = F S the first Piola-Kirchhoff stress
  // resultant and grad N_a the reference gradients of the linear shape functions, formed here
  // from the edges (grad N_a = n x (X_c - X_b) / (2A)), independently of the element's basis.
  std::mt19937_64 rng(8);
  const double nu = 0.25, t = 0.04;
  const double k = t / (2 * (1 - nu * nu));
  for (ShellFeLaw law : {ShellFeLaw::saint_venant_kirchhoff, ShellFeLaw::hencky}) {
    const WallMaterial m = wall(law, nu, t);
    for (int trial = 0; trial < 10; ++trial) {
      const Eigen::Vector3d X[3] = {Eigen::Vector3d(0.1, -0.2, 0), Eigen::Vector3d(0.25, -0.15, 0),
                                    Eigen::Vector3d(0.12, 0.05, 0)};
      const double l1 = 0.8 + 0.6 * unit_uniform(rng), l2 = 0.8 + 0.6 * unit_uniform(rng);
      const double theta = 3.0 * unit_uniform(rng);
      Eigen::Matrix2d n;
      n << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
      const Eigen::Matrix2d u = n * Eigen::Vector2d(l1, l2).asDiagonal() * n.transpose();
      // The law's 2nd PK resultant S in the principal basis, then rotated.
      Eigen::Vector2d s_principal;
      if (law == ShellFeLaw::saint_venant_kirchhoff) {
        const double e1 = 0.5 * (l1 * l1 - 1), e2 = 0.5 * (l2 * l2 - 1);
        s_principal << 2 * k * (e1 + nu * e2), 2 * k * (e2 + nu * e1);
      } else {  // Kirchhoff tau_i = 2k (eps_i + nu eps_j), S_i = tau_i / l_i^2
        const double e1 = std::log(l1), e2 = std::log(l2);
        s_principal << 2 * k * (e1 + nu * e2) / (l1 * l1), 2 * k * (e2 + nu * e1) / (l2 * l2);
      }
      const Eigen::Matrix2d s2 = n * s_principal.asDiagonal() * n.transpose();
      Eigen::Matrix3d f = Eigen::Matrix3d::Identity(), s = Eigen::Matrix3d::Zero();
      f.topLeftCorner<2, 2>() = u;
      s.topLeftCorner<2, 2>() = s2;
      const Eigen::Matrix3d q = random_rotation(rng);
      const Vec9 x = stack(q * f * X[0], q * f * X[1], q * f * X[2]);
      const MembraneReference ref = make_membrane_reference(X[0], X[1], X[2]);
      Vec9 g;
      membrane_energy(m, ref, x, &g, nullptr);
      const Eigen::Vector3d normal = (X[1] - X[0]).cross(X[2] - X[0]);
      const double area = 0.5 * normal.norm();
      const Eigen::Vector3d unit = normal.normalized();
      for (int a = 0; a < 3; ++a) {
        const Eigen::Vector3d grad_n = unit.cross(X[(a + 2) % 3] - X[(a + 1) % 3]) / (2 * area);
        const Eigen::Vector3d force = area * q * f * s * grad_n;
        CHECK((g.segment<3>(3 * a) - force).norm() <= 1e-13 * force.norm() + 1e-17);
      }
      // Cauchy stresses: principal values of F S F^T / (l1 l2 lambda3 t).
      const MembraneStress stress = membrane_stress(m, ref, x);
      double lambda3, sig1, sig2;
      if (law == ShellFeLaw::saint_venant_kirchhoff) {
        lambda3 = std::sqrt(1 - 2 * nu / (1 - nu) * 0.5 * (l1 * l1 + l2 * l2 - 2));
      } else {
        lambda3 = std::exp(-nu / (1 - nu) * (std::log(l1) + std::log(l2)));
      }
      sig1 = l1 * l1 * s_principal(0) / (l1 * l2 * lambda3 * t);
      sig2 = l2 * l2 * s_principal(1) / (l1 * l2 * lambda3 * t);
      if (sig1 < sig2) std::swap(sig1, sig2);
      CHECK(stress.thickness_stretch == doctest::Approx(lambda3).epsilon(1e-14));
      CHECK(std::fabs(stress.sigma1 - sig1) < 1e-13);
      CHECK(std::fabs(stress.sigma2 - sig2) < 1e-13);
      CHECK(stress.von_mises == doctest::Approx(std::sqrt(sig1 * sig1 - sig1 * sig2 + sig2 * sig2)).epsilon(1e-12));
    }
  }
}

TEST_CASE("membrane: an inverted Hencky triangle has infinite energy; a degenerate reference is an input error") {
  const Eigen::Vector3d X0(0, 0, 0), X1(1, 0, 0), X2(0, 1, 0);
  const MembraneReference ref = make_membrane_reference(X0, X1, X2);
  CHECK(ref.area == doctest::Approx(0.5).epsilon(1e-15));
  const Vec9 flat = stack(X0, X1, X0 + 0.5 * (X1 - X0));  // collapsed to a line: det C = 0
  CHECK(std::isinf(membrane_energy(wall(ShellFeLaw::hencky), ref, flat, nullptr, nullptr)));
  CHECK(std::isfinite(membrane_energy(wall(ShellFeLaw::saint_venant_kirchhoff), ref, flat, nullptr, nullptr)));
  CHECK_THROWS_AS(make_membrane_reference(X0, X1, X0 + 2.0 * (X1 - X0)), growthuq::InputError);
}
