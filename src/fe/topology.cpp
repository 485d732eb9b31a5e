#include "fe/topology.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "growthuq/core/error.hpp"

namespace growthuq::fe {

MeshTopology build_topology(const TriangleMesh& mesh, bool mirror_y0) {
  MeshTopology topology;
  const long long n = mesh.positions.cols();
  std::unordered_map<long long, int> index;
  topology.face_edges.resize(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int u = mesh.faces[f][(k + 1) % 3], v = mesh.faces[f][(k + 2) % 3];
      const auto [it, inserted] = index.try_emplace(std::min(u, v) * n + std::max(u, v),
                                                    static_cast<int>(topology.edges.size()));
      if (inserted) {
        topology.edges.push_back({std::min(u, v), std::max(u, v)});
        topology.edge_faces.push_back({static_cast<int>(f), -1});
      } else {
        auto& faces = topology.edge_faces[static_cast<std::size_t>(it->second)];
        if (faces[1] >= 0) {
          throw InputError("mesh", "edge " + std::to_string(u) + "-" + std::to_string(v) +
                                       " is shared by more than two faces: expected a manifold surface");
        }
        faces[1] = static_cast<int>(f);
      }
      topology.face_edges[f][k] = it->second;
    }
  }
  const auto on_mirror = [&](int v) { return std::fabs(mesh.positions(1, v)) <= 1e-12; };
  topology.stencils.resize(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    BendingStencil& stencil = topology.stencils[f];
    for (int k = 0; k < 3; ++k) {
      stencil.vertices[static_cast<std::size_t>(k)] = mesh.faces[f][k];
      const int e = topology.face_edges[f][k];
      const auto& faces = topology.edge_faces[static_cast<std::size_t>(e)];
      const int other = faces[0] == static_cast<int>(f) ? faces[1] : faces[0];
      if (other >= 0) {
        const auto& t = mesh.faces[static_cast<std::size_t>(other)];
        const auto& edge = topology.edges[static_cast<std::size_t>(e)];
        int w = -1;
        for (int v : t) if (v != edge[0] && v != edge[1]) w = v;
        stencil.vertices[static_cast<std::size_t>(3 + k)] = w;
        stencil.edges[static_cast<std::size_t>(k)] = EdgeKind::interior;
      } else {
        const auto& edge = topology.edges[static_cast<std::size_t>(e)];
        stencil.vertices[static_cast<std::size_t>(3 + k)] = -1;
        stencil.edges[static_cast<std::size_t>(k)] =
            mirror_y0 && on_mirror(edge[0]) && on_mirror(edge[1]) ? EdgeKind::mirror : EdgeKind::free;
      }
    }
  }
  return topology;
}

}  // namespace growthuq::fe
