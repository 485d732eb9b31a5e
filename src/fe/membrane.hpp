// The membrane element of the shell: a linear (constant-strain) triangle with the plane-stress
// laws of material_law.hpp; energy with analytic gradient and Hessian, and the wall stresses of a
// state for output. Fixed-size Eigen types, no allocation.
#pragma once

#include <Eigen/Core>

#include "fe/material_law.hpp"

namespace growthuq::fe {

// Reference data of one triangle: F = [x0 x1 x2] shape_gradient is the 3x2 deformation gradient
// onto an orthonormal basis of the reference plane (t1 along X1 - X0, t2 = n x t1).
struct MembraneReference {
  Eigen::Matrix<double, 3, 2> shape_gradient;
  double area = 0.0;  // reference area
};

// Throws InputError for a degenerate reference triangle (zero area).
MembraneReference make_membrane_reference(const Eigen::Vector3d& X0, const Eigen::Vector3d& X1,
                                          const Eigen::Vector3d& X2);

// Membrane energy area * W(C) of one triangle, x = (x0, x1, x2) stacked; gradient and Hessian
// optional (nullptr = not wanted), exact. hencky: +infinity for an inverted triangle (gradient
// and Hessian then untouched).
double membrane_energy(const WallMaterial& material, const MembraneReference& reference,
                       const Eigen::Matrix<double, 9, 1>& x, Eigen::Matrix<double, 9, 1>* gradient,
                       Eigen::Matrix<double, 9, 9>* hessian);

// Right Cauchy-Green tensor (C11, C22, C12) of the triangle in its reference basis.
Eigen::Vector3d membrane_cauchy_green(const MembraneReference& reference,
                                      const Eigen::Matrix<double, 9, 1>& x);

// Wall stresses of a state, in the units of material.young (i.e. / E in the solver): principal
// Cauchy stresses in the wall's tangent plane sigma1 >= sigma2 (membrane force per current length
// over the current thickness lambda3 h0), the von Mises stress of that plane-stress state
// sqrt(s1^2 - s1 s2 + s2^2), and the thickness stretch lambda3 = h / h0. Needs thickness > 0.
struct MembraneStress {
  double sigma1, sigma2, von_mises, thickness_stretch;
};
MembraneStress membrane_stress(const WallMaterial& material, const MembraneReference& reference,
                               const Eigen::Matrix<double, 9, 1>& x);

}  // namespace growthuq::fe
