// Far-field inflation of a closed-end tube: closed-form axial stretch, explicit pressure group,
// one bracketed root for the forward problem (see far_field.hpp for the equations).
#include "fe/far_field.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <memory>

#include "core/gsl_errors.hpp"

namespace growthuq::fe {

namespace {

constexpr double search_limit = 20.0;  // largest hoop stretch searched (St-VK has no maximum)

// St-VK: lambda_z^2 = u solves u^2 - b u - c = 0 (ratio of the axial to the hoop equation),
// b = 1 - 2 nu a + nu l^2/2, c = l^2 (a - nu/2), a = (l^2 - 1)/2; the larger root (u = 1 at l = 1).
FarFieldState stvk_state(double l, double nu) {
  const double a = 0.5 * (l * l - 1.0);
  const double b = 1.0 - 2.0 * nu * a + 0.5 * nu * l * l;
  const double c = l * l * (a - 0.5 * nu);
  const double u = 0.5 * (b + std::sqrt(std::fmax(0.0, b * b + 4.0 * c)));
  const double lz = std::sqrt(u);
  const double ez = 0.5 * (u - 1.0);
  const double s_hoop = (a + nu * ez) / (1.0 - nu * nu);
  const double e33 = -nu / (1.0 - nu) * (a + ez);
  return {l, lz, std::sqrt(std::fmax(0.0, 1.0 + 2.0 * e33)), 2.0 * s_hoop / lz};
}

// Both log laws: eps_z = kappa eps_t, eps_3 = -nu/(1-nu) (eps_t + eps_z),
// stress_t = E (eps_t + nu eps_z)/(1 - nu^2).
FarFieldState log_state(FarFieldLaw law, double l, double nu) {
  const double kappa = (1.0 - 2.0 * nu) / (2.0 - nu);
  const double et = std::log(l), ez = kappa * et;
  const double lz = std::exp(ez);
  const double l3 = std::exp(-nu / (1.0 - nu) * (et + ez));
  const double stress = (et + nu * ez) / (1.0 - nu * nu);
  const double group = law == FarFieldLaw::hencky ? 2.0 * stress / (l * l * lz) : 2.0 * stress * l3 / l;
  return {l, lz, l3, group};
}

double pressure_group(double l, void* params) {
  const auto* p = static_cast<const std::pair<FarFieldLaw, double>*>(params);
  return far_field_state(p->first, l, p->second).pressure_group;
}

double negative_pressure_group(double l, void* params) { return -pressure_group(l, params); }

// The root of f in [low, high], where f changes sign, by GSL's Brent solver to 1e-15.
double brent_root(gsl_function& f, double low, double high) {
  detail::gsl_errors_return();
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
  gsl_root_fsolver_set(solver.get(), &f, low, high);
  for (int iteration = 0; iteration < 200; ++iteration) {
    gsl_root_fsolver_iterate(solver.get());
    if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()), gsl_root_fsolver_x_upper(solver.get()), 0.0,
                               1e-15) == GSL_SUCCESS) {
      break;
    }
  }
  return gsl_root_fsolver_root(solver.get());
}

}  // namespace

FarFieldLaw far_field_law(ShellFeLaw law) {
  return law == ShellFeLaw::saint_venant_kirchhoff ? FarFieldLaw::saint_venant_kirchhoff : FarFieldLaw::hencky;
}

FarFieldState far_field_state(FarFieldLaw law, double hoop_stretch, double nu) {
  return law == FarFieldLaw::saint_venant_kirchhoff ? stvk_state(hoop_stretch, nu) : log_state(law, hoop_stretch, nu);
}

FarFieldState far_field_pressure_maximum(FarFieldLaw law, double nu) {
  const double kappa = (1.0 - 2.0 * nu) / (2.0 - nu);
  if (law == FarFieldLaw::hencky) return far_field_state(law, std::exp(1.0 / (2.0 + kappa)), nu);
  if (law == FarFieldLaw::cauchy_log) {
    const double beta = nu * (1.0 + kappa) / (1.0 - nu);
    return far_field_state(law, std::exp(1.0 / (1.0 + beta)), nu);
  }
  // St-VK: scan ln(l) on [0, ln 20] for an interior maximum, refine it with GSL's Brent minimiser.
  detail::gsl_errors_return();
  std::pair<FarFieldLaw, double> params{law, nu};
  constexpr int samples = 400;
  int best = 1;
  double best_value = -1.0;
  for (int i = 1; i <= samples; ++i) {
    const double l = std::exp(std::log(search_limit) * i / samples);
    const double g = pressure_group(l, &params);
    if (g > best_value) best_value = g, best = i;
  }
  if (best == samples) return far_field_state(law, search_limit, nu);
  const double lo = std::exp(std::log(search_limit) * (best - 1) / samples);
  const double mid = std::exp(std::log(search_limit) * best / samples);
  const double hi = std::exp(std::log(search_limit) * (best + 1) / samples);
  gsl_function f{&negative_pressure_group, &params};
  std::unique_ptr<gsl_min_fminimizer, decltype(&gsl_min_fminimizer_free)> minimizer(
      gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent), gsl_min_fminimizer_free);
  if (gsl_min_fminimizer_set(minimizer.get(), &f, mid, lo, hi) != GSL_SUCCESS) return far_field_state(law, mid, nu);
  for (int iteration = 0; iteration < 100; ++iteration) {
    gsl_min_fminimizer_iterate(minimizer.get());
    if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(minimizer.get()), gsl_min_fminimizer_x_upper(minimizer.get()),
                              0.0, 1e-12) == GSL_SUCCESS) {
      break;
    }
  }
  return far_field_state(law, gsl_min_fminimizer_x_minimum(minimizer.get()), nu);
}

