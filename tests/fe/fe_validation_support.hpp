// Small helpers of the finite-element validation tests: the apparent stiffness of a curve as
// the instrument fits it, Richardson extrapolation of a mesh sequence, and the physiological
// parameter points the tests share (dimensionless, as the solver works).
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace growthuq::testing {

// Least-squares slope of force against depth over the samples with force in [low, high] (the
// instrument's linear fit over its force window); NaN with fewer than two samples there.
inline double window_slope(const std::vector<double>& depth, const std::vector<double>& force, double low,
                           double high) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < depth.size() && i < force.size(); ++i) {
    if (force[i] < low || force[i] > high) continue;
    n += 1, sx += depth[i], sy += force[i], sxx += depth[i] * depth[i], sxy += depth[i] * force[i];
  }
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// Observed order and extrapolated limit of a quantity on three meshes, each `ratio` times finer
// than the one before (Richardson; Roache 1998, ch. 5): p = ln((q1 - q2)/(q2 - q3)) / ln(ratio),
// q_inf = q3 + (q3 - q2)/(ratio^p - 1). NaN order when the differences do not shrink
// monotonically (no asymptotic range).
struct Richardson {
  double order = std::numeric_limits<double>::quiet_NaN();
  double limit = std::numeric_limits<double>::quiet_NaN();
};
inline Richardson richardson(double coarse, double middle, double fine, double ratio) {
  Richardson r;
  const double d1 = coarse - middle, d2 = middle - fine;
  if (!(d1 * d2 > 0) || !(std::fabs(d2) < std::fabs(d1))) return r;
  r.order = std::log(d1 / d2) / std::log(ratio);
  r.limit = fine + (fine - middle) / (std::pow(ratio, r.order) - 1.0);
  return r;
}

// A point of the physiological envelope in the solver's units: p/E, h0/d0, rho/d0 and the
// force window over E d0^2, from values in SI (pressure, modulus, thickness h0, plasmolysed
// diameter d0, probe radius, window in newtons).
struct DimensionlessPoint {
  double pressure, thickness, probe_radius, window_low, window_high;
};
inline DimensionlessPoint dimensionless_point(double p, double young, double h0, double d0, double rho,
                                              double window_low = 0.4e-6, double window_high = 4e-6) {
  const double force_scale = young * d0 * d0;
  return {p / young, h0 / d0, rho / d0, window_low / force_scale, window_high / force_scale};
}

}  // namespace growthuq::testing
