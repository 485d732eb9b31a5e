// Reading closed triangulated surfaces (Wavefront OBJ, OFF) and checking that they bound a
// volume: manifold, closed, consistently and outwardly oriented, without degenerate faces.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>
#include <string_view>
#include <unordered_map>

#include "fe/mesh.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/io/read_text_file.hpp"

namespace growthuq::fe {
namespace {

struct ParsedMesh {
  std::vector<Eigen::Vector3d> points;
  std::vector<long> point_lines;
  std::vector<std::array<int, 3>> faces;
  std::vector<long> face_lines;
};

double parse_number(std::string_view token, const std::string& where) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(value)) {
    throw InputError(where, "'" + std::string(token) + "': expected a finite number");
  }
  return value;
}

long parse_integer(std::string_view token, const std::string& where) {
  long value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) {
    throw InputError(where, "'" + std::string(token) + "': expected an integer");
  }
  return value;
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    std::size_t j = i;
    while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
    if (j > i) tokens.push_back(line.substr(i, j - i));
    i = j;
  }
  return tokens;
}

std::string strip_comment(const std::string& line) {
  const auto hash = line.find('#');
  return hash == std::string::npos ? line : line.substr(0, hash);
}

// Splits a polygon into a fan of triangles.
void add_polygon(ParsedMesh& mesh, const std::vector<int>& polygon, long line,
                 const std::string& where) {
  if (polygon.size() < 3) throw InputError(where, "expected a face with at least 3 vertices");
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    mesh.faces.push_back({polygon[0], polygon[k], polygon[k + 1]});
    mesh.face_lines.push_back(line);
  }
}

ParsedMesh parse_obj(std::istream& in, const std::string& path) {
  ParsedMesh mesh;
  std::string raw;
  long line = 0;
  while (std::getline(in, raw)) {
    ++line;
    const std::string text = strip_comment(raw);
    const auto tokens = split(text);
    if (tokens.empty()) continue;
    const std::string where = file_location(path, line);
    if (tokens[0] == "v") {
      if (tokens.size() < 4) throw InputError(where, "expected 'v x y z'");
      mesh.points.emplace_back(parse_number(tokens[1], where), parse_number(tokens[2], where),
                               parse_number(tokens[3], where));
      mesh.point_lines.push_back(line);
    } else if (tokens[0] == "f") {
      std::vector<int> polygon;
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        const std::string_view t = tokens[k].substr(0, tokens[k].find('/'));
        long index = parse_integer(t, where);
        // OBJ indices count from 1; negative ones count back from the last vertex so far.
        if (index < 0) index += static_cast<long>(mesh.points.size()) + 1;
        if (index < 1 || index > static_cast<long>(mesh.points.size())) {
          throw InputError(where, "vertex index '" + std::string(t) + "': expected 1 to " +
                                      std::to_string(mesh.points.size()) + " (vertices defined so far)");
        }
        polygon.push_back(static_cast<int>(index - 1));
      }
      add_polygon(mesh, polygon, line, where);
    }
    // Other OBJ statements (vn, vt, o, g, s, usemtl, mtllib, l) carry nothing the shell needs.
  }
  return mesh;
}

