#include "growthuq/synthetic/relaxation_tube.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/relaxation/modulus.hpp"
#include "relaxation/nnls.hpp"
#include "relaxation/noise.hpp"

namespace growthuq {
namespace {

ShellGeometry shell_of(const RelaxationTube& tube) {
  return ShellGeometry{tube.turgor, tube.diameter, tube.thickness, tube.instrument};
}

void validate(const RelaxationTube& tube) {
  const auto require = [](bool good, const char* key, double value, const char* expected) {
    if (!good) throw_bad_value("synthetic relaxation tube", key, format_double(value), expected);
  };
  const std::pair<double, const char*> positive[] = {{tube.turgor, "p"},           {tube.diameter, "d"},
                                                      {tube.thickness, "h"},        {tube.instrument.probe_radius_m, "rho"},
                                                      {tube.stiffness0, "k0"},      {tube.tau_slow, "tau_slow"},
                                                      {tube.tau_fast, "tau_fast"}};
  for (const auto& [value, key] : positive) require(value > 0.0 && std::isfinite(value), key, value, "a positive finite number");
  require(tube.einf >= 0.0 && tube.einf < 1.0, "einf", tube.einf, "a fraction in [0, 1)");
  require(tube.fast_share >= 0.0 && tube.fast_share <= 1.0, "fast_share", tube.fast_share, "a fraction in [0, 1]");
  require(tube.tau_fast < tube.tau_slow, "tau_fast", tube.tau_fast, "a time below tau_slow");
}

// The positive generalized Maxwell series closest (least squares over [0, hold], log-spaced
// points) to the tube's step stiffness: NNLS over 40 relaxation times log-spaced from a
// quarter sample interval to 20 hold lengths, a time grid fine enough that the series is
// limited by complete monotonicity, not by the grid.
MaxwellModel positive_series(const RelaxationTube& tube, const RampHoldProtocol& protocol) {
  constexpr int times = 40, points = 400;
  const double tau_low = 0.25 * protocol.sample_interval, tau_high = 20.0 * protocol.hold;
  std::vector<double> tau(times), t(points + 1, 0.0);
  for (int i = 0; i < times; ++i) tau[static_cast<std::size_t>(i)] = tau_low * std::pow(tau_high / tau_low, i / (times - 1.0));
  const double t_low = 0.05 * protocol.sample_interval;
  for (int j = 1; j <= points; ++j) t[static_cast<std::size_t>(j)] = t_low * std::pow(protocol.hold / t_low, (j - 1.0) / (points - 1.0));
  Eigen::MatrixXd basis(points + 1, times + 1);
  Eigen::VectorXd target(points + 1);
  for (int j = 0; j <= points; ++j) {
    const double time = t[static_cast<std::size_t>(j)];
    basis(j, 0) = 1.0;
    for (int i = 0; i < times; ++i) basis(j, i + 1) = std::exp(-time / tau[static_cast<std::size_t>(i)]);
    target(j) = tube_step_stiffness(tube, time);
  }
  const Eigen::VectorXd norms = basis.colwise().norm().transpose();
  const Eigen::VectorXd coefficients = solve_nnls(basis * norms.cwiseInverse().asDiagonal(), target).cwiseQuotient(norms);
  MaxwellModel model;
  model.k_inf = coefficients(0);
  for (int i = 0; i < times; ++i) {
    if (coefficients(i + 1) > 0.0) {
      model.k.push_back(coefficients(i + 1));
      model.tau.push_back(tau[static_cast<std::size_t>(i)]);
    }
  }
  return model;
}

double series_stiffness(const MaxwellModel& model, double t) {
  double k = model.k_inf;
  for (std::size_t i = 0; i < model.k.size(); ++i) k += model.k[i] * std::exp(-t / model.tau[i]);
  return k;
}

}  // namespace

double tube_step_stiffness(const RelaxationTube& tube, double t) {
  const ShellGeometry shell = shell_of(tube);
  const double relaxing = tube.fast_share * std::exp(-t / tube.tau_fast) + (1.0 - tube.fast_share) * std::exp(-t / tube.tau_slow);
  const double modulus0 = relaxation_modulus(tube.stiffness0, shell);
  return relaxation_stiffness(modulus0 * (tube.einf + (1.0 - tube.einf) * relaxing), shell);
}

SimulatedCurve simulate_relaxation_tube(const RelaxationTube& tube, const RampHoldProtocol& protocol,
                                        double relative_noise, std::uint64_t noise_seed) {
  validate(tube);
  if (!(relative_noise >= 0.0) || !std::isfinite(relative_noise)) {
    throw_bad_value("synthetic relaxation tube", "noise", format_double(relative_noise), "a relative noise >= 0");
  }
  const MaxwellModel series = positive_series(tube, protocol);
  SimulatedCurve curve = simulate_ramp_hold(series, protocol);
  GaussianNoise noise(noise_seed);
  for (std::size_t i = 0; i < curve.t.size(); ++i) {
    if (curve.t[i] >= curve.ramp_end) {
      const double since = curve.t[i] - curve.ramp_end;
      curve.force[i] += curve.indentation * (tube_step_stiffness(tube, since) - series_stiffness(series, since));
    }
    curve.force[i] = std::max(0.0, curve.force[i] + relative_noise * protocol.set_point * noise.normal());
  }
  return curve;
}

}  // namespace growthuq
