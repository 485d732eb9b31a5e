// Turgor as a follower load: the potential -p V of the enclosed volume, V = (1/6) sum over faces
// of x0 . (x1 x x2) (the divergence theorem with the origin on the tube axis in the end plane,
// so that the mirror plane y = 0 and the open end disk z = 0, both through the origin, add
// nothing and the half model encloses exactly half the tube's volume).
#pragma once

#include <Eigen/Dense>

#include <array>
#include <vector>

namespace growthuq::fe {

// Volume contribution of one face x = (x0, x1, x2) stacked; exact gradient and Hessian
// (nullptr = not wanted). The Hessian is constant in each pair of vertices: d2V/dxi dxj is
// (1/6) times the cross-product matrix of the third vertex, with the sign of the permutation.
double face_volume(const Eigen::Matrix<double, 9, 1>& x, Eigen::Matrix<double, 9, 1>* gradient,
                   Eigen::Matrix<double, 9, 9>* hessian);

// Enclosed volume of a triangulated surface (whole or cut by planes through the origin).
double enclosed_volume(const Eigen::Matrix3Xd& positions, const std::vector<std::array<int, 3>>& faces);

}  // namespace growthuq::fe