ParsedMesh parse_off(std::istream& in, const std::string& path) {
  ParsedMesh mesh;
  std::string raw;
  long line = 0;
  std::vector<std::string_view> tokens;
  std::string text;
  auto next = [&]() {
    while (std::getline(in, raw)) {
      ++line;
      text = strip_comment(raw);
      tokens = split(text);
      if (!tokens.empty()) return true;
    }
    return false;
  };
  if (!next() || tokens[0].substr(0, 3) != "OFF") {
    throw InputError(file_location(path, line), "expected the header 'OFF'");
  }
  tokens.erase(tokens.begin());
  if (tokens.empty() && !next()) {
    throw InputError(file_location(path, line), "expected 'vertices faces edges' counts");
  }
  std::string where = file_location(path, line);
  if (tokens.size() < 2) throw InputError(where, "expected 'vertices faces edges' counts");
  const long vertices = parse_integer(tokens[0], where);
  const long polygons = parse_integer(tokens[1], where);
  if (vertices < 3 || polygons < 1) {
    throw InputError(where, "expected at least 3 vertices and 1 face");
  }
  for (long v = 0; v < vertices; ++v) {
    if (!next()) throw InputError(file_location(path, line), "expected " + std::to_string(vertices) + " vertex lines, found " + std::to_string(v));
    where = file_location(path, line);
    if (tokens.size() < 3) throw InputError(where, "expected 'x y z'");
    mesh.points.emplace_back(parse_number(tokens[0], where), parse_number(tokens[1], where),
                             parse_number(tokens[2], where));
    mesh.point_lines.push_back(line);
  }
  for (long f = 0; f < polygons; ++f) {
    if (!next()) throw InputError(file_location(path, line), "expected " + std::to_string(polygons) + " face lines, found " + std::to_string(f));
    where = file_location(path, line);
    const long count = parse_integer(tokens[0], where);
    if (count < 3 || static_cast<long>(tokens.size()) < count + 1) {
      throw InputError(where, "expected 'n i1 ... in' with n >= 3 vertex indices");
    }
    std::vector<int> polygon;
    for (long k = 1; k <= count; ++k) {
      const long index = parse_integer(tokens[static_cast<std::size_t>(k)], where);
      if (index < 0 || index >= vertices) {
        throw InputError(where, "vertex index '" + std::string(tokens[static_cast<std::size_t>(k)]) +
                                    "': expected 0 to " + std::to_string(vertices - 1));
      }
      polygon.push_back(static_cast<int>(index));
    }
    add_polygon(mesh, polygon, line, where);
  }
  return mesh;
}

// Checks of a closed, consistently oriented 2-manifold. `face_where(f)` and `point_where(v)`
// name a face or a vertex in messages (file and line when read from a file).
template <class FaceWhere, class PointWhere>
void validate(const TriangleMesh& mesh, const FaceWhere& face_where, const PointWhere& point_where,
              const std::string& where) {
  const Eigen::Index n = mesh.positions.cols();
  if (mesh.faces.size() < 4) throw InputError(where, "expected a closed surface of at least 4 triangles");
  const double size = (mesh.positions.rowwise().maxCoeff() - mesh.positions.rowwise().minCoeff()).norm();
  std::vector<int> uses(static_cast<std::size_t>(n), 0);
  std::unordered_map<long long, int> directed;  // (u, v) -> face
  auto key = [n](int u, int v) { return static_cast<long long>(u) * n + v; };
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& t = mesh.faces[f];
    for (int v : t) {
      if (v < 0 || v >= n) throw InputError(face_where(f), "vertex index out of range");
    }
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      throw InputError(face_where(f), "degenerate face (a vertex repeated): expected three distinct vertices");
    }
    const Eigen::Vector3d a = mesh.positions.col(t[0]), b = mesh.positions.col(t[1]), c = mesh.positions.col(t[2]);
    if ((b - a).cross(c - a).norm() <= 1e-12 * size * size) {
      throw InputError(face_where(f), "degenerate face (zero area): expected a proper triangle");
    }
    for (int k = 0; k < 3; ++k) {
      ++uses[static_cast<std::size_t>(t[k])];
      const auto [it, inserted] = directed.try_emplace(key(t[k], t[(k + 1) % 3]), static_cast<int>(f));
      if (!inserted) {
        throw InputError(face_where(f), "edge " + std::to_string(t[k]) + "-" + std::to_string(t[(k + 1) % 3]) +
                                            " also used in the same direction by " + face_where(static_cast<std::size_t>(it->second)) +
                                            ": expected consistently oriented faces, each edge shared by two");
      }
    }
  }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& t = mesh.faces[f];
    for (int k = 0; k < 3; ++k) {
      if (!directed.count(key(t[(k + 1) % 3], t[k]))) {
        throw InputError(face_where(f), "edge " + std::to_string(t[k]) + "-" + std::to_string(t[(k + 1) % 3]) +
                                            " has no neighbour face: expected a closed surface");
      }
    }
  }
  for (Eigen::Index v = 0; v < n; ++v) {
    if (uses[static_cast<std::size_t>(v)] == 0) {
      throw InputError(point_where(static_cast<std::size_t>(v)), "vertex used by no face: expected every vertex on the surface");
    }
  }
  // One fan of faces around every vertex (no two cones touching at a point).
  std::vector<std::vector<int>> incident(static_cast<std::size_t>(n));
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    for (int v : mesh.faces[f]) incident[static_cast<std::size_t>(v)].push_back(static_cast<int>(f));
  }
  for (Eigen::Index v = 0; v < n; ++v) {
    const auto& around = incident[static_cast<std::size_t>(v)];
    int f = around.front(), count = 0;
    do {
      ++count;
      const auto& t = mesh.faces[static_cast<std::size_t>(f)];
      const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
      f = directed.at(key(t[(k + 1) % 3], static_cast<int>(v)));  // across the edge v-t[k+1]
    } while (f != around.front() && count <= static_cast<int>(around.size()));
    if (count != static_cast<int>(around.size())) {
      throw InputError(point_where(static_cast<std::size_t>(v)), "non-manifold vertex (surface sheets touch there): expected one fan of faces");
    }
  }
  double volume = 0.0;
  for (const auto& t : mesh.faces) {
    volume += mesh.positions.col(t[0]).dot(mesh.positions.col(t[1]).cross(mesh.positions.col(t[2])));
  }
  if (!(volume > 0)) {
    throw InputError(where, "the faces enclose a negative volume: expected faces counter-clockwise seen from outside");
  }
}

}  // namespace

