// The generated meshes: on the exact surface, closed or bounded where they should be,
// consistently oriented, graded as asked, the enclosed volume converging at second order.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "fe/mesh.hpp"
#include "fe/mesh_quality.hpp"
#include "fe/pressure.hpp"
#include "growthuq/core/error.hpp"

using namespace growthuq::fe;
using growthuq::ShellFeMesh;

namespace {

// Directed-edge census: every directed edge used once (consistent orientation); returns the
// undirected boundary edges (used in one direction only).
std::vector<std::array<int, 2>> boundary_edges(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& f : mesh.faces) {
    for (int k = 0; k < 3; ++k) {
      const int count = ++directed[{f[k], f[(k + 1) % 3]}];
      REQUIRE(count == 1);
    }
  }
  std::vector<std::array<int, 2>> boundary;
  for (const auto& [edge, count] : directed) {
    if (!directed.count({edge.second, edge.first})) boundary.push_back({edge.first, edge.second});
  }
  return boundary;
}

double min_angle_degrees(const TriangleMesh& mesh) {
  double smallest = 180.0;
  for (const auto& f : mesh.faces) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d a = mesh.positions.col(f[(k + 1) % 3]) - mesh.positions.col(f[k]);
      const Eigen::Vector3d b = mesh.positions.col(f[(k + 2) % 3]) - mesh.positions.col(f[k]);
      smallest = std::min(smallest, std::acos(a.normalized().dot(b.normalized())) * 180 / std::numbers::pi);
    }
  }
  return smallest;
}

}  // namespace

TEST_CASE("half tube mesh: nodes on the capped tube, open only on y = 0 and z = 0, graded under the probe") {
  const double L = 10.0, a = 1.0;
  const MeshSizing sizing = mesh_sizing(ShellFeMesh::standard, 0.05, 0.02);
  const TriangleMesh mesh = make_tube_mesh(L, a, true, sizing);
  const double cap_base = L - 0.5;
  for (Eigen::Index v = 0; v < mesh.positions.cols(); ++v) {
    const Eigen::Vector3d p = mesh.positions.col(v);
    CHECK(p.y() >= 0.0);
    const double r = p.z() <= cap_base ? std::hypot(p.x(), p.y()) : (p - Eigen::Vector3d(0, 0, cap_base)).norm();
    CHECK(r == doctest::Approx(0.5).epsilon(1e-12));
  }
  for (const auto& e : boundary_edges(mesh)) {
    const Eigen::Vector3d p = mesh.positions.col(e[0]), q = mesh.positions.col(e[1]);
    const bool mirror = p.y() == 0.0 && q.y() == 0.0, end = p.z() == 0.0 && q.z() == 0.0;
    CHECK((mirror || end));
  }
  // Outward: the volume is half the capped cylinder's, pi r^2 (L - r) + (2/3) pi r^3, to the
  // chord error of the coarse far field (edges <= 0.14: relative error ~ (0.14/2/0.5)^2/3).
  const double exact = 0.5 * (std::numbers::pi * 0.25 * cap_base + 2.0 / 3 * std::numbers::pi * 0.125);
  CHECK(enclosed_volume(mesh.positions, mesh.faces) == doctest::Approx(exact).epsilon(0.01));
  // Every edge fits the size field; the finest edges are where the probe touches.
  const Eigen::Vector3d focus(0.5, 0, L - a);
  double shortest_far = 1.0, longest_near = 0.0;
  for (const auto& f : mesh.faces) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = mesh.positions.col(f[k]), q = mesh.positions.col(f[(k + 1) % 3]);
      const double d = (0.5 * (p + q) - focus).norm();
      const double limit = sizing.coarsest * std::sqrt(1 + sizing.far_aspect * sizing.far_aspect);
      const double allowed = std::min(limit, sizing.finest + sizing.grading * std::max(0.0, d - sizing.fine_radius));
      CHECK((p - q).norm() <= allowed * (1 + 1e-9));
      if (d < sizing.fine_radius) longest_near = std::max(longest_near, (p - q).norm());
      if (d > 2.0) shortest_far = std::min(shortest_far, (p - q).norm());
    }
  }
  CHECK(longest_near <= sizing.finest * (1 + 1e-9));
  CHECK(shortest_far > 2 * sizing.finest);
  // Red-green refinement (green cuts through any edge, then flips and smoothing) keeps angles
  // bounded away from 0.
  CHECK(min_angle_degrees(mesh) > 20.0);
  // The apex is a node of a few triangles (the octant patch, perhaps bisected), not a fan.
  int apex_faces = 0;
  for (const auto& f : mesh.faces) {
    for (int v : f) apex_faces += mesh.positions(2, v) == doctest::Approx(L).epsilon(1e-14) ? 1 : 0;
  }
  CHECK(apex_faces >= 2);
  CHECK(apex_faces <= 4);
}

