// Mesh quality for the rotation-free bending element: the generated meshes are improved, after
// their refinement, by valence-balancing edge flips and a few passes of tangential smoothing.
//
// Why. Longest-edge bisection (mesh.cpp) leaves a "4-8" triangulation near the probe: vertices
// of valence 4 and 8, squares with alternating diagonals. On such meshes the quadratic patch fit
// of the bending element (bending.hpp) has a checkerboard mode, a uniform mean curvature plus a
// face-alternating twist, that relieves part of any real mean curvature at little cost: the
// effective bending modulus tends to (1 - (1 + nu)^2 / 4) B, so a probe's stiffness (which goes
// as sqrt(B)) comes out 13 % soft at nu = 0 and 24 % at nu = 0.3, whatever the mesh size.
// Meshes whose interior vertices have valence 5-7 do not have the mode (tests/fe/test_mesh.cpp
// measures both the valences and, through the Vella sphere, the stiffness).
#pragma once

#include <Eigen/Core>

#include <array>
#include <functional>
#include <vector>

namespace growthuq::fe {

struct ValenceCounts {
  int interior = 0;    // vertices not on an open boundary (those on the mirror plane y = 0 included)
  int irregular = 0;   // of them, those of valence 4 or less, or 8 or more (in the full model)
};

// Flips interior edges while a flip brings the four vertices it touches closer to the ideal
// valence (6 inside, counted in the full model on the mirror plane y = 0, 4 on an open
// boundary), each vertex's defect weighted by `importance` (where the probe presses, regularity
// matters most: elsewhere the mesh only inflates); a flip must leave two well-shaped triangles
// that fold by less than 25 degrees, and no edge longer than `size` allows. Then moves every interior vertex part of the way towards
// the centroid of its neighbours, projected back onto the exact surface by `project`, unless that
// would shrink the smallest angle around it, turn a face over or stretch an edge beyond `size`. A vertex on the mirror plane
// slides along it (`project` must keep y = 0); vertices on an open boundary and those `pinned`
// (the probe's focus) never move. Orientation (counter-clockwise seen from outside) is kept.
void improve_triangulation(std::vector<Eigen::Vector3d>& points, std::vector<std::array<int, 3>>& faces,
                           const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& project,
                           const std::function<double(const Eigen::Vector3d&)>& importance,
                           const std::function<double(const Eigen::Vector3d&)>& size,
                           const std::function<bool(const Eigen::Vector3d&)>& pinned);

// The valences of the vertices for which `counted` is true (all when it is empty).
ValenceCounts valence_counts(const std::vector<Eigen::Vector3d>& points, const std::vector<std::array<int, 3>>& faces,
                             const std::function<bool(const Eigen::Vector3d&)>& counted = {});

}  // namespace growthuq::fe
