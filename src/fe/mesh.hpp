// Triangulated mid-surfaces of the shell model: the capped tube and the sphere, graded towards
// the probe, and closed surfaces read from Wavefront OBJ or OFF files. Dimensionless: lengths
// are over d0, the unstressed mid-surface diameter.
#pragma once

#include <Eigen/Dense>

#include <array>
#include <string>
#include <vector>

#include "growthuq/fe/shell_fe_vocabulary.hpp"

namespace growthuq::fe {

struct TriangleMesh {
  Eigen::Matrix3Xd positions;             // reference (unstressed) positions, / d0
  std::vector<std::array<int, 3>> faces;  // counter-clockwise seen from outside
};

// Element sizes of a graded mesh: `finest` within `fine_radius` of the focus point (where the
// probe touches), growing linearly by `grading` per unit distance beyond it, up to `coarsest`
// around the circumference; along the tube's cylinder, far from the probe, rings may be up to
// `far_aspect` times `coarsest` apart (the inflated cylinder is uniform along its axis).
struct MeshSizing {
  double finest = 0.02;
  double fine_radius = 0.1;
  double grading = 0.35;
  double coarsest = 0.14;
  double far_aspect = 2.5;
  int max_faces = 400000;  // refusing a mesh beyond this bounds time and memory
};

// The wall's bending length sqrt(h0 R) (R = 1/2), over d0, for the thickness h0/d0: the width of
// its bending boundary layers, and what tells a wide probe from a narrow one.
double bending_length(double thickness);

// The sizing of a level for a probe of radius rho and a wall of bending length b = sqrt(h0 R)
// (R = 1/2): the finest size resolves the smaller of the two over a fine region 2 rho wide; a
// probe wider than b gets cells down to b/16 over a region b wide instead (mesh.cpp says why);
// each level is sqrt(2) finer than the one before it.
MeshSizing mesh_sizing(ShellFeMesh level, double probe_radius, double thickness);

// The capped tube of unit diameter: a cylinder from the open distal ring in the plane z = 0 to
// z = L - 1/2, closed by a hemisphere whose apex is at z = L. The cap is an octant-patch
// hemisphere (the apex has four triangles, no fan); the cylinder's rings share the cap's
// equator nodes. Half model: y >= 0, mirror nodes exactly at y = 0; the full model is the half
// and its mirror image. Graded by `sizing`
// around the surface point at z = L - a on the meridian x > 0.
TriangleMesh make_tube_mesh(double length, double probe_distance, bool half_model,
                            const MeshSizing& sizing);

// The sphere of unit diameter centred at the origin, from the octahedron, graded around the
// pole +x (where the probe presses). Half model: y >= 0.
TriangleMesh make_sphere_mesh(bool half_model, const MeshSizing& sizing);

// A closed triangulated surface from a Wavefront OBJ (.obj) or OFF (.off) file, lengths taken
// as / d0. Polygons with more than three vertices are split into fans. Validated: every edge
// shared by exactly two faces, consistently oriented, no degenerate faces, every vertex used,
// positive enclosed volume (outward orientation); otherwise one InputError naming the file,
// the line where it can, and what was expected.
TriangleMesh read_mesh_file(const std::string& path);

// The checks read_mesh_file applies, for a mesh from anywhere; `where` names it in messages.
void validate_closed_surface(const TriangleMesh& mesh, const std::string& where);

// The shell's bending element (bending.hpp) interpolates each face's three vertices and the far
// vertex of each neighbour across its edges: six different vertices. InputError "<where>: face
// F: two neighbouring faces share their far vertex V: ..." where two neighbours share it (around
// a vertex of only three faces, as every vertex of a tetrahedron), before the simulation (whose
// element failed without naming the file: "the six vertices ... lie on one conic").
// `mesh` must be a validated closed surface.
void require_bending_stencils(const TriangleMesh& mesh, const std::string& where);

// Smallest and largest edge length, for reports and tests.
struct EdgeLengthRange {
  double shortest = 0.0;
  double longest = 0.0;
};
EdgeLengthRange edge_length_range(const TriangleMesh& mesh);

}  // namespace growthuq::fe
