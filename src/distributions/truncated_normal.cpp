// Tail care: with alpha = (lower - mean)/sd and beta = (upper - mean)/sd, a truncation window
// on the right of the mean (alpha > 0) is handled as the mirror image of a left window, so the
// normal probabilities involved are lower-tail values Phi(t) <= 1/2 (or upper-tail Q(t) <= 1/2)
// that GSL returns with full relative accuracy (Phi(-37) ~ 1e-300 is still exact to ~1e-16).
// Inside the window the quantile interpolates from the nearer end (u from the lower end, 1 - u
// from the upper), and inverts through Phi^-1 or Q^-1, whichever argument is below 1/2. The
// cdf close to an end integrates the density instead of subtracting two normal probabilities.
#include "growthuq/distributions/truncated_normal.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "distributions/checks.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"

namespace growthuq {
namespace {

using Window = TruncatedNormal::Window;

// Integral of the standard normal density over [a, b] when the two ends are so close that
// Phi(b) - Phi(a) would cancel: with (b - a)(1 + max|t|) <= 1 the integrand varies by at most
// a factor e over the interval, and 12-point Gauss-Legendre integrates it to ~1e-19 relative
// (error ~ 1/(24)! of the 24th derivative scale), keeping F relative-accurate at the ends.
bool close_ends(double a, double b) { return (b - a) * (1.0 + std::max(std::fabs(a), std::fabs(b))) <= 1.0; }

double density_integral(double a, double b) {
  static gsl_integration_glfixed_table* const table = gsl_integration_glfixed_table_alloc(12);
  gsl_function density{[](double t, void*) { return std::exp(-0.5 * t * t); }, nullptr};
  return gsl_integration_glfixed(&density, a, b, table) / std::sqrt(2.0 * std::numbers::pi);
}

// Phi(t) - Phi(alpha) and Phi(beta) - Phi(t) for t in the window: by quadrature when t is
// close to the end, else from the tail function that does not cancel.
double mass_below(const Window& w, double t) {
  if (close_ends(w.alpha, t)) return density_integral(w.alpha, t);
  return t <= 0.0 ? gsl_cdf_ugaussian_P(t) - w.phi_alpha : w.mass - (gsl_cdf_ugaussian_Q(t) - w.q_beta);
}
double mass_above(const Window& w, double t) {
  if (close_ends(t, w.beta)) return density_integral(t, w.beta);
  return t >= 0.0 ? gsl_cdf_ugaussian_Q(t) - w.q_beta : w.mass - (gsl_cdf_ugaussian_P(t) - w.phi_alpha);
}

Window make_window(double mean, double sd, double lower, double upper) {
  Window w;
  w.alpha = (lower - mean) / sd;
  w.beta = (upper - mean) / sd;
  w.mirrored = w.alpha > 0.0;
  if (w.mirrored) {
    const double a = -w.beta;
    w.beta = -w.alpha;
    w.alpha = a;
  }
  w.phi_alpha = gsl_cdf_ugaussian_P(w.alpha);
  w.q_beta = gsl_cdf_ugaussian_Q(w.beta);
  // alpha <= 0: for beta <= 0 both Phi values are small and exact; otherwise 1 - Q - Phi.
  if (std::isfinite(w.alpha) && close_ends(w.alpha, w.beta)) {
    w.mass = density_integral(w.alpha, w.beta);
  } else {
    w.mass = w.beta <= 0.0 ? gsl_cdf_ugaussian_P(w.beta) - w.phi_alpha : (1.0 - w.q_beta) - w.phi_alpha;
  }
  return w;
}

// Phi^-1(p) evaluated from whichever of p and q = 1 - p is below 1/2.
double inverse_from_lower(double p) {
  return p <= 0.5 ? gsl_cdf_ugaussian_Pinv(p) : gsl_cdf_ugaussian_Qinv(1.0 - p);
}
double inverse_from_upper(double q) {
  return q <= 0.5 ? gsl_cdf_ugaussian_Qinv(q) : gsl_cdf_ugaussian_Pinv(1.0 - q);
}

// Standardized quantile of the window at lower-tail probability u (uc = 1 - u, given exactly).
double window_quantile(const Window& w, double u, double uc) {
  const double z = u <= 0.5 ? inverse_from_lower(w.phi_alpha + u * w.mass)
                            : inverse_from_upper(w.q_beta + uc * w.mass);
  // Rounding of the probabilities may step a hair outside the window; the law never does.
  return std::clamp(z, w.alpha, w.beta);
}

}  // namespace

TruncatedNormal::TruncatedNormal(double mean, double sd, double lower, double upper)
    : mean_(mean), sd_(sd), lower_(lower), upper_(upper) {
  detail::gsl_errors_return();
  detail::require_finite("truncated_normal", "mean", mean);
  detail::require_positive("truncated_normal", "sd", sd);
  if (std::isnan(lower) || lower == HUGE_VAL) {
    throw_bad_value("truncated_normal", "lower", format_double(lower), "a number or -inf");
  }
  if (std::isnan(upper) || upper == -HUGE_VAL) {
    throw_bad_value("truncated_normal", "upper", format_double(upper), "a number or inf");
  }
  if (!(upper > lower)) {
    throw_bad_value("truncated_normal", "upper", format_double(upper),
                    "a number above lower = " + format_double(lower));
  }
  window_ = make_window(mean, sd, lower, upper);
  if (!(window_.mass > 1e-300)) {
    throw InputError("truncated_normal",
                     "[lower, upper] = [" + format_double(lower) + ", " + format_double(upper) +
                         "] holds a probability of " + format_double(window_.mass) +
                         " under normal(mean = " + format_double(mean) + ", sd = " + format_double(sd) +
                         "): expected a window within ~37 sd of the mean");
  }
}

double pdf(const TruncatedNormal& distribution, double x) {
  if (!(x >= distribution.lower() && x <= distribution.upper()) || std::isinf(x)) return 0.0;
  const double z = (x - distribution.mean()) / distribution.sd();
  return std::exp(-0.5 * z * z) /
         (std::sqrt(2.0 * std::numbers::pi) * distribution.sd() * distribution.window().mass);
}

double cdf(const TruncatedNormal& distribution, double x) {
  if (std::isnan(x)) return x;
  if (x <= distribution.lower()) return 0.0;
  if (x >= distribution.upper()) return 1.0;
  const Window& w = distribution.window();
  const double z = (x - distribution.mean()) / distribution.sd();
  // Mirrored: P(X <= x) = P(Z' >= -z) over the mirrored window.
  const double part = w.mirrored ? mass_above(w, -z) : mass_below(w, z);
  return std::clamp(part / w.mass, 0.0, 1.0);
}

double quantile(const TruncatedNormal& distribution, double u) {
  detail::require_probability("truncated_normal", u);
  if (u == 0.0) return distribution.lower();
  if (u == 1.0) return distribution.upper();
  const Window& w = distribution.window();
  const double uc = 1.0 - u;
  const double x = w.mirrored ? distribution.mean() - distribution.sd() * window_quantile(w, uc, u)
                              : distribution.mean() + distribution.sd() * window_quantile(w, u, uc);
  return std::clamp(x, distribution.lower(), distribution.upper());
}

}  // namespace growthuq
