#include "fe/mesh_quality.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>
#include <unordered_set>

namespace growthuq::fe {
namespace {

using Eigen::Vector3d;
using Faces = std::vector<std::array<int, 3>>;

long long edge_key(int u, int v, long long stride) { return std::min(u, v) * stride + std::max(u, v); }

// The smallest interior angle of a triangle, in radians (0 for a degenerate one).
double smallest_angle(const Vector3d& a, const Vector3d& b, const Vector3d& c) {
  const std::array<Vector3d, 3> p = {a, b, c};
  double smallest = std::numbers::pi;
  for (int k = 0; k < 3; ++k) {
    const Vector3d u = p[(k + 1) % 3] - p[k], w = p[(k + 2) % 3] - p[k];
    const double nu = u.norm(), nw = w.norm();
    if (!(nu > 0 && nw > 0)) return 0.0;
    smallest = std::min(smallest, std::acos(std::clamp(u.dot(w) / (nu * nw), -1.0, 1.0)));
  }
  return smallest;
}

Vector3d face_normal(const std::vector<Vector3d>& x, int a, int b, int c) {
  return (x[b] - x[a]).cross(x[c] - x[a]);
}

struct Adjacency {
  std::unordered_map<long long, std::array<int, 2>> edge_faces;  // second -1 on the boundary
  std::vector<int> valence;
  std::vector<char> boundary;
  std::vector<char> mirror;  // boundary vertices on the plane y = 0
};

Adjacency adjacency(const std::vector<Vector3d>& x, const Faces& faces, int vertex_count) {
  Adjacency adj;
  const long long stride = vertex_count;
  adj.edge_faces.reserve(faces.size() * 2);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const long long key = edge_key(faces[f][k], faces[f][(k + 1) % 3], stride);
      auto [it, inserted] = adj.edge_faces.try_emplace(key, std::array<int, 2>{static_cast<int>(f), -1});
      if (!inserted) it->second[1] = static_cast<int>(f);
    }
  }
  adj.valence.assign(static_cast<std::size_t>(vertex_count), 0);
  adj.boundary.assign(static_cast<std::size_t>(vertex_count), 0);
  for (const auto& [key, pair] : adj.edge_faces) {
    const int u = static_cast<int>(key / stride), v = static_cast<int>(key % stride);
    ++adj.valence[static_cast<std::size_t>(u)], ++adj.valence[static_cast<std::size_t>(v)];
    if (pair[1] < 0) adj.boundary[static_cast<std::size_t>(u)] = adj.boundary[static_cast<std::size_t>(v)] = 1;
  }
  // On the mirror plane: every boundary edge at the vertex lies in y = 0 (so a corner where the
  // mirror plane meets an open end is not one, and never slides).
  adj.mirror = adj.boundary;
  for (const auto& [key, pair] : adj.edge_faces) {
    if (pair[1] >= 0) continue;
    const auto u = static_cast<std::size_t>(key / stride), v = static_cast<std::size_t>(key % stride);
    if (!(std::fabs(x[u].y()) <= 1e-12 && std::fabs(x[v].y()) <= 1e-12)) adj.mirror[u] = adj.mirror[v] = 0;
  }
  return adj;
}

// A vertex's valence as the full model sees it, after `change` more edges, and its ideal: on the
// mirror plane y = 0, 2 (v - 1) (the mirror image adds its v - 2 interior neighbours) against 6;
// elsewhere on the boundary (an open end) v against 4; inside, v against 6.
struct Valence {
  int value, ideal;
};
Valence valence_of(const Adjacency& adj, std::size_t v, int change = 0) {
  const int valence = adj.valence[v] + change;
  if (adj.mirror[v]) return {2 * (valence - 1), 6};
  return {valence, adj.boundary[v] ? 4 : 6};
}

// The squared distance of a vertex's valence from the ideal, weighted by its importance.
double valence_defect(const Adjacency& adj, const std::vector<double>& weight, int v, int change) {
  const auto i = static_cast<std::size_t>(v);
  const Valence valence = valence_of(adj, i, change);
  const double d = valence.value - valence.ideal;
  return weight[i] * d * d;
}

// The third vertex of face f, the one not on edge (u, v).
int opposite(const std::array<int, 3>& face, int u, int v) {
  for (int w : face) {
    if (w != u && w != v) return w;
  }
  return -1;
}

