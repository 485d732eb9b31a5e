// Thin-shell inverse and forward model (Eqs. (M1)-(M10), src/mechanics/README.md). Equations:
//   relation 1, Eq. (M1) (Vogler et al. 2013):  p d / (2 h) = E ln(lambda),  lambda = d / d0
//   relation 2, Eqs. (M2), (M3) (Arnoldi et al. 2000): k = (3 pi / 4) p d phi(rho / alpha),
//                                     alpha^2 = 3 p d^3 / (16 (2 E h / (1 - nu^2) - p d))
// Substituting 1 into alpha gives alpha = d sqrt(3 q / (16 (1 - q))), q = (1 - nu^2) ln(lambda)
// (Eq. (M5)).
#include "growthuq/mechanics/thin_shell.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_lambert.h>

#include "core/gsl_errors.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/mechanics/arnoldi.hpp"

namespace growthuq {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

bool positive_finite(double value) noexcept { return std::isfinite(value) && value > 0.0; }

// alpha from the stretch measure q in [0, 1): both relations combined.
double decay_length(double d, double q) noexcept { return d * std::sqrt(3.0 * q / (16.0 * (1.0 - q))); }

// Relation 1 as p(lambda) = (2 h E / d0) ln(lambda) / lambda peaks at lambda = e: beyond it a
// larger diameter needs a smaller pressure, an unstable state the forward model (principal
// branch W0, lambda <= e) never returns. ln(lambda) = 1 (lambda = e, the burst point the forward
// model reaches with W0(-1/e) = -1) is still ok. Testing ln(lambda) rather than d/d0 keeps the
// window exactly empty for nu = 0, where q = ln(lambda) and q >= 1 is caught first.
bool on_unstable_branch(double ln_lambda) noexcept { return ln_lambda > 1.0; }

}  // namespace

TubeDiameters measured_diameters(double d, double d_to_si, double d0, double d0_to_si) noexcept {
  // One unit: ratio and difference of the values as measured. Two: of their SI values.
  const double ratio_d = d_to_si == d0_to_si ? d : d * d_to_si;
  const double ratio_d0 = d_to_si == d0_to_si ? d0 : d0 * d0_to_si;
  // d - d0 is exact (Sterbenz) whenever lambda <= 2, so the strain keeps full relative precision
  // as lambda -> 1, where E = p d / (2 h ln lambda) is most sensitive.
  return {d * d_to_si, d0 * d0_to_si, ratio_d / ratio_d0, (ratio_d - ratio_d0) / ratio_d0};
}

TurgorResult invert_turgor(double k_measured, double d, double d0, const Instrument& parameters) noexcept {
  return invert_turgor(k_measured, diameters_in_si(d, d0), parameters);
}

TurgorResult invert_turgor(double k_measured, const TubeDiameters& diameters, const Instrument& parameters) noexcept {
  TurgorResult result{nan, nan, nan, nan, nan, nan, SampleStatus::ok};
  const double d = diameters.d;
  const double d0 = diameters.d0;
  if (!positive_finite(k_measured) || !positive_finite(d) || !positive_finite(d0) ||
      !std::isfinite(diameters.strain)) {
    result.status = SampleStatus::invalid_input;
    return result;
  }
  const double k_sys = parameters.sensor_stiffness_N_per_m;
  if (k_measured >= k_sys) {
    result.status = SampleStatus::stiffness_at_sensor_limit;
    return result;
  }
  // Probe and tube in series: 1/k_m = 1/k + 1/k_sys (k_sys = inf leaves k = k_m).
  const double k = tube_stiffness(k_measured, parameters);

  result.lambda = diameters.lambda;
  if (!(diameters.strain > 0.0)) {
    result.status = SampleStatus::lambda_not_above_one;
    return result;
  }
  const double ln_lambda = std::log1p(diameters.strain);
  const double nu = parameters.poisson_ratio;
  result.q = (1.0 - nu * nu) * ln_lambda;
  if (!(result.q < 1.0)) {
    result.status = SampleStatus::beyond_membrane_limit;
    return result;
  }
  if (on_unstable_branch(ln_lambda)) {
    result.status = SampleStatus::unstable_branch;
    return result;
  }
  result.alpha = decay_length(d, result.q);
  result.x = parameters.probe_radius_m / result.alpha;
  result.phi = arnoldi_phi(result.x);
  result.p = 4.0 * k / (3.0 * std::numbers::pi * d * result.phi);
  if (!positive_finite(result.p) || !positive_finite(k)) {
    result.p = nan;
    result.status = SampleStatus::out_of_range;
  }
  return result;
}