FarFieldInflation far_field_inflation(FarFieldLaw law, double pressure_over_E, double h0_over_d0, double nu) {
  const double target = pressure_over_E / h0_over_d0;
  if (!(target > 0.0)) return {1.0, 1.0, 1.0, false};
  const FarFieldState peak = far_field_pressure_maximum(law, nu);
  if (target > peak.pressure_group) return {peak.hoop_stretch, peak.axial_stretch, peak.thickness_stretch, true};
  if (target == peak.pressure_group) return {peak.hoop_stretch, peak.axial_stretch, peak.thickness_stretch, false};
  // G rises from 0 at l = 1 to its maximum: one root in (1, l_peak), bracketed.
  struct Shifted {
    std::pair<FarFieldLaw, double> params;
    double target;
  } shifted{{law, nu}, target};
  gsl_function f{[](double l, void* p) {
                   auto* s = static_cast<Shifted*>(p);
                   return pressure_group(l, &s->params) - s->target;
                 },
                 &shifted};
  const FarFieldState state = far_field_state(law, brent_root(f, 1.0, peak.hoop_stretch), nu);
  return {state.hoop_stretch, state.axial_stretch, state.thickness_stretch, false};
}

FarFieldTurgidInflation far_field_inflation_to_turgid_thickness(FarFieldLaw law, double pressure_over_E,
                                                                double h_over_d0, double nu) {
  if (!(pressure_over_E > 0.0)) return {{1.0, 1.0, 1.0, false}, h_over_d0};
  const FarFieldState peak = far_field_pressure_maximum(law, nu);
  // turgid h/d0 at hoop stretch l, minus the target: decreasing on (1, l_peak].
  struct Target {
    FarFieldLaw law;
    double pressure_over_E, h_over_d0, nu;
  } target{law, pressure_over_E, h_over_d0, nu};
  const auto excess = [](double l, void* p) {
    const auto* t = static_cast<const Target*>(p);
    const FarFieldState state = far_field_state(t->law, l, t->nu);
    return t->pressure_over_E * state.thickness_stretch / state.pressure_group - t->h_over_d0;
  };
  const auto burst = [&] {
    return FarFieldTurgidInflation{{peak.hoop_stretch, peak.axial_stretch, peak.thickness_stretch, true}, 0.0};
  };
  if (excess(peak.hoop_stretch, &target) > 0.0) return burst();
  // Lower end of the bracket: near l = 1, G ~ c (l - 1), so the turgid thickness there is about
  // (p/E) / (c (l - 1)); halve l - 1 until it exceeds h (below 1e-15, p/E is too small to stretch the wall).
  double low = 1.0 + 0.5 * (peak.hoop_stretch - 1.0);
  while (excess(low, &target) <= 0.0) {
    low = 1.0 + 0.5 * (low - 1.0);
    if (low - 1.0 < 1e-15) return {{1.0, 1.0, 1.0, false}, h_over_d0};  // p/E negligible: no stretch
  }
  gsl_function f{excess, &target};
  const FarFieldState state = far_field_state(law, brent_root(f, low, peak.hoop_stretch), nu);
  if (!(state.thickness_stretch > 0.0)) return burst();
  return {{state.hoop_stretch, state.axial_stretch, state.thickness_stretch, false},
          pressure_over_E / state.pressure_group};
}

FarFieldInverse far_field_inverse(FarFieldLaw law, double d_over_d0, double h_over_d0, double nu) {
  FarFieldInverse out;
  if (!std::isfinite(d_over_d0) || !std::isfinite(h_over_d0) || !(d_over_d0 > 0.0) || !(h_over_d0 > 0.0) ||
      !(nu >= 0.0 && nu < 0.5)) {
    out.status = FarFieldInverseStatus::invalid_input;
    return out;
  }
  if (!(d_over_d0 > 1.0)) {
    out.status = FarFieldInverseStatus::not_stretched;
    return out;
  }
  if (d_over_d0 > far_field_pressure_maximum(law, nu).hoop_stretch) {
    out.status = FarFieldInverseStatus::beyond_pressure_maximum;
    return out;
  }
  const FarFieldState state = far_field_state(law, d_over_d0, nu);
  if (!(state.thickness_stretch > 0.0)) {
    out.status = FarFieldInverseStatus::thickness_collapsed;
    return out;
  }
  out.axial_stretch = state.axial_stretch;
  out.thickness_stretch = state.thickness_stretch;
  out.h0_over_d0 = h_over_d0 / state.thickness_stretch;
  out.pressure_over_E = state.pressure_group * out.h0_over_d0;
  return out;
}

}  // namespace growthuq::fe
