// The clamped semi-cylindrical shell under a point load of Sze, Liu and Lo 2004 (Finite
// Elements in Analysis and Design 40:1551, section 3.7, isotropic case): its data, reference
// load-deflection values and a structured triangle mesh laid out for the model's mirror plane.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "fe/mesh.hpp"

namespace growthuq::testing {

// Sze et al. 2004, section 3.7: radius 1.016, length 3.048, thickness 0.03, E = 2.0685e7,
// nu = 0.3; one curved end clamped, the straight edges held in the plane of the cut with their
// rotation about the axis blocked (the symmetry of a whole cylinder, which the model's mirror
// plane is), the other end free and loaded at its crown by a radial force P up to 2000.
struct SemicylinderData {
  static constexpr double radius = 1.016;
  static constexpr double length = 3.048;
  static constexpr double thickness = 0.03;
  static constexpr double young = 2.0685e7;
  static constexpr double poisson = 0.3;
  static constexpr double max_load = 2000.0;
};

// Sze et al. 2004's table for the isotropic semi-cylinder (their 40 x 40 Abaqus S4R model, the
// commonly used reference): P / Pmax and the inward deflection under the load. Transcribed as
// published there; the same figures are in MBDyn's tests/plates/sze2004/sze37/sze37_ref.dat and
// FEniCS-Shells' nonlinear Naghdi semi-cylinder demo (both scaled by 100 there).
struct LoadDeflection {
  double load_fraction;
  double deflection;
};
inline const std::vector<LoadDeflection>& semicylinder_reference() {
  static const std::vector<LoadDeflection> table{
      {0.05, 0.05421}, {0.10, 0.16100}, {0.125, 0.22195}, {0.15, 0.27657}, {0.175, 0.32700},
      {0.20, 0.37582}, {0.225, 0.42633}, {0.25, 0.48537}, {0.275, 0.56355}, {0.30, 0.66410},
      {0.325, 0.79810}, {0.35, 0.94669}, {0.40, 1.13704}, {0.45, 1.24751}, {0.50, 1.32653},
      {0.55, 1.38920}, {0.60, 1.44185}, {0.65, 1.48770}, {0.70, 1.52863}, {0.75, 1.56584},
      {0.80, 1.60015}, {0.85, 1.63211}, {0.90, 1.66200}, {0.95, 1.68973}, {1.00, 1.71505}};
  return table;
}

// The semi-cylinder as half of a tube about the z axis: (R cos t, R sin t, z), t in [0, pi], so
// that the straight edges lie in the mirror plane y = 0 (vertices exactly there), the clamped
// end in z = 0 and the loaded crown at (0, R, L). The clamp is the end ring plus one ghost ring
// at z = -L / axial_segments, both fixed: with the discrete bending of a face and its
// neighbours, fixing two rings fixes the end's rotation as well as its position.
struct SemicylinderMesh {
  fe::TriangleMesh mesh;
  std::vector<int> clamped;  // vertices of the two fixed rings
  int crown = -1;            // the loaded vertex (0, R, L)
};

// `alternating`: quads split along alternating diagonals, else all along the same one. The
// bending element is softer on the alternating pattern where a free edge is near (measured: 32 x
// 32 cells, P/Pmax = 0.1, deflection 0.208 alternating, 0.155 uniform, reference 0.161), so the
// benchmark uses the uniform split. hoop_segments must be even (the crown is a vertex).
//
// `hoop_grading` g in [0, 1): the hoop angle of column c is t = pi (u - g sin(4 pi u) / (4 pi)),
// u = c / hoop_segments, so the cells are 1 - g times the uniform width at the straight edges and
// at the crown and 1 + g times it at 45 degrees. Why: past P/Pmax = 0.5 the wall folds along the
// straight edges, where the symmetry holds it normal to the plane y = 0, in a boundary layer of
// the bending length sqrt(R t) = 0.17, which uniform cells of pi R / 48 = 0.066 barely resolve
// (measured: on 24 x 24 uniform cells the fold is one cell wide, and the path jumps between
// P/Pmax = 0.875 and 0.9 from w = 1.79 to 1.95; with g = 0.6 the same cell count follows the
// reference without a jump).
//
// `axial_grading` b in [0, 1): ring r lies at z = L (v - b sin(2 pi v) / (2 pi)), v = r /
// axial_segments, so the rings are 1 - b times the uniform spacing at the clamp and at the loaded
// end and 1 + b times it half way. Why: the deflection at small loads is set by the bending near
// the point load and the clamp (measured, hoop-graded 48-cell rings: the deflection at P/Pmax =
// 0.05 is 0.0656, 0.0603 and 0.0576 with 24, 36 and 48 uniform rings, 0.0540 with 48 graded ones,
// reference 0.0542). The map is odd in v, so the ghost ring mirrors the first ring through z = 0.
inline SemicylinderMesh make_semicylinder_mesh(int hoop_segments, int axial_segments, bool alternating = false,
                                               double hoop_grading = 0.0, double axial_grading = 0.0) {
  const double radius = SemicylinderData::radius;
  const double length = SemicylinderData::length;
  SemicylinderMesh out;
  const int columns = hoop_segments + 1;
  const int rings = axial_segments + 2;  // the ghost ring, then z = 0 ... L
  out.mesh.positions.resize(3, columns * rings);
  auto index = [columns](int ring, int column) { return ring * columns + column; };
  for (int r = 0; r < rings; ++r) {
    const double v = static_cast<double>(r - 1) / axial_segments;
    const double z = length * (v - axial_grading * std::sin(2 * std::numbers::pi * v) / (2 * std::numbers::pi));
    for (int c = 0; c < columns; ++c) {
      const double u = static_cast<double>(c) / hoop_segments;
      const double t = std::numbers::pi * (u - hoop_grading * std::sin(4 * std::numbers::pi * u) / (4 * std::numbers::pi));
      // The straight edges exactly in y = 0, the crown exactly at x = 0.
      const double x = (2 * c == hoop_segments) ? 0.0 : radius * std::cos(t);
      const double y = (c == 0 || c == hoop_segments) ? 0.0 : radius * std::sin(t);
      out.mesh.positions.col(index(r, c)) = Eigen::Vector3d(x, y, z);
      if (r <= 1) out.clamped.push_back(index(r, c));
    }
  }
  // Faces counter-clockwise seen from outside: d/dt x d/dz points outwards.
  for (int r = 0; r + 1 < rings; ++r) {
    for (int c = 0; c < hoop_segments; ++c) {
      const int a = index(r, c), b = index(r, c + 1), e = index(r + 1, c + 1), d = index(r + 1, c);
      // Uniform: one diagonal on the half c < hoop_segments / 2, mirrored on the other half, so
      // that the mesh is symmetric about the crown's plane x = 0 as the problem is (diagonals all
      // one way make a lattice without that symmetry, whose path leaves the symmetric branch).
      const bool first_half = 2 * c < hoop_segments;
      if (alternating ? (r + c) % 2 == 0 : first_half) {
        out.mesh.faces.push_back({a, b, e});
        out.mesh.faces.push_back({a, e, d});
      } else {
        out.mesh.faces.push_back({a, b, d});
        out.mesh.faces.push_back({b, e, d});
      }
    }
  }
  out.crown = index(rings - 1, hoop_segments / 2);
  return out;
}

}  // namespace growthuq::testing
