// Frictionless contact of the wall's nodes with the rigid obstacles (obstacles.hpp) by a smooth
// penalty on the penetration, kept beside the exact active-set method (active_set_contact.hpp) for
// comparison, and nodal point loads. The penalty is dimensionless (force over E d0 per unit
// penetration over d0), so the solution scales with E; the load stepping raises it until the
// deepest penetration is below its tolerance.
#pragma once

#include <Eigen/Dense>

#include "fe/obstacles.hpp"

namespace growthuq::fe {

// Energy of a penetration s = -gap > 0: a cubic k s^3/(6 eps) up to s = eps, then the quadratic
// k (s^2/2 - eps s/2 + eps^2/6), matched in value, slope and curvature (C2, so that Newton's
// method sees a continuous Hessian when a node enters contact). The normal force is k s - k eps/2
// in the quadratic range.
struct PenaltyLaw {
  double stiffness = 1.0;   // k
  double smoothing = 0.0;   // eps >= 0
};

struct PenaltyValue {
  double energy = 0.0, slope = 0.0, curvature = 0.0;  // phi(s), phi'(s), phi''(s)
};
PenaltyValue penalty(const PenaltyLaw&, double penetration);

// Penalty energy of a node at gap g from an obstacle, with its gradient and Hessian with respect
// to the node's position (nullptr = not wanted).
double obstacle_contact(const ObstacleGap& g, const PenaltyLaw&, Eigen::Vector3d* gradient, Eigen::Matrix3d* hessian);
// Penalty energy of a node at x against an obstacle, with its exact gradient and Hessian with
// respect to x (nullptr = not wanted). `penetration_out`, if given, receives -gap.
double sphere_contact(const RigidSphere&, const PenaltyLaw&, const Eigen::Vector3d& x,
                      Eigen::Vector3d* gradient, Eigen::Matrix3d* hessian,
                      double* penetration_out = nullptr);
double plane_contact(const RigidPlane&, const PenaltyLaw&, const Eigen::Vector3d& x,
                     Eigen::Vector3d* gradient, Eigen::Matrix3d* hessian,
                     double* penetration_out = nullptr);

// A dead load at one node: the potential -force . x.
struct PointLoad {
  int node = 0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // / (E d0^2)
};

}  // namespace growthuq::fe
