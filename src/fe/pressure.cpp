#include "fe/pressure.hpp"

#include <Eigen/Geometry>

namespace growthuq::fe {
namespace {

// [a]x, the matrix with [a]x b = a x b.
Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d m;
  m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return m;
}

}  // namespace

double face_volume(const Eigen::Matrix<double, 9, 1>& x, Eigen::Matrix<double, 9, 1>* gradient,
                   Eigen::Matrix<double, 9, 9>* hessian) {
  const Eigen::Vector3d x0 = x.segment<3>(0), x1 = x.segment<3>(3), x2 = x.segment<3>(6);
  if (gradient) {
    gradient->segment<3>(0) = x1.cross(x2) / 6.0;
    gradient->segment<3>(3) = x2.cross(x0) / 6.0;
    gradient->segment<3>(6) = x0.cross(x1) / 6.0;
  }
  if (hessian) {
    // dV/dx1 = (x2 x x0)/6 = [x2]x x0 / 6, so d2V/dx1 dx0 = [x2]x / 6; cyclically likewise.
    hessian->setZero();
    const Eigen::Matrix3d c0 = cross_matrix(x0) / 6.0, c1 = cross_matrix(x1) / 6.0,
                          c2 = cross_matrix(x2) / 6.0;
    hessian->block<3, 3>(3, 0) = c2;
    hessian->block<3, 3>(0, 3) = -c2;
    hessian->block<3, 3>(6, 3) = c0;
    hessian->block<3, 3>(3, 6) = -c0;
    hessian->block<3, 3>(0, 6) = c1;
    hessian->block<3, 3>(6, 0) = -c1;
  }
  return x0.dot(x1.cross(x2)) / 6.0;
}

double enclosed_volume(const Eigen::Matrix3Xd& positions, const std::vector<std::array<int, 3>>& faces) {
  double volume = 0.0;
  for (const auto& f : faces) {
    volume += positions.col(f[0]).dot(positions.col(f[1]).cross(positions.col(f[2])));
  }
  return volume / 6.0;
}

}  // namespace growthuq::fe