// One pass of flips over the edges as they were at its start; returns the number of flips.
int flip_pass(const std::vector<Vector3d>& x, const std::vector<double>& weight,
              const std::function<double(const Vector3d&)>& size, Faces& faces) {
  const int n = static_cast<int>(x.size());
  Adjacency adj = adjacency(x, faces, n);
  std::vector<char> touched(faces.size(), 0);
  std::unordered_set<long long> created;  // edges made by this pass's flips
  const double fold_limit = std::cos(25.0 * std::numbers::pi / 180.0);
  int flips = 0;
  for (const auto& [key, pair] : adj.edge_faces) {
    const int f1 = pair[0], f2 = pair[1];
    if (f2 < 0 || touched[static_cast<std::size_t>(f1)] || touched[static_cast<std::size_t>(f2)]) continue;
    const int a = static_cast<int>(key / n), b = static_cast<int>(key % n);
    const int c = opposite(faces[static_cast<std::size_t>(f1)], a, b);
    const int d = opposite(faces[static_cast<std::size_t>(f2)], a, b);
    if (c < 0 || d < 0 || c == d) continue;
    const long long new_edge = edge_key(c, d, n);
    if (adj.edge_faces.count(new_edge) != 0 || created.count(new_edge) != 0) continue;  // it exists already
    if (size && (x[c] - x[d]).norm() > size(0.5 * (x[c] + x[d]))) continue;  // longer than the mesh allows
    if (adj.valence[static_cast<std::size_t>(a)] <= 3 || adj.valence[static_cast<std::size_t>(b)] <= 3) continue;
    const double before = valence_defect(adj, weight, a, 0) + valence_defect(adj, weight, b, 0) + valence_defect(adj, weight, c, 0) +
                          valence_defect(adj, weight, d, 0);
    const double after = valence_defect(adj, weight, a, -1) + valence_defect(adj, weight, b, -1) + valence_defect(adj, weight, c, 1) +
                         valence_defect(adj, weight, d, 1);
    if (!(after < before)) continue;
    // Orient: face f1 runs u -> w along the shared edge, so f1 = (u, w, c), f2 = (w, u, d), and the
    // flipped faces (u, d, c), (d, w, c) keep the orientation.
    const auto& face1 = faces[static_cast<std::size_t>(f1)];
    int u = a, w = b;
    for (int k = 0; k < 3; ++k) {
      if (face1[k] == b && face1[(k + 1) % 3] == a) u = b, w = a;
    }
    const Vector3d old_normal = (face_normal(x, u, w, c).normalized() + face_normal(x, w, u, d).normalized());
    const Vector3d n1 = face_normal(x, u, d, c), n2 = face_normal(x, d, w, c);
    if (!(n1.dot(old_normal) > 0 && n2.dot(old_normal) > 0)) continue;  // not convex
    if (n1.normalized().dot(n2.normalized()) < fold_limit) continue;
    const double old_quality = std::min(smallest_angle(x[u], x[w], x[c]), smallest_angle(x[w], x[u], x[d]));
    const double new_quality = std::min(smallest_angle(x[u], x[d], x[c]), smallest_angle(x[d], x[w], x[c]));
    // Valence may cost some shape, not much: the smoothing that follows evens the angles out.
    if (new_quality < std::min(0.5 * old_quality, 20.0 * std::numbers::pi / 180.0)) continue;
    faces[static_cast<std::size_t>(f1)] = {u, d, c};
    faces[static_cast<std::size_t>(f2)] = {d, w, c};
    touched[static_cast<std::size_t>(f1)] = touched[static_cast<std::size_t>(f2)] = 1;
    created.insert(new_edge);
    --adj.valence[static_cast<std::size_t>(a)], --adj.valence[static_cast<std::size_t>(b)];
    ++adj.valence[static_cast<std::size_t>(c)], ++adj.valence[static_cast<std::size_t>(d)];
    ++flips;
  }
  return flips;
}

