// The rigid obstacles the wall meets (the probe, a sphere; the substrate, a plane) and the one
// description of their shape every contact method uses: the signed gap of a point, the
// obstacle's outward normal there and the curvature of the gap, and the projection of a point
// out of the obstacle. Dimensionless (lengths / d0).
#pragma once

#include <Eigen/Dense>

#include <vector>

namespace growthuq::fe {

struct RigidSphere {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

// The half space normal . (x - point) >= 0 is free; the rest is the obstacle.
struct RigidPlane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // unit
};

// The gap g(x) >= 0 outside the obstacle, its gradient `normal` (unit, pointing out of the
// obstacle) and its Hessian curvature (I - normal normal^T): 1/|x - c| for a sphere, 0 for a
// plane. Moving x by -gap along `normal` puts it on the surface (exactly, for both shapes).
struct ObstacleGap {
  double gap = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();
  double curvature = 0.0;
};

ObstacleGap gap_to(const RigidSphere&, const Eigen::Vector3d& x);
ObstacleGap gap_to(const RigidPlane&, const Eigen::Vector3d& x);

// Every obstacle of a problem. Obstacle index o counts the spheres first, then the planes.
struct Obstacles {
  std::vector<RigidSphere> spheres;
  std::vector<RigidPlane> planes;

  std::size_t size() const { return spheres.size() + planes.size(); }
  bool empty() const { return spheres.empty() && planes.empty(); }
  ObstacleGap gap(std::size_t obstacle, const Eigen::Vector3d& x) const;
  // The obstacle whose gap at x is smallest (-1 when there is none), and that gap.
  int nearest(const Eigen::Vector3d& x, ObstacleGap& gap) const;
  // x moved out of every obstacle it lies deeper in than `cap` >= 0, back to a penetration of
  // `cap` (radially for a sphere, along the normal for a plane).
  Eigen::Vector3d limited(Eigen::Vector3d x, double cap) const;
};

}  // namespace growthuq::fe