void validate_closed_surface(const TriangleMesh& mesh, const std::string& where) {
  validate(
      mesh, [&](std::size_t f) { return where + ": face " + std::to_string(f); },
      [&](std::size_t v) { return where + ": vertex " + std::to_string(v); }, where);
}

void require_bending_stencils(const TriangleMesh& mesh, const std::string& where) {
  std::unordered_map<long long, int> far_of;  // directed edge (u, v) -> the far vertex of its face
  const long long n = mesh.positions.cols();
  const auto key = [n](int u, int v) { return static_cast<long long>(u) * n + v; };
  for (const auto& t : mesh.faces) {
    for (int k = 0; k < 3; ++k) far_of[key(t[k], t[(k + 1) % 3])] = t[(k + 2) % 3];
  }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& t = mesh.faces[f];
    std::array<int, 3> far{};
    for (int k = 0; k < 3; ++k) {
      const auto neighbour = far_of.find(key(t[(k + 1) % 3], t[k]));  // the same edge, seen from the other face
      far[static_cast<std::size_t>(k)] = neighbour == far_of.end() ? -1 - k : neighbour->second;
    }
    if (far[0] == far[1] || far[1] == far[2] || far[0] == far[2]) {
      const int shared = far[0] == far[1] || far[0] == far[2] ? far[0] : far[1];
      throw InputError(where + ": face " + std::to_string(f),
                       "two neighbouring faces share their far vertex " + std::to_string(shared) +
                           ": the bending element needs six different vertices around each face (expected every "
                           "vertex in at least four faces; a tetrahedron has none)");
    }
  }
}

TriangleMesh read_mesh_file(const std::string& path) {
  std::istringstream in(detail::read_text_file(path));
  std::string lower = path;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  ParsedMesh parsed;
  if (lower.ends_with(".obj")) parsed = parse_obj(in, path);
  else if (lower.ends_with(".off")) parsed = parse_off(in, path);
  else throw InputError(path, "unknown mesh format: expected a .obj (Wavefront) or .off file");
  if (parsed.points.size() < 4) throw InputError(path, "expected at least 4 vertices");
  // The generated meshes' cap, for a file's too: a 422 000-triangle OBJ ran past 30 s and 1 GB
  // before the first Newton step, where a generated mesh that large is refused at once.
  if (const std::size_t cap = static_cast<std::size_t>(MeshSizing{}.max_faces); parsed.faces.size() > cap) {
    throw InputError(path, std::to_string(parsed.faces.size()) + " triangles: expected at most " + std::to_string(cap) +
                               " (the limit of a generated mesh; it bounds time and memory): coarsen the surface");
  }
  TriangleMesh mesh;
  mesh.positions.resize(3, static_cast<Eigen::Index>(parsed.points.size()));
  for (std::size_t i = 0; i < parsed.points.size(); ++i) mesh.positions.col(static_cast<Eigen::Index>(i)) = parsed.points[i];
  mesh.faces = parsed.faces;
  validate(
      mesh, [&](std::size_t f) { return file_location(path, parsed.face_lines[f]); },
      [&](std::size_t v) { return file_location(path, parsed.point_lines[v]); }, path);
  return mesh;
}

}  // namespace growthuq::fe
