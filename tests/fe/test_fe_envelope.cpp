// Stability at the corners of the numerical envelope: thin and thick walls, low and high p/E
// (stretch near 1 and near the burst limit of the far field), probe radius 0.1 and 2 um. Every
// point must end with a value or a status within a bounded number of Newton iterations: never
// a hang, a NaN or an exception.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "fe/far_field.hpp"
#include "fe/forward.hpp"

using namespace growthuq;

namespace {

// The far field's burst pressure of a Hencky tube (the largest p/E with an equilibrium), by
// bisection on its burst flag.
double burst_pressure(double thickness, double nu) {
  double low = 0.0, high = 10.0 * thickness;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (low + high);
    (fe::far_field_inflation(fe::FarFieldLaw::hencky, mid, thickness, nu).burst ? high : low) = mid;
  }
  return low;
}

}  // namespace

TEST_CASE("every corner of the envelope ends with a value or a status, in bounded work") {
  // d0 = 5 um. Walls h0 = 0.05 and 0.5 um (h0/d0 0.01, 0.1); probes 0.1 and 2 um (rho/d0 0.02,
  // 0.4); p/E giving a far-field hoop stretch of ~1.005 and 97 % of the burst pressure.
  // Tube 6 d0 long, probed 1.5 d0 behind the apex (shorter than the default to bound the
  // sweep's time; the corners test robustness, not the value).
  const double nu = 0.2;
  // Work bound: the load stepping's attempts (200 per path, two paths plus a re-mesh pass)
  // times Newton's 40 iterations.
  const int bound = 3 * 200 * 40;
  int point = 0;
  for (double thickness : {0.01, 0.1}) {
    const double burst = burst_pressure(thickness, nu);
    for (double pressure : {0.01 * thickness, 0.97 * burst}) {
      for (double rho : {0.02, 0.4}) {
        ++point;
        fe::ForwardProblem problem;
        problem.pressure = pressure;
        problem.thickness = thickness;
        problem.poisson = nu;
        problem.probe_radius = rho;
        problem.tube_length = 6.0;
        problem.probe_distance = 1.5;
        problem.max_depth = 0.1;
        problem.mesh = ShellFeMesh::coarse;
        fe::ForwardResult result;
        bool threw = false;
        try {
          result = fe::simulate_forward(problem);
        } catch (...) {
          threw = true;
        }
        CAPTURE(thickness);
        CAPTURE(pressure);
        CAPTURE(rho);
        REQUIRE_FALSE(threw);
        bool finite = std::isfinite(result.turgid_diameter);
        for (std::size_t i = 0; i < result.force.size(); ++i) {
          finite = finite && std::isfinite(result.force[i]) && std::isfinite(result.depth[i]);
        }
        std::printf("envelope %2d h0/d0 %.3f p/E %.3e rho/d0 %.2f: status %d, %zu points, max force %.3e, Newton %d%s%s\n",
                    point, thickness, pressure, rho, static_cast<int>(result.status), result.force.size(),
                    result.force.empty() ? 0.0 : result.force.back(), result.newton_iterations,
                    result.message.empty() ? "" : ", ", result.message.c_str());
        CHECK(result.newton_iterations <= bound);
        if (result.status == SampleStatus::ok) {
          CHECK(finite);
          CHECK(result.force.size() >= 2);
          CHECK(result.depth.back() == doctest::Approx(problem.max_depth));
        } else {
          CHECK_FALSE(result.message.empty());
        }
      }
    }
  }
}
