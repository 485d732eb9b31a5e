// Mesh convergence of the apparent stiffness k (mesh_convergence.hpp) at an Arabidopsis-like
// tube whose curve reaches the window's top (k about 2 N/m): the observed order from the coarse,
// default and fine levels and the default level within 1 % of the Richardson limit.
//
// Two points, not the sweep (tools/bench/fe-mesh-convergence), for the suite's time: this one
// and the thick wall under a large probe (test_fe_convergence_thick_wall.cpp). The corners of
// the envelope are covered for robustness by test_fe_envelope, not for accuracy.
#include <doctest/doctest.h>

#include "mesh_convergence.hpp"

using namespace growthuq;

TEST_CASE("k converges with the mesh and the default level is within 1 % of the extrapolated limit") {
  // p = 0.45 MPa, E = 45 MPa, h0 = 211 nm (turgid h about 200 nm), d0 = 5.35 um, rho = 0.25 um.
  testing::check_convergence({"Arabidopsis-like", 0.45e6, 45e6, 211e-9, 5.35e-6, 0.25e-6, 2.3e-6}, ShellFeMesh::coarse,
                             ShellFeMesh::standard, ShellFeMesh::fine);
}
