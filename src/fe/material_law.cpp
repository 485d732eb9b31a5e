// Plane-stress Saint Venant-Kirchhoff and Hencky membrane energies with exact derivatives.
//
// The Hencky energy is an isotropic function of C. Its spectral form needs the eigenvectors of C
// and the divided difference (g1 - g2)/(lambda1 - lambda2) of the eigenvalue derivatives, which
// is 0/0 where the eigenvalues coincide, exactly at the reference state C = I. In two dimensions
// the same function is a smooth function of two invariants instead:
//   eps1 + eps2 = L = ln sqrt(det C),   (eps1 - eps2)^2 = arccosh(s)^2,   s = tr C / (2 sqrt(det C)),
// so W = k [ (1 + nu)/2 L^2 + (1 - nu)/2 arccosh(s)^2 ], k = t E / (2 (1 - nu^2)). The divided
// difference becomes f'(s) = 2 arccosh(s)/sqrt(s^2 - 1), whose limit at coincidence is taken from
// the power series of arccosh(1 + x)^2 (acosh_squared). s - 1 is formed without cancellation from
// (lambda1 - lambda2)^2 = (C11 - C22)^2 + 4 C12^2, so it keeps full relative precision.
#include "fe/material_law.hpp"

#include <cmath>
#include <limits>

