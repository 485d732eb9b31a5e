// One synthetic force-indentation curve with a known truth, as the instrument would record it:
// the stage moves at constant speed from `start` to `end` and back; the tube answers with
// F = k_m (z - z_c)+ where k_m = k k_sys / (k + k_sys) is the tube and the sensor in series
// (Eq. (M8), src/mechanics/README.md: a linear, closed-form shape); the reading adds a baseline
// offset, a drift linear in time and Gaussian noise (GaussianNoise(seed), so a seed gives the
// same curve everywhere). Recovery of k from such curves: src/forcecurves/README.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include "growthuq/forcecurves/force_curve.hpp"

namespace growthuq {

struct IndentationTruth {
  double stiffness = 2.87;                       // k of the tube (N/m)
  double sensor_stiffness = std::numeric_limits<double>::infinity();  // k_sys (N/m)
  double probe_radius = 0.25e-6;                 // rho (m), written to the sheet only
  double start = 0.0;                            // stage position where the approach starts (m)
  double end = 4e-6;                             // its turning point (m)
  double contact = 1.5e-6;                       // z_c (m)
  double speed = 2e-6;                           // stage speed (m/s)
  std::size_t approach_samples = 2000;           // the retract has as many
  double baseline_offset = 0.3e-6;               // N
  double drift = 0.02e-6;                        // N/s
  double noise = 0.01e-6;                        // sd of the reading (N)
};

// The curve `name` of `tube`, repetition `repetition`. InputError for a truth that is not
// physical (k, k_sys, speed or noise out of range, the contact outside (start, end), fewer
// than minimum_approach_samples samples).
ForceCurve simulate_indentation_curve(const IndentationTruth& truth, std::uint64_t seed, const std::string& name,
                                      const std::string& tube, int repetition);

}  // namespace growthuq
