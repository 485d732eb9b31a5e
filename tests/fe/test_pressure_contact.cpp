// Gradient and Hessian of the pressure (volume) and contact (penalty) terms against central
// finite differences; the penalty's smoothness; the obstacles' geometry.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "fe/contact.hpp"
#include "fe/pressure.hpp"

using namespace growthuq::fe;

namespace {

// Central differences with step 1e-6 on O(1) coordinates: truncation ~1e-12 * third
// derivative, round-off ~1e-16/1e-6 = 1e-10 relative; 1e-7 leaves a margin over both.
constexpr double fd_step = 1e-6;
constexpr double fd_tolerance = 1e-7;

template <int N, class F>
void check_gradient_hessian(const F& f, const Eigen::Matrix<double, N, 1>& x) {
  Eigen::Matrix<double, N, 1> g, gp, gm, dummy;
  Eigen::Matrix<double, N, N> h, hd;
  f(x, &g, &h);
  double scale_g = std::max(1.0, g.template lpNorm<Eigen::Infinity>());
  double scale_h = std::max(1.0, h.template lpNorm<Eigen::Infinity>());
  for (int i = 0; i < N; ++i) {
    Eigen::Matrix<double, N, 1> xp = x, xm = x;
    xp[i] += fd_step;
    xm[i] -= fd_step;
    const double fd = (f(xp, nullptr, nullptr) - f(xm, nullptr, nullptr)) / (2 * fd_step);
    CHECK(std::fabs(fd - g[i]) <= fd_tolerance * scale_g);
    f(xp, &gp, nullptr);
    f(xm, &gm, nullptr);
    for (int j = 0; j < N; ++j) {
      CHECK(std::fabs((gp[j] - gm[j]) / (2 * fd_step) - h(j, i)) <= fd_tolerance * scale_h);
    }
  }
  CHECK((h - h.transpose()).norm() <= 1e-14 * scale_h);
}

}  // namespace

TEST_CASE("face volume: gradient and Hessian against central differences on random triangles") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::Matrix<double, 9, 1> x;
    for (int i = 0; i < 9; ++i) x[i] = u(rng);
    check_gradient_hessian<9>([](const Eigen::Matrix<double, 9, 1>& y, Eigen::Matrix<double, 9, 1>* g,
                                 Eigen::Matrix<double, 9, 9>* h) { return face_volume(y, g, h); },
                              x);
  }
}

TEST_CASE("face volume of a translated closed surface does not change (gradient sums to zero per face set)") {
  // The unit cube as 12 triangles: V = 1 wherever it is, and the total gradient under a
  // translation (sum over all vertex gradients) is zero.
  Eigen::Matrix3Xd p(3, 8);
  p << 0, 1, 1, 0, 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 1, 1;
  std::vector<std::array<int, 3>> faces = {{0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                           {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  CHECK(enclosed_volume(p, faces) == doctest::Approx(1.0).epsilon(1e-15));
  p.colwise() += Eigen::Vector3d(3.0, -2.0, 5.0);
  CHECK(enclosed_volume(p, faces) == doctest::Approx(1.0).epsilon(1e-14));
}

TEST_CASE("penalty is C2 at the contact onset and at the end of its cubic range") {
  const PenaltyLaw law{50.0, 1e-3};
  const double eps = law.smoothing;
  for (double s : {0.0, eps}) {
    const PenaltyValue below = penalty(law, s * (1 - 1e-9) - 1e-15), above = penalty(law, s * (1 + 1e-9) + 1e-15);
    CHECK(above.energy == doctest::Approx(below.energy).epsilon(1e-6));
    CHECK(std::fabs(above.slope - below.slope) <= 1e-6 * law.stiffness * eps);
    CHECK(std::fabs(above.curvature - below.curvature) <= 1e-6 * law.stiffness);
  }
  // In the quadratic range the force is k (s - eps/2).
  CHECK(penalty(law, 0.01).slope == doctest::Approx(50.0 * (0.01 - 0.0005)).epsilon(1e-14));
}

TEST_CASE("sphere and plane contact: gradient and Hessian against central differences") {
  const PenaltyLaw law{20.0, 1e-3};
  const RigidSphere sphere{Eigen::Vector3d(0.7, 0.1, -0.2), 0.3};
  const RigidPlane plane{Eigen::Vector3d(-0.1, 0.0, 0.0), Eigen::Vector3d(1, 2, 2).normalized()};
  std::mt19937 rng(11);
  std::normal_distribution<double> n(0.0, 1.0);
  for (double depth : {0.05, 0.0004, 0.002}) {  // quadratic range, cubic range, near its end
    for (int trial = 0; trial < 5; ++trial) {
      const Eigen::Vector3d dir = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
      const Eigen::Matrix<double, 3, 1> xs = sphere.centre + (sphere.radius - depth) * dir;
      check_gradient_hessian<3>([&](const Eigen::Matrix<double, 3, 1>& y, Eigen::Matrix<double, 3, 1>* g,
                                    Eigen::Matrix<double, 3, 3>* h) {
        Eigen::Vector3d gv;
        Eigen::Matrix3d hv;
        const double e = sphere_contact(sphere, law, y, g ? &gv : nullptr, h ? &hv : nullptr);
        if (g) *g = gv;
        if (h) *h = hv;
        return e;
      }, xs);
      double penetration = 0;
      sphere_contact(sphere, law, xs, nullptr, nullptr, &penetration);
      CHECK(penetration == doctest::Approx(depth).epsilon(1e-9));
      const Eigen::Matrix<double, 3, 1> xp = plane.point - depth * plane.normal + 0.3 * dir.cross(plane.normal);
      check_gradient_hessian<3>([&](const Eigen::Matrix<double, 3, 1>& y, Eigen::Matrix<double, 3, 1>* g,
                                    Eigen::Matrix<double, 3, 3>* h) {
        Eigen::Vector3d gv;
        Eigen::Matrix3d hv;
        const double e = plane_contact(plane, law, y, g ? &gv : nullptr, h ? &hv : nullptr);
        if (g) *g = gv;
        if (h) *h = hv;
        return e;
      }, xp);
    }
  }
  // Outside both obstacles: no energy, no force.
  Eigen::Vector3d g;
  CHECK(sphere_contact(sphere, law, sphere.centre + Eigen::Vector3d(0, 0, 0.31), &g, nullptr) == 0.0);
  CHECK(g.norm() == 0.0);
  CHECK(plane_contact(plane, law, plane.point + 0.01 * plane.normal, &g, nullptr) == 0.0);
  CHECK(g.norm() == 0.0);
}
