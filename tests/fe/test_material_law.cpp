// The plane-stress laws: derivatives against central differences, the Hencky law against an
// independent spectral evaluation in long double (exactly at, near and far from coincident
// eigenvalues of C), the series of arccosh(1+x)^2 against long-double closed forms, and the
// thickness stretch against its definition through the principal stretches.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "fe/material_law.hpp"
#include "support/random_draws.hpp"

using namespace growthuq::fe;
using growthuq::ShellFeLaw;
using growthuq::testing::unit_uniform;

namespace {

WallMaterial wall(ShellFeLaw law, double nu = 0.3, double t = 0.03) {
  WallMaterial m;
  m.law = law;
  m.poisson = nu;
  m.thickness = t;
  return m;
}

// A random symmetric positive definite C with principal stretches in [0.6, 1.6].
Eigen::Vector3d random_cauchy_green(std::mt19937_64& rng) {
  const double l1 = 0.6 + unit_uniform(rng), l2 = 0.6 + unit_uniform(rng);
  const double angle = 3.14159 * unit_uniform(rng);
  const double cs = std::cos(angle), sn = std::sin(angle);
  const double c1 = l1 * l1, c2 = l2 * l2;
  return {cs * cs * c1 + sn * sn * c2, sn * sn * c1 + cs * cs * c2, cs * sn * (c1 - c2)};
}

// The spectral form of the Hencky law in long double (Hill 1968; Miehe 1998 for the second
// derivative of an isotropic tensor function): eigenvalues lambda_i of C, g_i = dw/dlambda_i,
// dW/dC = sum g_i n_i n_i^T and d2W[X, Y] = sum_ij dg_i/dlambda_j X'_ii Y'_jj
// + 2 (g1 - g2)/(lambda1 - lambda2) X'_12 Y'_12 in the eigenbasis; at coincidence the divided
// difference is replaced by its limit dg1/dlambda1 - dg1/dlambda2.
struct SpectralHencky {
  long double energy;
  long double gradient[3];
  long double hessian[3][3];
};

SpectralHencky spectral_hencky(const WallMaterial& m, long double c11, long double c22, long double c12) {
  using L = long double;
  const L k = static_cast<L>(m.thickness) / (2.0L * (1.0L - static_cast<L>(m.poisson) * m.poisson));
  const L nu = m.poisson;
  const L mean = 0.5L * (c11 + c22), radius = std::hypot(0.5L * (c11 - c22), c12);
  const L lam[2] = {mean + radius, mean - radius};
  const L angle = 0.5L * std::atan2(2.0L * c12, c11 - c22);
  const L n[2][2] = {{std::cos(angle), std::sin(angle)}, {-std::sin(angle), std::cos(angle)}};
  const L eps[2] = {0.5L * std::log(lam[0]), 0.5L * std::log(lam[1])};
  SpectralHencky out{};
  out.energy = k * ((1 - nu) * (eps[0] * eps[0] + eps[1] * eps[1]) + nu * (eps[0] + eps[1]) * (eps[0] + eps[1]));
  L g[2], dg[2][2];
  for (int i = 0; i < 2; ++i) g[i] = k * ((1 - nu) * eps[i] + nu * (eps[0] + eps[1])) / lam[i];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      dg[i][j] = i == j ? k / (2 * lam[i] * lam[i]) - g[i] / lam[i] : k * nu / (2 * lam[i] * lam[j]);
  const L divided = radius > 0 ? (g[0] - g[1]) / (lam[0] - lam[1]) : dg[0][0] - dg[0][1];
  // Directions of c: dC for C11, C22 and for C12 (= C21).
  const L dirs[3][2][2] = {{{1, 0}, {0, 0}}, {{0, 0}, {0, 1}}, {{0, 1}, {1, 0}}};
  L rotated[3][2][2];  // N^T dC N
  for (int d = 0; d < 3; ++d)
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        L s = 0;
        for (int i = 0; i < 2; ++i)
          for (int j = 0; j < 2; ++j) s += n[a][i] * dirs[d][i][j] * n[b][j];
        rotated[d][a][b] = s;
      }
  for (int d = 0; d < 3; ++d) out.gradient[d] = g[0] * rotated[d][0][0] + g[1] * rotated[d][1][1];
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) {
      L s = 2 * divided * rotated[p][0][1] * rotated[q][0][1];
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) s += dg[i][j] * rotated[p][i][i] * rotated[q][j][j];
      out.hessian[p][q] = s;
    }
  return out;
}

