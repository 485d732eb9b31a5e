// Reading closed surfaces: a valid OBJ and OFF give the same tetrahedron; every defect gives one
// InputError naming the file, the line and what was expected.
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <string>

#include "fe/mesh.hpp"
#include "fe/pressure.hpp"
#include "growthuq/core/error.hpp"

using namespace growthuq::fe;

namespace {

std::string write_temporary(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("growthuq_fe_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(path) << text;
  return path.string();
}

std::string error_of(const std::string& name, const std::string& text) {
  const std::string path = write_temporary(name, text);
  std::string message;
  try {
    read_mesh_file(path);
  } catch (const growthuq::InputError& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  return message;
}

// The unit right tetrahedron, outward: volume 1/6.
const char* tetra_obj =
    "# tetrahedron\n"
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";

}  // namespace

TEST_CASE("OBJ and OFF tetrahedra read with volume 1/6") {
  const std::string obj = write_temporary("t.obj", tetra_obj);
  const TriangleMesh a = read_mesh_file(obj);
  CHECK(a.faces.size() == 4);
  CHECK(enclosed_volume(a.positions, a.faces) == doctest::Approx(1.0 / 6).epsilon(1e-15));
  std::filesystem::remove(obj);
  const std::string off = write_temporary("t.off", "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n");
  const TriangleMesh b = read_mesh_file(off);
  CHECK(enclosed_volume(b.positions, b.faces) == doctest::Approx(1.0 / 6).epsilon(1e-15));
  std::filesystem::remove(off);
  // A quad face is split into triangles: the unit cube, volume 1.
  const std::string cube = write_temporary("c.obj",
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  const TriangleMesh c = read_mesh_file(cube);
  CHECK(c.faces.size() == 12);
  CHECK(enclosed_volume(c.positions, c.faces) == doctest::Approx(1.0).epsilon(1e-15));
  std::filesystem::remove(cube);
}

TEST_CASE("defective surfaces: one message with file, line and what was expected") {
  // Bad number on line 2.
  std::string m = error_of("n.obj", "v 0 0 0\nv 1 x 0\n");
  CHECK(m.find("n.obj:2: 'x': expected a finite number") != std::string::npos);
  // Index beyond the vertices.
  m = error_of("i.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  CHECK(m.find("i.obj:4: vertex index '7': expected 1 to 3") != std::string::npos);
  // A face missing: open surface.
  m = error_of("o.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\nf 3 1 4\n");
  CHECK(m.find("expected consistently oriented faces") != std::string::npos);
  m = error_of("p.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 3 4\n");
  CHECK(m.find("p.obj:9") != std::string::npos);  // the flipped face
  // Inward orientation.
  m = error_of("r.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\nf 2 4 3\nf 3 4 1\n");
  CHECK(m.find("negative volume: expected faces counter-clockwise seen from outside") != std::string::npos);
  // Degenerate face.
  m = error_of("d.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 3\nf 3 1 4\n");
  CHECK(m.find("d.obj:7: degenerate face") != std::string::npos);
  // Unused vertex.
  m = error_of("u.obj", std::string(tetra_obj) + "v 5 5 5\n");
  CHECK(m.find("u.obj:10: vertex used by no face") != std::string::npos);
  // OFF with too few vertex lines; unknown extension.
  m = error_of("s.off", "OFF\n4 4 6\n0 0 0\n1 0 0\n");
  CHECK(m.find("expected 4 vertex lines, found 2") != std::string::npos);
  m = error_of("x.stl", "solid\n");
  CHECK(m.find("expected a .obj (Wavefront) or .off file") != std::string::npos);
  CHECK(error_of("missing/none.obj", "").find("cannot open") != std::string::npos);
}

TEST_CASE("two tetrahedra sharing a vertex are rejected as non-manifold") {
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv -1 0 0\nv 0 -1 0\nv 0 0 -1\n"
                     "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n"
                     "f 1 5 6\nf 1 7 5\nf 5 7 6\nf 6 7 1\n";
  const std::string m = error_of("m.obj", text);
  CHECK(m.find("m.obj:1: non-manifold vertex") != std::string::npos);
}
