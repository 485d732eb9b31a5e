// Plane-stress hyperelastic laws of the shell wall: the membrane energy per unit reference area
// as a function of the mid-surface right Cauchy-Green tensor C, with exact first and second
// derivatives, and the thickness stretch that plane stress implies. Dimensionless in the solver.
#pragma once

#include <Eigen/Core>

#include "growthuq/fe/shell_fe_vocabulary.hpp"

namespace growthuq::fe {

// What an element needs of the wall (dimensionless: young = 1 in the solver).
struct WallMaterial {
  ShellFeLaw law = ShellFeLaw::hencky;
  double young = 1.0;
  double poisson = 0.2;
  double thickness = 0.0;  // h0 / d0 (membrane); bending uses `bending_thickness` of its stencil
};

// C is 2x2 symmetric in an orthonormal basis of the reference tangent plane; the functions below
// take its three independent entries c = (C11, C22, C12).
//
// W = t E / (2 (1 - nu^2)) [ (1 - nu) tr(A^2) + nu (tr A)^2 ], the plane-stress reduction
// (S33 = 0, resp. tau33 = 0) of the isotropic 3-D law, with
//   saint_venant_kirchhoff: A = (C - I) / 2 (Green-Lagrange);
//   hencky:                 A = ln(C) / 2 (Hencky strain; the Kirchhoff stress is Hooke's law of
//                           the logarithmic strain, Hencky 1928).
// The commercial code's "linear elastic under geometric nonlinearity" puts the Cauchy stress
// there instead; that differs from hencky by the volume ratio J and derives from no energy, so
// an energy-minimising model cannot use it (far_field.hpp quantifies the difference).
//
// gradient = dW/dc (so dW/dC12 counts both off-diagonal entries: gradient(2) = S12, while
// gradient(0) = S11 / 2, gradient(1) = S22 / 2, S = 2 dW/dC); hessian = d2W/dc2.
// Either may be nullptr. hencky at det C <= 0 (an inverted element) returns +infinity and leaves
// gradient and hessian untouched, so a line search rejects the step.
double membrane_energy_density(const WallMaterial& material, const Eigen::Vector3d& c,
                               Eigen::Vector3d* gradient, Eigen::Matrix3d* hessian);

// Second Piola-Kirchhoff stress resultant S = 2 dW/dC (force per reference length).
Eigen::Matrix2d second_piola_kirchhoff(const WallMaterial& material, const Eigen::Vector3d& c);

// Thickness stretch lambda3 = h / h0 of plane stress:
//   saint_venant_kirchhoff: E33 = -nu/(1-nu) (E11 + E22), lambda3 = sqrt(1 + 2 E33) (0 where the
//                           plane-stress thickness would collapse, 1 + 2 E33 <= 0);
//   hencky:                 eps3 = -nu/(1-nu) (eps1 + eps2) = -nu/(1-nu) ln sqrt(det C).
double thickness_stretch(const WallMaterial& material, const Eigen::Vector3d& c);

// f(x) = arccosh(1 + x)^2 and its first two derivatives in x. The Hencky energy's dependence on
// the eigenvalue split of C, written in invariants: f(s - 1), s = tr C / (2 sqrt(det C)) =
// cosh(ln(lambda1/lambda2)/2). f is analytic at x = 0 (coincident eigenvalues), where the closed
// forms of f' and f'' are 0/0; a power series is used for x < 1/4.
struct AcoshSquared {
  double value, first, second;
};
AcoshSquared acosh_squared(double x);

}  // namespace growthuq::fe
