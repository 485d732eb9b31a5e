#include "fe/contact.hpp"

#include <Eigen/Dense>

namespace growthuq::fe {

PenaltyValue penalty(const PenaltyLaw& law, double s) {
  const double k = law.stiffness, eps = law.smoothing;
  if (s <= 0) return {};
  if (s < eps) return {k * s * s * s / (6 * eps), k * s * s / (2 * eps), k * s / eps};
  return {k * (s * s / 2 - eps * s / 2 + eps * eps / 6), k * (s - eps / 2), k};
}

// One formula for every shape (obstacles.hpp): the penetration s = -gap has ds/dx = -n and
// d2s/dx2 = -c (I - n n^T), so d2 phi/dx2 = phi'' n n^T + phi' c (I - n n^T) with a minus sign.
double obstacle_contact(const ObstacleGap& g, const PenaltyLaw& law, Eigen::Vector3d* gradient,
                        Eigen::Matrix3d* hessian) {
  const double s = -g.gap;
  if (s <= 0) {
    if (gradient) gradient->setZero();
    if (hessian) hessian->setZero();
    return 0.0;
  }
  const PenaltyValue v = penalty(law, s);
  if (gradient) *gradient = -v.slope * g.normal;
  if (hessian) {
    const Eigen::Matrix3d nn = g.normal * g.normal.transpose();
    *hessian = v.curvature * nn - v.slope * g.curvature * (Eigen::Matrix3d::Identity() - nn);
  }
  return v.energy;
}

double sphere_contact(const RigidSphere& sphere, const PenaltyLaw& law, const Eigen::Vector3d& x,
                      Eigen::Vector3d* gradient, Eigen::Matrix3d* hessian, double* penetration_out) {
  const ObstacleGap g = gap_to(sphere, x);
  if (penetration_out) *penetration_out = -g.gap;
  if (x == sphere.centre) {  // no normal: no force
    if (gradient) gradient->setZero();
    if (hessian) hessian->setZero();
    return 0.0;
  }
  return obstacle_contact(g, law, gradient, hessian);
}

double plane_contact(const RigidPlane& plane, const PenaltyLaw& law, const Eigen::Vector3d& x,
                     Eigen::Vector3d* gradient, Eigen::Matrix3d* hessian, double* penetration_out) {
  const ObstacleGap g = gap_to(plane, x);
  if (penetration_out) *penetration_out = -g.gap;
  return obstacle_contact(g, law, gradient, hessian);
}

}  // namespace growthuq::fe
