// Constant-strain membrane triangle. With f_i = sum_a B(a, i) x_a the columns of F, the entries
// c = (f0.f0, f1.f1, f0.f1) of C are quadratic in x, so the Hessian is J^T W_cc J (J = dc/dx)
// plus the geometric term sum_m (dW/dc_m) d2c_m/dx2, which is a 3x3 nodal matrix times I3.
#include "fe/membrane.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "growthuq/core/error.hpp"

namespace growthuq::fe {

MembraneReference make_membrane_reference(const Eigen::Vector3d& X0, const Eigen::Vector3d& X1,
                                          const Eigen::Vector3d& X2) {
  const Eigen::Vector3d e1 = X1 - X0, e2 = X2 - X0;
  const Eigen::Vector3d normal = e1.cross(e2);
  const double twice_area = normal.norm();
  const double scale = e1.squaredNorm() + e2.squaredNorm();
  if (!(twice_area > 1e-14 * scale)) {
    throw InputError("membrane element", "degenerate reference triangle (zero area)");
  }
  const Eigen::Vector3d t1 = e1.normalized();
  const Eigen::Vector3d t2 = (normal / twice_area).cross(t1);
  Eigen::Matrix2d edges;  // reference edge vectors in the local basis, as columns
  edges << e1.dot(t1), e2.dot(t1), 0.0, e2.dot(t2);
  Eigen::Matrix<double, 3, 2> node_to_edges;
  node_to_edges << -1.0, -1.0, 1.0, 0.0, 0.0, 1.0;
  MembraneReference reference;
  reference.shape_gradient = node_to_edges * edges.inverse();
  reference.area = 0.5 * twice_area;
  return reference;
}

namespace {

struct Columns {
  Eigen::Vector3d f0, f1;
};

Columns deformation_columns(const MembraneReference& reference, const Eigen::Matrix<double, 9, 1>& x) {
  const auto& b = reference.shape_gradient;
  Columns f;
  f.f0 = b(0, 0) * x.segment<3>(0) + b(1, 0) * x.segment<3>(3) + b(2, 0) * x.segment<3>(6);
  f.f1 = b(0, 1) * x.segment<3>(0) + b(1, 1) * x.segment<3>(3) + b(2, 1) * x.segment<3>(6);
  return f;
}

}  // namespace

Eigen::Vector3d membrane_cauchy_green(const MembraneReference& reference,
                                      const Eigen::Matrix<double, 9, 1>& x) {
  const Columns f = deformation_columns(reference, x);
  return {f.f0.dot(f.f0), f.f1.dot(f.f1), f.f0.dot(f.f1)};
}

double membrane_energy(const WallMaterial& material, const MembraneReference& reference,
                       const Eigen::Matrix<double, 9, 1>& x, Eigen::Matrix<double, 9, 1>* gradient,
                       Eigen::Matrix<double, 9, 9>* hessian) {
  const Columns f = deformation_columns(reference, x);
  const Eigen::Vector3d c(f.f0.dot(f.f0), f.f1.dot(f.f1), f.f0.dot(f.f1));
  Eigen::Vector3d g;
  Eigen::Matrix3d h;
  const bool derivatives = gradient != nullptr || hessian != nullptr;
  const double density =
      membrane_energy_density(material, c, derivatives ? &g : nullptr, hessian != nullptr ? &h : nullptr);
  if (!std::isfinite(density) || !derivatives) return reference.area * density;

  const auto& b = reference.shape_gradient;
  // J = dc/dx: dc0/dx_a = 2 B_a0 f0, dc1/dx_a = 2 B_a1 f1, dc2/dx_a = B_a0 f1 + B_a1 f0.
  Eigen::Matrix<double, 3, 9> jacobian;
  for (int a = 0; a < 3; ++a) {
    jacobian.block<1, 3>(0, 3 * a) = 2.0 * b(a, 0) * f.f0.transpose();
    jacobian.block<1, 3>(1, 3 * a) = 2.0 * b(a, 1) * f.f1.transpose();
    jacobian.block<1, 3>(2, 3 * a) = (b(a, 0) * f.f1 + b(a, 1) * f.f0).transpose();
  }
  if (gradient != nullptr) *gradient = reference.area * (jacobian.transpose() * g);
  if (hessian != nullptr) {
    *hessian = reference.area * (jacobian.transpose() * h * jacobian);
    for (int a = 0; a < 3; ++a) {
      for (int bb = 0; bb < 3; ++bb) {
        const double geometric = 2.0 * g(0) * b(a, 0) * b(bb, 0) + 2.0 * g(1) * b(a, 1) * b(bb, 1) +
                                 g(2) * (b(a, 0) * b(bb, 1) + b(a, 1) * b(bb, 0));
        hessian->block<3, 3>(3 * a, 3 * bb).diagonal().array() += reference.area * geometric;
      }
    }
  }
  return reference.area * density;
}

MembraneStress membrane_stress(const WallMaterial& material, const MembraneReference& reference,
                               const Eigen::Matrix<double, 9, 1>& x) {
  const Eigen::Vector3d c = membrane_cauchy_green(reference, x);
  const Eigen::Matrix2d s = second_piola_kirchhoff(material, c);
  Eigen::Matrix2d cm;
  cm << c(0), c(2), c(2), c(1);
  // The membrane force per current length is F S F^T / J (J = sqrt(det C), the area ratio); its
  // nonzero eigenvalues are those of S C (similar to C^(1/2) S C^(1/2), so real).
  const Eigen::Matrix2d sc = s * cm;
  const double half_trace = 0.5 * sc.trace();
  const double discriminant = std::sqrt(std::fmax(0.0, half_trace * half_trace - sc.determinant()));
  const double area_ratio = std::sqrt(std::fmax(0.0, c(0) * c(1) - c(2) * c(2)));
  const double lambda3 = thickness_stretch(material, c);
  const double current_thickness = lambda3 * material.thickness;
  MembraneStress out{0.0, 0.0, 0.0, lambda3};
  if (area_ratio > 0.0 && current_thickness > 0.0) {
    out.sigma1 = (half_trace + discriminant) / (area_ratio * current_thickness);
    out.sigma2 = (half_trace - discriminant) / (area_ratio * current_thickness);
  }
  out.von_mises = std::sqrt(std::fmax(0.0, out.sigma1 * out.sigma1 - out.sigma1 * out.sigma2 + out.sigma2 * out.sigma2));
  return out;
}

}  // namespace growthuq::fe
