#include "fe/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

#include "fe/mesh_quality.hpp"
#include "growthuq/core/error.hpp"

namespace growthuq::fe {
namespace {

using Eigen::Vector3d;
using Projection = std::function<Vector3d(const Vector3d&)>;
constexpr double radius = 0.5;  // of the unit-diameter tube and sphere

// Points are merged by their coordinates rounded to 1e-10 (the generators place shared points
// by the same arithmetic, so they agree to round-off).
struct PointKey {
  long long x, y, z;
  bool operator<(const PointKey& other) const {
    return std::tie(x, y, z) < std::tie(other.x, other.y, other.z);
  }
};
PointKey key_of(const Vector3d& p) {
  auto q = [](double v) { return static_cast<long long>(std::llround(v * 1e10)); };
  return {q(p.x()), q(p.y()), q(p.z())};
}

class MeshBuilder {
 public:
  int add_point(const Vector3d& p) {
    auto [it, inserted] = index_.try_emplace(key_of(p), static_cast<int>(points_.size()));
    if (inserted) points_.push_back(p);
    return it->second;
  }
  void add_face(int a, int b, int c) { faces_.push_back({a, b, c}); }
  std::vector<Vector3d>& points() { return points_; }
  std::vector<std::array<int, 3>>& faces() { return faces_; }

 private:
  std::map<PointKey, int> index_;
  std::vector<Vector3d> points_;
  std::vector<std::array<int, 3>> faces_;
};

// One octant face A, B, C (unit vectors) of the octahedron, subdivided n times and mapped to the
// sphere of `radius` about `centre`. The barycentric coordinates are warped by sin(pi/2 t)
// before normalising so that the nodes along each octant edge are equally spaced in angle.
void add_octant(MeshBuilder& builder, const Vector3d& a, const Vector3d& b, const Vector3d& c,
                int n, const Vector3d& centre, double sphere_radius) {
  const double half_pi = std::numbers::pi / 2;
  auto point = [&](int i, int j) {
    const double tb = static_cast<double>(i) / n, tc = static_cast<double>(j) / n;
    const double ta = static_cast<double>(n - i - j) / n;  // exactly 0 on the edge B-C
    Vector3d p = std::sin(half_pi * ta) * a + std::sin(half_pi * tb) * b +
                 std::sin(half_pi * tc) * c;
    return builder.add_point(centre + sphere_radius * p.normalized());
  };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i + j < n; ++i) {
      builder.add_face(point(i, j), point(i + 1, j), point(i, j + 1));
      if (i + j + 1 < n) builder.add_face(point(i + 1, j), point(i + 1, j + 1), point(i, j + 1));
    }
  }
}

// Conforming red-green refinement (Bank, Sherman and Weiser 1983): every edge longer than the
// size field at its midpoint is marked; a face with two marked edges has its third marked too;
// then faces with three marked edges are cut into four similar ones ("red") and faces with one
// into two through that edge ("green"). Red refinement keeps a regular mesh regular: the new
// vertices have valence 6 and the old ones keep theirs, so the irregular vertices stay where the
// refinement levels meet, away from the focus (longest-edge bisection instead leaves "4-8"
// patches of valence 4 and 8 everywhere it refines, mesh_quality.hpp). The angles a green cut
// halves are evened out by the flips and smoothing that follow (improve_triangulation).
// Midpoints are projected onto the exact surface. Repeated until every edge fits the size field.
void refine(std::vector<Vector3d>& points, std::vector<std::array<int, 3>>& faces,
            const std::function<double(const Vector3d&)>& size, const Projection& project,
            int max_faces) {
  for (int pass = 0; pass < 64; ++pass) {
    std::unordered_map<long long, int> edge_index;
    std::vector<std::array<int, 2>> edges;
    std::vector<std::array<int, 3>> face_edges(faces.size());  // edge k is opposite vertex k
    const long long stride = static_cast<long long>(points.size());
    for (std::size_t f = 0; f < faces.size(); ++f) {
      for (int k = 0; k < 3; ++k) {
        const int u = faces[f][(k + 1) % 3], v = faces[f][(k + 2) % 3];
        const long long key = std::min(u, v) * stride + std::max(u, v);
        auto [it, inserted] = edge_index.try_emplace(key, static_cast<int>(edges.size()));
        if (inserted) edges.push_back({u, v});
        face_edges[f][k] = it->second;
      }
    }
    std::vector<double> length(edges.size());
    std::vector<char> marked(edges.size(), 0);
    bool any = false;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const Vector3d& p = points[edges[e][0]];
      const Vector3d& q = points[edges[e][1]];
      length[e] = (p - q).norm();
      if (length[e] > size(0.5 * (p + q))) marked[e] = 1, any = true;
    }
    if (!any) return;
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto& fe = face_edges[f];
        const int count = marked[fe[0]] + marked[fe[1]] + marked[fe[2]];
        if (count == 0 || count == 3) continue;
        if (count == 1) continue;  // green
        for (int k = 0; k < 3; ++k) {
          if (!marked[fe[k]]) marked[fe[k]] = 1, changed = true;
        }
      }
    }
    std::vector<int> midpoint(edges.size(), -1);
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (!marked[e]) continue;
      midpoint[e] = static_cast<int>(points.size());
      points.push_back(project(0.5 * (points[edges[e][0]] + points[edges[e][1]])));
    }
    std::vector<std::array<int, 3>> refined;
    refined.reserve(faces.size() * 3);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const auto& fe = face_edges[f];
      const auto& v = faces[f];
      const std::array<int, 3> m = {midpoint[fe[0]], midpoint[fe[1]], midpoint[fe[2]]};
      if (m[0] >= 0 && m[1] >= 0 && m[2] >= 0) {  // red: three corners and the middle
        refined.push_back({v[0], m[2], m[1]});
        refined.push_back({m[2], v[1], m[0]});
        refined.push_back({m[1], m[0], v[2]});
        refined.push_back({m[0], m[1], m[2]});
      } else if (m[0] >= 0 || m[1] >= 0 || m[2] >= 0) {  // green: halves through the marked edge
        const int k = m[0] >= 0 ? 0 : m[1] >= 0 ? 1 : 2;
        const int a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
        refined.push_back({a, b, m[k]});
        refined.push_back({a, m[k], c});
      } else {
        refined.push_back(v);
      }
    }
    faces = std::move(refined);
    if (static_cast<int>(faces.size()) > max_faces) {
      throw InputError("mesh", "the graded mesh exceeds " + std::to_string(max_faces) +
                                   " triangles: expected a coarser size field (probe radius "
                                   "or wall thickness too small for the mesh level)");
    }
  }
}