ModulusResult invert_modulus(double p, double d, double d0, double h) noexcept {
  return invert_modulus(p, diameters_in_si(d, d0), h);
}

ModulusResult invert_modulus(double p, const TubeDiameters& diameters, double h) noexcept {
  ModulusResult result{nan, nan, nan, SampleStatus::ok};
  const double d = diameters.d;
  if (!positive_finite(p) || !positive_finite(d) || !positive_finite(diameters.d0) || !positive_finite(h) ||
      !std::isfinite(diameters.strain)) {
    result.status = SampleStatus::invalid_input;
    return result;
  }
  if (!(diameters.strain > 0.0)) {
    result.status = SampleStatus::lambda_not_above_one;
    return result;
  }
  const double ln_lambda = std::log1p(diameters.strain);
  if (on_unstable_branch(ln_lambda)) {
    result.status = SampleStatus::unstable_branch;
    return result;
  }
  result.hoop_stress = p * d / (2.0 * h);
  result.E = result.hoop_stress / ln_lambda;
  result.wall_stiffness = result.E * h;
  if (!positive_finite(result.hoop_stress) || !positive_finite(result.E) ||
      !positive_finite(result.wall_stiffness)) {
    result = ModulusResult{nan, nan, nan, SampleStatus::out_of_range};
  }
  return result;
}

ForwardResult thin_shell_forward(double p, double E, double h, double d0,
                                 const Instrument& parameters) noexcept {
  ForwardResult result{nan, nan, nan, nan, nan, SampleStatus::ok};
  if (!positive_finite(p) || !positive_finite(E) || !positive_finite(h) || !positive_finite(d0)) {
    result.status = SampleStatus::invalid_input;
    return result;
  }
  // ln(d/d0) = c d has a solution only while c d0 <= 1/e; the principal branch W0 is the
  // stable one (the smaller diameter). GSL's own 1/e is 1.0 / M_E, the same double as
  // 1 / std::numbers::e, so z <= 1/e keeps its branch-point argument -z + 1/e >= 0 and gives
  // W0 = -1 exactly at the limit (lambda = e).
  const double c = p / (2.0 * h * E);
  const double z = c * d0;
  if (!std::isfinite(z)) {
    result.status = SampleStatus::out_of_range;
    return result;
  }
  if (z > 1.0 / std::numbers::e) {
    result.status = SampleStatus::burst;
    return result;
  }
  detail::gsl_errors_return();
  gsl_sf_result w;
  if (z == 0.0) {
    w.val = 0.0;  // c d0 underflowed: no stretch to double precision
  } else if (gsl_sf_lambert_W0_e(-z, &w) != GSL_SUCCESS) {
    result.status = SampleStatus::out_of_range;
    return result;
  }
  // lambda = -W0(-z)/z (from W e^W = -z): the same W gives d and ln(lambda) = c d = -W.
  result.lambda = z == 0.0 ? 1.0 : -w.val / z;
  result.d = d0 * result.lambda;
  const double ln_lambda = -w.val;
  if (!(ln_lambda > 0.0)) {
    result.status = SampleStatus::out_of_range;  // stretch below double resolution
    return result;
  }
  const double nu = parameters.poisson_ratio;
  const double q = (1.0 - nu * nu) * ln_lambda;
  if (!(q < 1.0)) {
    result.status = SampleStatus::beyond_membrane_limit;
    return result;
  }
  result.alpha = decay_length(result.d, q);
  result.phi = arnoldi_phi(parameters.probe_radius_m / result.alpha);
  const double k = 0.75 * std::numbers::pi * p * result.d * result.phi;
  result.k_measured = measured_stiffness(k, parameters);
  if (!positive_finite(result.d) || !positive_finite(result.k_measured)) {
    result.k_measured = nan;
    result.status = SampleStatus::out_of_range;
  }
  return result;
}

}  // namespace growthuq
