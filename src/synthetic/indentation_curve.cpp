#include "growthuq/synthetic/indentation_curve.hpp"

#include <cmath>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/mechanics/instrument.hpp"
#include "relaxation/noise.hpp"

namespace growthuq {
namespace {

void require(bool condition, std::string_view key, double value, std::string_view expected) {
  if (!condition) throw_bad_value("synthetic indentation curve", key, format_double(value), expected);
}

}  // namespace

ForceCurve simulate_indentation_curve(const IndentationTruth& truth, std::uint64_t seed, const std::string& name,
                                      const std::string& tube, int repetition) {
  require(truth.stiffness > 0.0 && std::isfinite(truth.stiffness), "k", truth.stiffness, "a stiffness > 0 (N/m)");
  require(truth.sensor_stiffness > 0.0, "k_sys", truth.sensor_stiffness, "a sensor stiffness > 0 or inf (N/m)");
  require(truth.end > truth.start, "end", truth.end, "a turning point beyond the start");
  require(truth.contact > truth.start && truth.contact < truth.end, "contact", truth.contact,
          "a contact point between the start and the turning point");
  require(truth.speed > 0.0 && std::isfinite(truth.speed), "speed", truth.speed, "a speed > 0 (m/s)");
  require(truth.noise >= 0.0 && std::isfinite(truth.noise), "noise", truth.noise, "a noise sd >= 0 (N)");
  require(truth.approach_samples >= minimum_approach_samples, "samples", static_cast<double>(truth.approach_samples),
          "at least " + std::to_string(minimum_approach_samples) + " approach samples");

  const double k_m = measured_stiffness(truth.stiffness, Instrument{truth.probe_radius, 0.2, truth.sensor_stiffness});
  ForceCurve curve;
  curve.name = name;
  curve.tube = tube;
  curve.repetition = repetition;
  curve.location = "synthetic";
  curve.probe_radius_m = truth.probe_radius;
  curve.sensor_stiffness_N_per_m = truth.sensor_stiffness;
  curve.approach_end = truth.approach_samples;
  const std::size_t n = truth.approach_samples;
  const double step = (truth.end - truth.start) / static_cast<double>(n - 1);
  GaussianNoise noise(seed);
  for (std::size_t i = 0; i < 2 * n; ++i) {
    // The retract retraces the approach's positions, last first.
    const std::size_t j = i < n ? i : 2 * n - 1 - i;
    const double z = truth.start + step * static_cast<double>(j);
    const double t = step * static_cast<double>(i) / truth.speed;
    const double f = k_m * std::max(0.0, z - truth.contact) + truth.baseline_offset + truth.drift * t +
                     truth.noise * noise.normal();
    curve.position.push_back(z);
    curve.time.push_back(t);
    curve.force.push_back(f);
  }
  return curve;
}

}  // namespace growthuq
