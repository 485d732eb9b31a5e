#include "fe/obstacles.hpp"

#include <limits>

namespace growthuq::fe {

ObstacleGap gap_to(const RigidSphere& sphere, const Eigen::Vector3d& x) {
  const Eigen::Vector3d r = x - sphere.centre;
  const double distance = r.norm();
  if (distance == 0.0) return {-sphere.radius, Eigen::Vector3d::UnitX(), 0.0};  // the centre: any direction
  return {distance - sphere.radius, r / distance, 1.0 / distance};
}

ObstacleGap gap_to(const RigidPlane& plane, const Eigen::Vector3d& x) {
  return {plane.normal.dot(x - plane.point), plane.normal, 0.0};
}

ObstacleGap Obstacles::gap(std::size_t obstacle, const Eigen::Vector3d& x) const {
  return obstacle < spheres.size() ? gap_to(spheres[obstacle], x) : gap_to(planes[obstacle - spheres.size()], x);
}

int Obstacles::nearest(const Eigen::Vector3d& x, ObstacleGap& gap) const {
  int best = -1;
  gap.gap = std::numeric_limits<double>::infinity();
  for (std::size_t o = 0; o < size(); ++o) {
    const ObstacleGap g = this->gap(o, x);
    if (g.gap < gap.gap) {
      gap = g;
      best = static_cast<int>(o);
    }
  }
  return best;
}

Eigen::Vector3d Obstacles::limited(Eigen::Vector3d x, double cap) const {
  for (std::size_t o = 0; o < size(); ++o) {
    const ObstacleGap g = gap(o, x);
    if (-g.gap > cap) x += (-g.gap - cap) * g.normal;
  }
  return x;
}

}  // namespace growthuq::fe
