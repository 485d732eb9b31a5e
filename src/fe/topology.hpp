// Connectivity of a triangulated wall: its edges, the faces on either side, and for every face
// the bending stencil (the face's vertices and the three vertices across its edges) with the
// kind of each edge: interior, on the mirror plane y = 0 (half model), or free (the open
// pinned end ring).
#pragma once

#include <array>
#include <vector>

#include "fe/bending.hpp"
#include "fe/mesh.hpp"

namespace growthuq::fe {

struct MeshTopology {
  std::vector<std::array<int, 2>> edges;       // vertex pairs, smaller index first
  std::vector<std::array<int, 2>> edge_faces;  // second is -1 on a boundary edge
  std::vector<std::array<int, 3>> face_edges;  // edge opposite local vertex k of each face
  std::vector<BendingStencil> stencils;        // one per face; a missing wi is -1
};

// Boundary edges whose two vertices lie on y = 0 are mirror edges when `mirror_y0`, the others
// free. Throws InputError for an edge shared by more than two faces.
MeshTopology build_topology(const TriangleMesh& mesh, bool mirror_y0);

}  // namespace growthuq::fe