TEST_CASE("full tube mesh is the half and its mirror image: volume exactly twice") {
  const MeshSizing sizing = mesh_sizing(ShellFeMesh::coarse, 0.1, 0.02);
  const TriangleMesh half = make_tube_mesh(6.0, 1.0, true, sizing);
  const TriangleMesh full = make_tube_mesh(6.0, 1.0, false, sizing);
  CHECK(full.faces.size() == 2 * half.faces.size());
  for (const auto& e : boundary_edges(full)) {
    CHECK(full.positions(2, e[0]) == 0.0);
    CHECK(full.positions(2, e[1]) == 0.0);
  }
  CHECK(enclosed_volume(full.positions, full.faces) ==
        doctest::Approx(2 * enclosed_volume(half.positions, half.faces)).epsilon(1e-13));
}

TEST_CASE("sphere volume converges to 4/3 pi r^3 at second order in the edge length") {
  // Uniform meshes (finest = coarsest); the inscribed polyhedron's volume error is
  // proportional to h^2 (chord sagitta), so halving h divides the error by about 4.
  std::vector<double> errors;
  for (double h : {0.2, 0.1, 0.05}) {
    MeshSizing uniform{h, 0.0, 1.0, h};
    const TriangleMesh mesh = make_sphere_mesh(false, uniform);
    CHECK(boundary_edges(mesh).empty());
    const double exact = 4.0 / 3 * std::numbers::pi * 0.125;
    const double volume = enclosed_volume(mesh.positions, mesh.faces);
    CHECK(volume < exact);  // inscribed
    errors.push_back((exact - volume) / exact);
    const TriangleMesh half = make_sphere_mesh(true, uniform);
    CHECK(2 * enclosed_volume(half.positions, half.faces) == doctest::Approx(volume).epsilon(1e-13));
  }
  const double order1 = std::log2(errors[0] / errors[1]), order2 = std::log2(errors[1] / errors[2]);
  CHECK(order1 == doctest::Approx(2.0).epsilon(0.15));
  CHECK(order2 == doctest::Approx(2.0).epsilon(0.1));
}

TEST_CASE("sphere mesh is graded around the pole +x") {
  const MeshSizing sizing = mesh_sizing(ShellFeMesh::standard, 0.02, 0.005);
  const TriangleMesh mesh = make_sphere_mesh(true, sizing);
  double nearest = 1.0;
  for (Eigen::Index v = 0; v < mesh.positions.cols(); ++v) {
    CHECK(mesh.positions.col(v).norm() == doctest::Approx(0.5).epsilon(1e-12));
    if (v > 0) nearest = std::min(nearest, (mesh.positions.col(v) - Eigen::Vector3d(0.5, 0, 0)).norm());
  }
  CHECK(mesh_sizing(ShellFeMesh::standard, 0.02, 0.005).finest < std::sqrt(0.005 * 0.5) / 4);
  CHECK(min_angle_degrees(mesh) > 20.0);
}

TEST_CASE("mesh sizing: each level sqrt(2) finer, the finest size below probe radius and bending length") {
  const MeshSizing c = mesh_sizing(ShellFeMesh::coarse, 0.05, 0.02);
  const MeshSizing s = mesh_sizing(ShellFeMesh::standard, 0.05, 0.02);
  const MeshSizing f = mesh_sizing(ShellFeMesh::fine, 0.05, 0.02);
  CHECK(c.finest / s.finest == doctest::Approx(std::sqrt(2.0)));
  CHECK(s.finest / f.finest == doctest::Approx(std::sqrt(2.0)));
  CHECK(c.finest <= 0.5 * 0.05);
  CHECK(c.fine_radius >= std::sqrt(0.01));
  const MeshSizing r = mesh_sizing(ShellFeMesh::finer, 0.05, 0.02);
  CHECK(f.finest / r.finest == doctest::Approx(std::sqrt(2.0)));
}