// The isotropic size field, and the longest edge an elongated far-field triangle of the tube
// may have (its diagonal), so that the refinement leaves those alone.
std::function<double(const Vector3d&)> size_field(const MeshSizing& sizing, const Vector3d& focus) {
  const double limit = sizing.coarsest * std::sqrt(1 + sizing.far_aspect * sizing.far_aspect);
  return [sizing, focus, limit](const Vector3d& p) {
    const double d = std::max(0.0, (p - focus).norm() - sizing.fine_radius);
    return std::min(limit, sizing.finest + sizing.grading * d);
  };
}

// How much a regular valence matters at p: most where the probe presses (within a few fine
// radii of the focus), where a 4-8 patch would soften the bending (mesh_quality.hpp).
std::function<double(const Vector3d&)> importance_near(const MeshSizing& sizing, const Vector3d& focus) {
  const double reach = std::max(2 * sizing.fine_radius, 4 * sizing.finest);
  return [focus, reach](const Vector3d& p) { return 1.0 + 20.0 * std::exp(-(p - focus).squaredNorm() / (reach * reach)); };
}

std::function<bool(const Vector3d&)> at(const Vector3d& point) {
  return [point](const Vector3d& p) { return (p - point).norm() <= 1e-12; };
}

TriangleMesh to_mesh(const std::vector<Vector3d>& points, std::vector<std::array<int, 3>> faces) {
  TriangleMesh mesh;
  mesh.positions.resize(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) mesh.positions.col(static_cast<Eigen::Index>(i)) = points[i];
  mesh.faces = std::move(faces);
  return mesh;
}

void check_sizing(const MeshSizing& s) {
  if (!(s.finest > 0 && s.coarsest >= s.finest && s.grading > 0 && s.fine_radius >= 0)) {
    throw InputError("mesh", "sizing: expected 0 < finest <= coarsest, grading > 0");
  }
}


// The full model as the half model and its mirror image in y = 0 (nodes on the plane shared),
// so that the two models discretise the same surface and the full one is exactly symmetric.
TriangleMesh mirrored(const TriangleMesh& half) {
  const Eigen::Index n = half.positions.cols();
  std::vector<int> image(static_cast<std::size_t>(n));
  std::vector<Vector3d> points;
  for (Eigen::Index v = 0; v < n; ++v) points.push_back(half.positions.col(v));
  for (Eigen::Index v = 0; v < n; ++v) {
    if (std::fabs(half.positions(1, v)) <= 1e-12) {
      image[static_cast<std::size_t>(v)] = static_cast<int>(v);
    } else {
      image[static_cast<std::size_t>(v)] = static_cast<int>(points.size());
      points.emplace_back(half.positions(0, v), -half.positions(1, v), half.positions(2, v));
    }
  }
  std::vector<std::array<int, 3>> faces = half.faces;
  for (const auto& f : half.faces) {
    // A reflection reverses orientation: swap two vertices to keep the faces outward.
    faces.push_back({image[static_cast<std::size_t>(f[0])], image[static_cast<std::size_t>(f[2])],
                     image[static_cast<std::size_t>(f[1])]});
  }
  return to_mesh(points, std::move(faces));
}

}  // namespace