// Largest deviation of (energy, gradient, hessian) from the spectral reference, over k.
double deviation_from_spectral(const WallMaterial& m, const Eigen::Vector3d& c) {
  Eigen::Vector3d g;
  Eigen::Matrix3d h;
  const double w = membrane_energy_density(m, c, &g, &h);
  const SpectralHencky ref = spectral_hencky(m, c(0), c(1), c(2));
  const double k = m.thickness / (2.0 * (1.0 - m.poisson * m.poisson));
  double worst = std::fabs(w - static_cast<double>(ref.energy));
  for (int i = 0; i < 3; ++i) {
    worst = std::fmax(worst, std::fabs(g(i) - static_cast<double>(ref.gradient[i])));
    for (int j = 0; j < 3; ++j) worst = std::fmax(worst, std::fabs(h(i, j) - static_cast<double>(ref.hessian[i][j])));
  }
  return worst / k;
}

Eigen::Vector3d rotated_diagonal(double c1, double c2, double angle) {
  const double cs = std::cos(angle), sn = std::sin(angle);
  return {cs * cs * c1 + sn * sn * c2, sn * sn * c1 + cs * cs * c2, cs * sn * (c1 - c2)};
}

}  // namespace

TEST_CASE("membrane laws: gradient and Hessian against central differences") {
  // Step 1e-6 on entries of order 1: central-difference truncation ~1e-12 and rounding
  // ~eps/1e-6 ~ 1e-10 relative, so 1e-7 of the largest entry is a safe bound that any sign or
  // factor error (relative size >= 1e-2) exceeds by far.
  std::mt19937_64 rng(12);
  for (ShellFeLaw law : {ShellFeLaw::saint_venant_kirchhoff, ShellFeLaw::hencky}) {
    const WallMaterial m = wall(law);
    for (int trial = 0; trial < 50; ++trial) {
      const Eigen::Vector3d c = random_cauchy_green(rng);
      Eigen::Vector3d g;
      Eigen::Matrix3d h;
      membrane_energy_density(m, c, &g, &h);
      const double step = 1e-6;
      Eigen::Vector3d g_fd;
      Eigen::Matrix3d h_fd;
      for (int i = 0; i < 3; ++i) {
        Eigen::Vector3d cp = c, cm = c;
        cp(i) += step;
        cm(i) -= step;
        g_fd(i) = (membrane_energy_density(m, cp, nullptr, nullptr) -
                   membrane_energy_density(m, cm, nullptr, nullptr)) / (2 * step);
        Eigen::Vector3d gp, gm;
        membrane_energy_density(m, cp, &gp, nullptr);
        membrane_energy_density(m, cm, &gm, nullptr);
        h_fd.col(i) = (gp - gm) / (2 * step);
      }
      CHECK((g - g_fd).cwiseAbs().maxCoeff() <= 1e-7 * g.cwiseAbs().maxCoeff());
      CHECK((h - h_fd).cwiseAbs().maxCoeff() <= 1e-7 * h.cwiseAbs().maxCoeff());
    }
  }
}