// A probe wider than the bending length b = sqrt(h0 / 2): the finest size falls from b / 2 to
// b / 32 (coarse level) and the fine region from 2 rho to b as rho grows from b to 1.2 b, with
// no jump anywhere, and a narrower probe keeps the sizes "half the probe radius over twice its
// radius".
TEST_CASE("mesh sizing under a probe wider than the bending length: finer cells, continuous in rho") {
  const double thickness = 0.05;
  const double b = std::sqrt(0.5 * thickness);
  for (double rho : {0.3 * b, 0.9 * b, b}) {
    const MeshSizing s = mesh_sizing(ShellFeMesh::coarse, rho, thickness);
    CHECK(s.finest == doctest::Approx(0.5 * rho));
    CHECK(s.fine_radius == doctest::Approx(2 * rho));
  }
  for (double rho : {1.2 * b, 2.0 * b, 10.0 * b}) {
    const MeshSizing s = mesh_sizing(ShellFeMesh::coarse, rho, thickness);
    CHECK(s.finest == doctest::Approx(b / 16));
    CHECK(s.fine_radius == doctest::Approx(b));
  }
  // Continuity: the sizes change by O(step) across the ramp's two ends and inside it.
  const double step = 1e-7 * b;
  for (double rho = 0.95 * b; rho < 1.25 * b; rho += 0.01 * b) {
    const MeshSizing here = mesh_sizing(ShellFeMesh::coarse, rho, thickness);
    const MeshSizing next = mesh_sizing(ShellFeMesh::coarse, rho + step, thickness);
    CAPTURE(rho / b);
    CHECK(std::fabs(next.finest - here.finest) < 1e-5 * b);
    CHECK(std::fabs(next.fine_radius - here.fine_radius) < 1e-5 * b);
  }
}

// Where the probe presses, every vertex has valence 6 (counted in the full model on the mirror
// plane): on a "4-8" patch of valence 4 and 8 the bending element has a checkerboard mode and
// the probe's stiffness comes out 13-24 % soft (mesh_quality.hpp; test_fe_vella measures it).
TEST_CASE("the tube and sphere meshes are regular (valence 6) where the probe presses, at every level") {
  for (ShellFeMesh level : {ShellFeMesh::coarse, ShellFeMesh::standard, ShellFeMesh::fine}) {
    for (double rho : {0.02, 0.05, 0.2}) {
      CAPTURE(rho);
      const MeshSizing sizing = mesh_sizing(level, rho, 0.03);
      const Eigen::Vector3d focus(0.5, 0, 19.0 - 1.87);
      const TriangleMesh tube = make_tube_mesh(19.0, 1.87, true, sizing);
      std::vector<Eigen::Vector3d> points(static_cast<std::size_t>(tube.positions.cols()));
      for (std::size_t v = 0; v < points.size(); ++v) points[v] = tube.positions.col(static_cast<Eigen::Index>(v));
      const ValenceCounts near = valence_counts(points, tube.faces, [&](const Eigen::Vector3d& p) {
        return (p - focus).norm() <= sizing.fine_radius;
      });
      CHECK(near.interior > 20);
      CHECK(near.irregular == 0);
      const ValenceCounts all = valence_counts(points, tube.faces);
      CHECK(all.irregular <= all.interior / 10);  // where the levels meet, and the apex

      const TriangleMesh sphere = make_sphere_mesh(true, sizing);
      points.resize(static_cast<std::size_t>(sphere.positions.cols()));
      for (std::size_t v = 0; v < points.size(); ++v) points[v] = sphere.positions.col(static_cast<Eigen::Index>(v));
      const ValenceCounts pole = valence_counts(points, sphere.faces, [&](const Eigen::Vector3d& p) {
        // (the octahedron's corners, of valence 4, lie 0.38 from the pole)
        return (p - Eigen::Vector3d(0.5, 0, 0)).norm() <= std::min(sizing.fine_radius, 0.3);
      });
      CHECK(pole.interior > 20);
      CHECK(pole.irregular == 0);
    }
  }
}
