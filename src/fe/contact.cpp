#include "fe/contact.hpp"

#include <Eigen/Dense>

namespace growthuq::fe {

PenaltyValue penalty(const PenaltyLaw& law, double s) {
  const double k = law.stiffness, eps = law.smoothing;
  if (s <= 0) return {};
  if (s < eps) return {k * s * s * s / (6 * eps), k * s * s / (2 * eps), k * s / eps};
  return {k * (s * s / 2 - eps * s / 2 + eps * eps / 6), k * (s - eps / 2), k};
}

double sphere_contact(const RigidSphere& sphere, const PenaltyLaw& law, const Eigen::Vector3d& x,
                      Eigen::Vector3d* gradient, Eigen::Matrix3d* hessian, double* penetration_out) {
  const Eigen::Vector3d r = x - sphere.centre;
  const double distance = r.norm();
  const double s = sphere.radius - distance;
  if (penetration_out) *penetration_out = s;
  if (s <= 0 || distance == 0) {
    if (gradient) gradient->setZero();
    if (hessian) hessian->setZero();
    return 0.0;
  }
  const PenaltyValue v = penalty(law, s);
  const Eigen::Vector3d n = r / distance;  // ds/dx = -n
  if (gradient) *gradient = -v.slope * n;
  if (hessian) {
    // d2 phi/dx2 = phi'' n n^T + phi' d2s/dx2, d2s/dx2 = -(I - n n^T)/|x - c|.
    const Eigen::Matrix3d nn = n * n.transpose();
    *hessian = v.curvature * nn - (v.slope / distance) * (Eigen::Matrix3d::Identity() - nn);
  }
  return v.energy;
}

double plane_contact(const RigidPlane& plane, const PenaltyLaw& law, const Eigen::Vector3d& x,
                     Eigen::Vector3d* gradient, Eigen::Matrix3d* hessian, double* penetration_out) {
  const double s = -plane.normal.dot(x - plane.point);
  if (penetration_out) *penetration_out = s;
  const PenaltyValue v = penalty(law, s);
  if (gradient) *gradient = -v.slope * plane.normal;
  if (hessian) *hessian = v.curvature * plane.normal * plane.normal.transpose();
  return v.energy;
}

}  // namespace growthuq::fe