TEST_CASE("Hencky law against the long-double spectral form, at, near and far from coincidence") {
  // Tolerance 1e-13 k: the double evaluation is accurate to a few eps times k; the long-double
  // divided difference at relative split delta is accurate to ~1e-19/delta (delta >= 1e-5).
  const WallMaterial m = wall(ShellFeLaw::hencky, 0.2, 0.05);
  SUBCASE("exactly at coincidence, C = lambda I") {
    for (double c : {0.5, 1.0, 1.0 + 1e-9, 1.3, 2.5}) {
      CHECK(deviation_from_spectral(m, Eigen::Vector3d(c, c, 0.0)) < 1e-13);
    }
  }
  SUBCASE("near and far from coincidence, rotated eigenbases") {
    for (double base : {0.7, 1.0, 1.45}) {
      for (double delta : {1e-5, 1e-3, 1e-1, 0.6}) {
        for (double angle : {0.0, 0.4, 1.1, 2.7}) {
          CHECK(deviation_from_spectral(m, rotated_diagonal(base * (1 + delta), base, angle)) < 1e-13);
        }
      }
    }
  }
  SUBCASE("splits below 1e-5 converge to the coincidence limit linearly in the split") {
    // The Hessian is smooth in C, so |H(split) - H(0)| <= (a few k) * split; the spectral
    // reference cannot be formed here (its divided difference loses 1e-19/delta).
    const double k = m.thickness / (2.0 * (1.0 - m.poisson * m.poisson));
    Eigen::Matrix3d h0, h;
    Eigen::Vector3d g0, g;
    membrane_energy_density(m, Eigen::Vector3d(1.2, 1.2, 0.0), &g0, &h0);
    for (double delta : {1e-6, 1e-9, 1e-12, 1e-15}) {
      membrane_energy_density(m, rotated_diagonal(1.2 * (1 + delta), 1.2, 0.7), &g, &h);
      CHECK((h - h0).cwiseAbs().maxCoeff() < k * (10 * delta + 1e-14));
      CHECK((g - g0).cwiseAbs().maxCoeff() < k * (10 * delta + 1e-14));
    }
  }
  SUBCASE("the reference state: zero energy and stress, Hessian of linear plane stress") {
    Eigen::Vector3d g;
    Eigen::Matrix3d h;
    CHECK(membrane_energy_density(m, Eigen::Vector3d(1, 1, 0), &g, &h) == 0.0);
    CHECK(g.cwiseAbs().maxCoeff() == 0.0);
    // At C = I both strains are (C - I)/2 to first order, so the Hessian equals St-VK's.
    Eigen::Matrix3d h_stvk;
    membrane_energy_density(wall(ShellFeLaw::saint_venant_kirchhoff, 0.2, 0.05), Eigen::Vector3d(1, 1, 0),
                            nullptr, &h_stvk);
    CHECK((h - h_stvk).cwiseAbs().maxCoeff() < 1e-15);
  }
}

TEST_CASE("arccosh(1 + x)^2: the series below 1/4 and the closed form above agree with long double") {
  for (double x : {1e-300, 1e-12, 1e-6, 1e-3, 0.05, 0.2, 0.2499999, 0.25, 0.3, 1.0, 10.0, 1e3}) {
    const AcoshSquared f = acosh_squared(x);
    const long double lx = x;
    const long double eta = std::log1p(lx + std::sqrt(lx * (lx + 2)));
    const long double sinh_eta = std::sqrt(lx * (lx + 2));
    const long double first = 2 * eta / sinh_eta;
    CHECK(std::fabs(f.value - static_cast<double>(eta * eta)) <= 4e-16 * static_cast<double>(eta * eta));
    CHECK(std::fabs(f.first - static_cast<double>(first)) <= 4e-16 * static_cast<double>(first));
    if (x >= 1e-3) {  // long double's (2 - s f')/(x (x + 2)) loses 1e-19/x
      const long double second = (2 - (1 + lx) * first) / (lx * (lx + 2));
      CHECK(std::fabs(f.second - static_cast<double>(second)) <= 1e-14 * std::fabs(static_cast<double>(second)));
    }
  }
  // Limits at coincidence: f = 2x - x^2/3 + ..., so f'(0) = 2, f''(0) = -2/3.
  CHECK(acosh_squared(0.0).first == 2.0);
  CHECK(std::fabs(acosh_squared(0.0).second + 2.0 / 3.0) < 1e-16);
}

TEST_CASE("thickness stretch of plane stress from the principal stretches") {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const double l1 = 0.8 + 0.5 * unit_uniform(rng), l2 = 0.8 + 0.5 * unit_uniform(rng);
    const Eigen::Vector3d c = rotated_diagonal(l1 * l1, l2 * l2, 6.0 * unit_uniform(rng));
    const double nu = 0.3;
    const double e33 = -nu / (1 - nu) * 0.5 * (l1 * l1 - 1 + l2 * l2 - 1);
    CHECK(thickness_stretch(wall(ShellFeLaw::saint_venant_kirchhoff, nu), c) ==
          doctest::Approx(std::sqrt(1 + 2 * e33)).epsilon(1e-14));
    CHECK(thickness_stretch(wall(ShellFeLaw::hencky, nu), c) ==
          doctest::Approx(std::exp(-nu / (1 - nu) * (std::log(l1) + std::log(l2)))).epsilon(1e-14));
  }
  // Collapse of the St-VK plane-stress thickness (1 + 2 E33 <= 0) gives 0, not NaN.
  CHECK(thickness_stretch(wall(ShellFeLaw::saint_venant_kirchhoff, 0.45), Eigen::Vector3d(3, 3, 0)) == 0.0);
}