// Tangential smoothing: each interior vertex moves half way to the centroid of its neighbours,
// projected onto the surface, if the smallest angle of its faces does not shrink.
void smoothing_pass(std::vector<Vector3d>& x, const Faces& faces,
                    const std::function<Vector3d(const Vector3d&)>& project,
                    const std::function<double(const Vector3d&)>& size, const std::function<bool(const Vector3d&)>& pinned) {
  const int n = static_cast<int>(x.size());
  const Adjacency adj = adjacency(x, faces, n);
  std::vector<std::vector<int>> vertex_faces(static_cast<std::size_t>(n));
  std::vector<std::unordered_set<int>> neighbours(static_cast<std::size_t>(n));
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const auto v = static_cast<std::size_t>(faces[f][k]);
      vertex_faces[v].push_back(static_cast<int>(f));
      neighbours[v].insert(faces[f][(k + 1) % 3]);
      neighbours[v].insert(faces[f][(k + 2) % 3]);
    }
  }
  auto worst_angle = [&](std::size_t v) {
    double worst = std::numbers::pi;
    for (int f : vertex_faces[v]) {
      const auto& t = faces[static_cast<std::size_t>(f)];
      worst = std::min(worst, smallest_angle(x[t[0]], x[t[1]], x[t[2]]));
    }
    return worst;
  };
  for (std::size_t v = 0; v < x.size(); ++v) {
    if ((adj.boundary[v] && !adj.mirror[v]) || neighbours[v].empty() || (pinned && pinned(x[v]))) continue;
    // A vertex on the mirror plane slides along it, towards its two neighbours on the plane.
    Vector3d centroid = Vector3d::Zero();
    int count = 0;
    for (int w : neighbours[v]) {
      if (adj.mirror[v] && !adj.mirror[static_cast<std::size_t>(w)]) continue;
      centroid += x[static_cast<std::size_t>(w)];
      ++count;
    }
    if (count == 0) continue;
    centroid /= count;
    const Vector3d old = x[v];
    const double before = worst_angle(v);
    std::vector<Vector3d> old_normals;
    for (int f : vertex_faces[v]) {
      const auto& t = faces[static_cast<std::size_t>(f)];
      old_normals.push_back(face_normal(x, t[0], t[1], t[2]));
    }
    x[v] = project(old + 0.5 * (centroid - old));
    bool oriented = true;  // no face turned over
    for (std::size_t i = 0; i < vertex_faces[v].size(); ++i) {
      const auto& t = faces[static_cast<std::size_t>(vertex_faces[v][i])];
      if (!(face_normal(x, t[0], t[1], t[2]).dot(old_normals[i]) > 0)) oriented = false;
    }
    bool short_enough = true;  // every edge still fits the size field
    for (int w : neighbours[v]) {
      const Vector3d& q = x[static_cast<std::size_t>(w)];
      if (size && (x[v] - q).norm() > size(0.5 * (x[v] + q)) && (old - q).norm() <= size(0.5 * (old + q))) {
        short_enough = false;
      }
    }
    if (!oriented || !short_enough || worst_angle(v) < before) x[v] = old;
  }
}

}  // namespace

void improve_triangulation(std::vector<Vector3d>& points, Faces& faces,
                           const std::function<Vector3d(const Vector3d&)>& project,
                           const std::function<double(const Vector3d&)>& importance,
                           const std::function<double(const Vector3d&)>& size, const std::function<bool(const Vector3d&)>& pinned) {
  for (int round = 0; round < 5; ++round) {
    std::vector<double> weight(points.size(), 1.0);
    if (importance) {
      for (std::size_t v = 0; v < points.size(); ++v) weight[v] = importance(points[v]);
    }
    for (int pass = 0; pass < 50 && flip_pass(points, weight, size, faces) > 0; ++pass) {
    }
    for (int pass = 0; pass < 3; ++pass) smoothing_pass(points, faces, project, size, pinned);
  }
}

ValenceCounts valence_counts(const std::vector<Vector3d>& points, const Faces& faces,
                             const std::function<bool(const Vector3d&)>& counted) {
  const int vertex_count = static_cast<int>(points.size());
  const Adjacency adj = adjacency(points, faces, vertex_count);
  ValenceCounts counts;
  for (std::size_t v = 0; v < points.size(); ++v) {
    if (adj.valence[v] == 0 || (adj.boundary[v] && !adj.mirror[v])) continue;
    if (counted && !counted(points[v])) continue;
    const int valence = valence_of(adj, v).value;
    ++counts.interior;
    if (valence <= 4 || valence >= 8) ++counts.irregular;
  }
  return counts;
}

}  // namespace growthuq::fe