double bending_length(double thickness) { return std::sqrt(thickness * 0.5); }

MeshSizing mesh_sizing(ShellFeMesh level, double probe_radius, double thickness) {
  const double b = bending_length(thickness);
  const double scale = level == ShellFeMesh::coarse     ? 1.0
                       : level == ShellFeMesh::standard ? std::numbers::sqrt2 / 2
                       : level == ShellFeMesh::fine     ? 0.5
                                                      : std::numbers::sqrt2 / 4;
  // A probe wider than the bending length: the wall no longer wraps it, and the contact patch
  // shrinks far below both (0.03 d0 under a probe of 0.19 d0 on a wall of bending length 0.16
  // d0, src/fe/README.md): the finest cell then follows the bending length down to a sixteenth
  // of it, over a fine region one bending length wide. A ramp over rho from 1 to 1.2 bending
  // lengths, not a switch, keeps the sizes continuous in the inputs; narrower probes (every
  // training tube of the corrected form) keep the sizes they had.
  const double wide = std::clamp((probe_radius / b - 1) / 0.2, 0.0, 1.0);
  MeshSizing s;
  s.finest = 0.5 * scale * std::min(probe_radius, b * (1 - 0.875 * wide));
  s.fine_radius = std::max(0.25 * b, (1 - wide) * 2 * probe_radius + wide * b);
  s.grading = 0.5 * scale;
  s.coarsest = std::max(0.14 * scale, s.finest);
  return s;
}