namespace growthuq::fe {

namespace {

// k = t E / (2 (1 - nu^2)), the prefactor of both energies.
double energy_prefactor(const WallMaterial& material) {
  return material.thickness * material.young / (2.0 * (1.0 - material.poisson * material.poisson));
}

double stvk_energy(const WallMaterial& material, const Eigen::Vector3d& c, Eigen::Vector3d* gradient,
                   Eigen::Matrix3d* hessian) {
  const double k = energy_prefactor(material);
  const double nu = material.poisson;
  const double a11 = 0.5 * (c(0) - 1.0), a22 = 0.5 * (c(1) - 1.0), a12 = 0.5 * c(2);
  const double trace = a11 + a22;
  const double energy = k * ((1.0 - nu) * (a11 * a11 + a22 * a22 + 2.0 * a12 * a12) + nu * trace * trace);
  if (gradient != nullptr) {
    // dW/dA = 2k [(1 - nu) A + nu tr(A) I] = S; dA/dc = 1/2 per entry (both off-diagonals for c2).
    *gradient << k * ((1.0 - nu) * a11 + nu * trace), k * ((1.0 - nu) * a22 + nu * trace),
        2.0 * k * (1.0 - nu) * a12;
  }
  if (hessian != nullptr) {
    *hessian << 0.5 * k, 0.5 * k * nu, 0.0,  //
        0.5 * k * nu, 0.5 * k, 0.0,          //
        0.0, 0.0, k * (1.0 - nu);
  }
  return energy;
}

double hencky_energy(const WallMaterial& material, const Eigen::Vector3d& c, Eigen::Vector3d* gradient,
                     Eigen::Matrix3d* hessian) {
  const double det = c(0) * c(1) - c(2) * c(2);
  if (!(det > 0.0)) return std::numeric_limits<double>::infinity();
  const double k = energy_prefactor(material);
  const double nu = material.poisson;
  const double trace = c(0) + c(1);
  const double root_det = std::sqrt(det);
  const double split = (c(0) - c(1)) * (c(0) - c(1)) + 4.0 * c(2) * c(2);  // (lambda1 - lambda2)^2
  // s - 1 = (tr C - 2 sqrt(det C)) / (2 sqrt(det C)), with tr^2 - 4 det = split.
  const double x = split / (2.0 * root_det * (trace + 2.0 * root_det));
  const double log_area = 0.5 * std::log(det);  // L = eps1 + eps2
  const AcoshSquared f = acosh_squared(x);
  const double energy = k * (0.5 * (1.0 + nu) * log_area * log_area + 0.5 * (1.0 - nu) * f.value);
  if (gradient == nullptr && hessian == nullptr) return energy;

  // Derivatives of det, L = ln(det)/2 and s = tr / (2 sqrt(det)) with respect to c.
  const Eigen::Vector3d d_det(c(1), c(0), -2.0 * c(2));
  const Eigen::Vector3d d_trace(1.0, 1.0, 0.0);
  const Eigen::Vector3d d_log = d_det / (2.0 * det);
  const double det_m12 = 1.0 / root_det, det_m32 = det_m12 / det;
  const Eigen::Vector3d d_s = 0.5 * (d_trace * det_m12 - 0.5 * trace * det_m32 * d_det);
  if (gradient != nullptr) {
    *gradient = k * ((1.0 + nu) * log_area * d_log + 0.5 * (1.0 - nu) * f.first * d_s);
  }
  if (hessian != nullptr) {
    Eigen::Matrix3d dd_det;
    dd_det << 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, -2.0;
    const Eigen::Matrix3d dd_log = dd_det / (2.0 * det) - d_det * d_det.transpose() / (2.0 * det * det);
    const Eigen::Matrix3d dd_s =
        0.5 * (-0.5 * det_m32 * (d_trace * d_det.transpose() + d_det * d_trace.transpose()) +
               0.75 * trace * det_m32 / det * d_det * d_det.transpose() - 0.5 * trace * det_m32 * dd_det);
    *hessian = k * ((1.0 + nu) * (d_log * d_log.transpose() + log_area * dd_log) +
                    0.5 * (1.0 - nu) * (f.second * d_s * d_s.transpose() + f.first * dd_s));
  }
  return energy;
}

}  // namespace

AcoshSquared acosh_squared(double x) {
  if (x < 0.25) {
    // arccosh(1 + x)^2 = sum_{n>=1} a_n x^n, a_n = -2 (-2)^n / (n^2 binom(2n, n)) (from
    // arcsin(z)^2 = (1/2) sum (2z)^{2n} / (n^2 binom(2n, n)), Abramowitz and Stegun 4.4.41 with
    // cosh(eta) = cos(i eta)); a_{n+1} = -a_n n^2 / ((n + 1)(2n + 1)), |a_{n+1}/a_n| < 1/2, so at
    // x < 1/4 the terms fall at least 8x per order: 20 terms reach 1e-18 relative.
    AcoshSquared f{0.0, 0.0, 0.0};
    double a = 2.0;           // a_n
    double power = 1.0;       // x^(n-1)
    double power_down = 0.0;  // x^(n-2), 0 for n = 1
    for (int n = 1; n <= 24; ++n) {
      const double dn = n;
      f.value += a * power * x;
      f.first += dn * a * power;
      f.second += dn * (dn - 1.0) * a * power_down;
      power_down = power;
      power *= x;
      a *= -dn * dn / ((dn + 1.0) * (2.0 * dn + 1.0));
    }
    return f;
  }
  // eta = arccosh(1 + x), sinh(eta) = sqrt(x (x + 2)); f' = 2 eta / sinh(eta),
  // f'' = (2 - cosh(eta) f') / sinh(eta)^2.
  const double sinh_sq = x * (x + 2.0);
  const double sinh_eta = std::sqrt(sinh_sq);
  const double eta = std::log1p(x + sinh_eta);
  const double first = 2.0 * eta / sinh_eta;
  return {eta * eta, first, (2.0 - (1.0 + x) * first) / sinh_sq};
}

double membrane_energy_density(const WallMaterial& material, const Eigen::Vector3d& c,
                               Eigen::Vector3d* gradient, Eigen::Matrix3d* hessian) {
  switch (material.law) {
    case ShellFeLaw::saint_venant_kirchhoff:
      return stvk_energy(material, c, gradient, hessian);
    case ShellFeLaw::hencky:
      return hencky_energy(material, c, gradient, hessian);
  }
  return std::numeric_limits<double>::quiet_NaN();  // unreachable: every enumerator handled
}

Eigen::Matrix2d second_piola_kirchhoff(const WallMaterial& material, const Eigen::Vector3d& c) {
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  membrane_energy_density(material, c, &g, nullptr);
  Eigen::Matrix2d s;
  s << 2.0 * g(0), g(2), g(2), 2.0 * g(1);
  return s;
}

double thickness_stretch(const WallMaterial& material, const Eigen::Vector3d& c) {
  const double ratio = material.poisson / (1.0 - material.poisson);
  switch (material.law) {
    case ShellFeLaw::saint_venant_kirchhoff: {
      const double e33 = -ratio * 0.5 * (c(0) + c(1) - 2.0);
      return std::sqrt(std::fmax(0.0, 1.0 + 2.0 * e33));
    }
    case ShellFeLaw::hencky: {
      const double det = c(0) * c(1) - c(2) * c(2);
      if (!(det > 0.0)) return 0.0;  // an inverted element has no thickness stretch
      return std::exp(-ratio * 0.5 * std::log(det));
    }
  }
  return std::numeric_limits<double>::quiet_NaN();  // unreachable
}

}  // namespace growthuq::fe
