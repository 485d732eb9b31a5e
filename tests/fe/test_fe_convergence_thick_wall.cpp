// Mesh convergence of the apparent stiffness k (mesh_convergence.hpp) at the thick wall under a
// large probe, the point that set the mesh's sizing for probes wider than the bending length
// (src/fe/mesh.cpp, mesh_sizing; src/fe/README.md, "Validation status").
#include <doctest/doctest.h>

#include "mesh_convergence.hpp"

using namespace growthuq;

// p = 0.6 MPa, E = 150 MPa, h0 = 405 nm (turgid h 400 nm), d0 = 8 um, rho = 1.5 um: rho is 1.18
// bending lengths. Its coarse, default and fine levels oscillate within 0.36 % (no asymptotic
// range, tools/bench/fe-mesh-convergence), so the order and limit come from the default, fine and
// finer levels (about 4 minutes of one core in all).
TEST_CASE("thick wall under a large probe: k converges, the default level within 1 % of the limit") {
  testing::check_convergence({"thick wall, large probe", 0.6e6, 150e6, 405.2e-9, 8e-6, 1.5e-6, 0.8e-6}, ShellFeMesh::standard,
                             ShellFeMesh::fine, ShellFeMesh::finer);
}