TriangleMesh make_tube_mesh(double length, double probe_distance, bool half_model,
                            const MeshSizing& sizing) {
  check_sizing(sizing);
  const double cap_base = length - radius;
  if (!(cap_base > 0)) throw InputError("mesh", "tube length: expected L/d0 > 1/2");
  // The coarse mesh: octant patches whose edges are about `coarsest` long.
  const int n = std::max(2, static_cast<int>(std::ceil(std::numbers::pi * radius / 2 / sizing.coarsest)));
  MeshBuilder builder;
  const Vector3d centre(0, 0, cap_base);
  const Vector3d ex(1, 0, 0), ey(0, 1, 0), ez(0, 0, 1);
  add_octant(builder, ex, ey, ez, n, centre, radius);
  add_octant(builder, ey, -ex, ez, n, centre, radius);
  // The cap's equator, ordered by angle from +x (counter-clockwise seen from +z).
  std::vector<std::pair<double, Vector3d>> equator;
  for (const Vector3d& p : builder.points()) {
    if (std::fabs(p.z() - cap_base) < 1e-12) {
      Vector3d q = p;
      q.z() = 0;
      double angle = std::atan2(q.y(), q.x());
      if (angle < -1e-12) angle += 2 * std::numbers::pi;
      equator.emplace_back(angle, q);
    }
  }
  std::sort(equator.begin(), equator.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const int columns = static_cast<int>(equator.size());  // 2n + 1, from angle 0 to pi
  // Rings from the cap's equator down to the open end: one circumferential spacing apart near
  // the probe, up to `far_aspect` spacings far from it, where the wall only inflates (uniform
  // along z) and elongated triangles represent it as well as isotropic ones.
  const double spacing = std::numbers::pi * radius / 2 / n;
  const double probe_z = length - probe_distance;
  const auto ring_spacing = [&](double z) {
    const double d = std::max(0.0, std::fabs(z - probe_z) - sizing.fine_radius);
    const double h = sizing.finest + sizing.grading * d;  // the size field along the meridian
    const double axial = std::sqrt(std::max(0.0, h * h - spacing * spacing));
    return std::clamp(axial, spacing, sizing.far_aspect * spacing);
  };
  std::vector<double> ring_z = {cap_base};
  while (ring_z.back() > 1e-9 && ring_z.size() < 100000) ring_z.push_back(ring_z.back() - ring_spacing(ring_z.back()));
  if (ring_z.size() > 2 && ring_z.back() < 0 && -ring_z.back() > 0.5 * (ring_z[ring_z.size() - 2] - ring_z.back())) {
    ring_z.pop_back();  // the last ring is closer to the end than half a spacing: merge them
  }
  const double span = cap_base - ring_z.back();
  for (double& z : ring_z) z = cap_base - (cap_base - z) * cap_base / span;
  ring_z.back() = 0.0;
  std::reverse(ring_z.begin(), ring_z.end());
  const int rings = static_cast<int>(ring_z.size()) - 1;
  std::vector<std::vector<int>> ring_nodes(rings + 1);
  for (int r = 0; r <= rings; ++r) {
    const double z = r == rings ? cap_base : ring_z[static_cast<std::size_t>(r)];
    for (const auto& [angle, q] : equator) {
      ring_nodes[r].push_back(builder.add_point(Vector3d(q.x(), q.y(), z)));
    }
  }
  for (int r = 0; r < rings; ++r) {
    for (int c = 0; c + 1 < columns; ++c) {
      const int c1 = c + 1;
      const int a = ring_nodes[r][c], b = ring_nodes[r][c1];
      const int d = ring_nodes[r + 1][c], e = ring_nodes[r + 1][c1];
      // Diagonals one way on the upper quarter (x > 0), mirrored on the lower one: every vertex
      // then has valence 6 (4 on the mirror plane y = 0, 6 in the full model), which red
      // refinement keeps (alternating diagonals would make a 4-8 mesh, soft in bending:
      // mesh_quality.hpp), and the mesh is symmetric about x = 0 as well as y = 0 (diagonals
      // all one way make a helical lattice whose twist, held by the mirror plane, bends the
      // inflated tube: 0.4 um over its 100 um, measured).
      if (2 * c + 1 < columns - 1) {
        builder.add_face(a, b, e), builder.add_face(a, e, d);
      } else {
        builder.add_face(a, b, d), builder.add_face(b, e, d);
      }
    }
  }
  Vector3d focus(radius, 0, probe_z);
  if (probe_z > cap_base) {
    const double dz = std::min(probe_z - cap_base, radius);
    focus = Vector3d(std::sqrt(radius * radius - dz * dz), 0, cap_base + dz);
  }
  auto project = [cap_base](const Vector3d& p) {
    if (p.z() <= cap_base) {
      const double r = std::hypot(p.x(), p.y());
      return Vector3d(p.x() * radius / r, p.y() * radius / r, p.z());
    }
    const Vector3d c(0, 0, cap_base);
    return Vector3d(c + radius * (p - c).normalized());
  };
  const auto size = size_field(sizing, focus);
  refine(builder.points(), builder.faces(), size, project, sizing.max_faces);
  improve_triangulation(builder.points(), builder.faces(), project, importance_near(sizing, focus), size, at(focus));
  TriangleMesh half = to_mesh(builder.points(), builder.faces());
  return half_model ? half : mirrored(half);
}

TriangleMesh make_sphere_mesh(bool half_model, const MeshSizing& sizing) {
  check_sizing(sizing);
  // The octahedron turned by 45 degrees about y, so that the pole +x where the probe presses is
  // the middle of an octahedron edge (in the plane y = 0), a vertex of valence 6 when n is
  // even, not one of the octahedron's valence-4 corners.
  int n = std::max(2, static_cast<int>(std::ceil(std::numbers::pi * radius / 2 / sizing.coarsest)));
  n += n % 2;
  MeshBuilder builder;
  const double r = std::numbers::sqrt2 / 2;
  const Vector3d o(0, 0, 0), ex(r, 0, -r), ey(0, 1, 0), ez(r, 0, r);
  for (double sz : {1.0, -1.0}) {
    for (double sx : {1.0, -1.0}) {
      // Octant (sx ex, ey, sz ez), ordered counter-clockwise seen from outside.
      const Vector3d a = sx * ex, c = sz * ez;
      if (sx * sz > 0) add_octant(builder, a, ey, c, n, o, radius);
      else add_octant(builder, ey, a, c, n, o, radius);
    }
  }
  auto project = [](const Vector3d& p) { return Vector3d(radius * p.normalized()); };
  const Vector3d pole(radius, 0, 0);
  const auto size = size_field(sizing, pole);
  refine(builder.points(), builder.faces(), size, project, sizing.max_faces);
  improve_triangulation(builder.points(), builder.faces(), project, importance_near(sizing, pole), size, at(pole));
  TriangleMesh half = to_mesh(builder.points(), builder.faces());
  return half_model ? half : mirrored(half);
}

EdgeLengthRange edge_length_range(const TriangleMesh& mesh) {
  EdgeLengthRange range{std::numeric_limits<double>::infinity(), 0.0};
  for (const auto& f : mesh.faces) {
    for (int k = 0; k < 3; ++k) {
      const double l = (mesh.positions.col(f[k]) - mesh.positions.col(f[(k + 1) % 3])).norm();
      range.shortest = std::min(range.shortest, l);
      range.longest = std::max(range.longest, l);
    }
  }
  return range;
}

}  // namespace growthuq::fe
