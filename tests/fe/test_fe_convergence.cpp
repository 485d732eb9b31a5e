// Mesh convergence of the apparent stiffness k (the instrument's linear fit over 0.4-4 uN) at
// points of the physiological envelope: the observed order from the three mesh levels (each
// sqrt(2) finer than the one before) and the default level within 1 % of the Richardson limit.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "fe/forward.hpp"
#include "fe_validation_support.hpp"

using namespace growthuq;

namespace {

struct EnvelopePoint {
  const char* name;
  double p, young, h0, d0, rho;  // SI
};

double stiffness(const testing::DimensionlessPoint& point, double d0, fe::MeshLevel level, int& iterations) {
  fe::ForwardProblem problem;
  problem.pressure = point.pressure;
  problem.thickness = point.thickness;
  problem.probe_radius = point.probe_radius;
  problem.tube_length = 100e-6 / d0;
  problem.probe_distance = 10e-6 / d0;
  problem.max_depth = 0.4;
  problem.mesh = level;
  const fe::ForwardResult result = fe::simulate_forward(problem);
  iterations = result.newton_iterations;
  if (result.status != fe::FeStatus::ok) {
    std::printf("convergence: status %d: %s\n", static_cast<int>(result.status), result.message.c_str());
    return NAN;
  }
  return testing::window_slope(result.depth, result.force, point.window_low, point.window_high);
}

}  // namespace

TEST_CASE("k converges with the mesh and the default level is within 1 % of the extrapolated limit") {
  // PHYSICS section 7 medians (wild type, pme48) with the closed form's p and E; h0 from the
  // turgid h through the Hencky thickness stretch (~0.93 at these stretches).
  const std::vector<EnvelopePoint> points{{"wild type", 0.25e6, 28e6, 155e-9, 5.35e-6, 0.5e-6},
                                          {"pme48", 0.256e6, 20.7e6, 213e-9, 4.51e-6, 0.25e-6}};
  for (const EnvelopePoint& e : points) {
    CAPTURE(e.name);
    const auto point = testing::dimensionless_point(e.p, e.young, e.h0, e.d0, e.rho);
    int i1 = 0, i2 = 0, i3 = 0;
    const double coarse = stiffness(point, e.d0, fe::MeshLevel::coarse, i1);
    const double standard = stiffness(point, e.d0, fe::MeshLevel::standard, i2);
    const double fine = stiffness(point, e.d0, fe::MeshLevel::fine, i3);
    const testing::Richardson r = testing::richardson(coarse, standard, fine, std::sqrt(2.0));
    std::printf("convergence %s: k coarse %.6e standard %.6e fine %.6e (E d0); order %.2f limit %.6e; standard %+.3f %% "
                "fine %+.3f %% of the limit; Newton %d %d %d\n",
                e.name, coarse, standard, fine, r.order, r.limit, 100 * (standard / r.limit - 1), 100 * (fine / r.limit - 1),
                i1, i2, i3);
    REQUIRE(std::isfinite(r.order));
    CHECK(r.order > 0.5);
    CHECK(std::fabs(standard / r.limit - 1.0) < 0.01);
  }
}
