#include "growthuq/relaxation/prony_fit.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multimin.h>

#include "core/gsl_errors.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>
#include <utility>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "relaxation/nnls.hpp"
#include "growthuq/relaxation/simulator.hpp"

namespace growthuq {
namespace {

// Columns of the linear model for given relaxation times: column 0 the constant (or k_inf)
// term, column i + 1 the i-th mode. The amplitudes are the NNLS solution on these columns.
// `extra` is one more nonlinear parameter some bases have (the ramp-aware fit's ramp time).
using Basis = std::function<Eigen::MatrixXd(const std::vector<double>& tau, double extra)>;

struct Projection {
  Eigen::VectorXd coefficients;
  double rss = 0.0;
};

// Variable projection: for fixed taus the best non-negative amplitudes and the residual.
// Columns are scaled to unit norm for NNLS (a slow and a fast exponential differ in norm by
// orders of magnitude) and the coefficients scaled back. With A = Q R (thin QR, one
// Householder pass over the n samples), |A x - y|^2 = |R x - Q^T y|^2 + const for every x, so
// NNLS runs on the (terms + 1) x (terms + 1) triangle instead of the n x (terms + 1) basis:
// the active-set walk then costs nothing next to the QR, without squaring the condition
// number as the normal equations would.
Projection project(const Eigen::MatrixXd& basis, const Eigen::VectorXd& y) {
  Eigen::VectorXd norms = basis.colwise().norm().transpose();
  for (Eigen::Index j = 0; j < norms.size(); ++j) {
    if (!(norms(j) > 0.0)) norms(j) = 1.0;
  }
  const Eigen::MatrixXd scaled = basis * norms.cwiseInverse().asDiagonal();
  const Eigen::Index columns = scaled.cols();
  Eigen::VectorXd coefficients;
  if (scaled.rows() > columns) {
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(scaled);
    const Eigen::MatrixXd r = qr.matrixQR().topRows(columns).triangularView<Eigen::Upper>();
    const Eigen::VectorXd rotated = (qr.householderQ().transpose() * y).head(columns);
    coefficients = solve_nnls(r, rotated);
  } else {
    coefficients = solve_nnls(scaled, y);
  }
  Projection projection;
  projection.coefficients = coefficients.cwiseQuotient(norms);
  projection.rss = (basis * projection.coefficients - y).squaredNorm();
  return projection;
}

// Ordered, bounded taus from unconstrained z: s_i = s_{i-1} + (ln tau_max - s_{i-1}) sigma(z_i),
// s_0 = ln tau_min, sigma the logistic function; then tau_min < tau_1 < ... < tau_max for every
// real z, so a derivative-free search needs no constraint handling.
std::vector<double> taus_from(const gsl_vector* z, std::size_t terms, double log_min, double log_max) {
  std::vector<double> tau(terms);
  double lower = log_min;
  for (std::size_t i = 0; i < terms; ++i) {
    const double fraction = 1.0 / (1.0 + std::exp(-gsl_vector_get(z, i)));
    lower += (log_max - lower) * fraction;
    tau[i] = std::exp(lower);
  }
  return tau;
}

// The inverse map, for starting points given as ordered log taus strictly inside the bounds.
void z_from(const std::vector<double>& log_tau, double log_min, double log_max, gsl_vector* z) {
  double lower = log_min;
  for (std::size_t i = 0; i < log_tau.size(); ++i) {
    const double fraction = (log_tau[i] - lower) / (log_max - lower);
    gsl_vector_set(z, i, std::log(fraction / (1.0 - fraction)));
    lower = log_tau[i];
  }
}

struct Problem {
  const Basis* basis;
  const Eigen::VectorXd* y;
  std::size_t terms;
  double log_min;
  double log_max;
  double scale;  // 1 / |y|^2, so that the simplex tolerance is scale-free
  double extra_min = 0.0;  // bounds of the extra parameter when extra_min < extra_max; it is
  double extra_max = 0.0;  // then the last z, mapped by the logistic function like the taus
};

double extra_from(const gsl_vector* z, const Problem& problem) {
  if (!(problem.extra_max > problem.extra_min)) return problem.extra_min;
  const double fraction = 1.0 / (1.0 + std::exp(-gsl_vector_get(z, problem.terms)));
  return problem.extra_min + (problem.extra_max - problem.extra_min) * fraction;
}

double projected_residual(const gsl_vector* z, void* data) {
  const auto& problem = *static_cast<const Problem*>(data);
  const auto tau = taus_from(z, problem.terms, problem.log_min, problem.log_max);
  const double rss = project((*problem.basis)(tau, extra_from(z, problem)), *problem.y).rss;
  return std::isfinite(rss) ? rss * problem.scale : std::numeric_limits<double>::max();
}

struct Minimum {
  std::vector<double> tau;
  double extra = 0.0;
  double objective = std::numeric_limits<double>::infinity();
  bool converged = false;
};

// Nelder-Mead (GSL nmsimplex2) from one start. The projected residual is continuous but not
// smooth where NNLS's active set changes, and it has at most three unknowns: a simplex is
// robust there and cheap, where gsl_multifit_nlinear would need a Jacobian of a non-smooth map.
Minimum minimize_from(const std::vector<double>& start, Problem& problem) {
  detail::gsl_errors_return();  // GSL reports through return codes; it must never abort a run
  const bool has_extra = problem.extra_max > problem.extra_min;
  const std::size_t n = start.size() + (has_extra ? 1 : 0);
  gsl_multimin_function function{projected_residual, n, &problem};
  std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> z(gsl_vector_alloc(n), gsl_vector_free);
  std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> step(gsl_vector_alloc(n), gsl_vector_free);
  z_from(start, problem.log_min, problem.log_max, z.get());
  if (has_extra) gsl_vector_set(z.get(), start.size(), 0.0);  // the middle of its interval
  gsl_vector_set_all(step.get(), 1.0);
  std::unique_ptr<gsl_multimin_fminimizer, decltype(&gsl_multimin_fminimizer_free)> minimizer(
      gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, n), gsl_multimin_fminimizer_free);
  gsl_multimin_fminimizer_set(minimizer.get(), &function, z.get(), step.get());

  Minimum minimum;
  for (int iteration = 0; iteration < 600 * static_cast<int>(n); ++iteration) {
    if (gsl_multimin_fminimizer_iterate(minimizer.get()) != GSL_SUCCESS) break;
    // 1e-6 in z is 1e-6 relative in tau away from the bounds: far below any data's resolution.
    if (gsl_multimin_test_size(gsl_multimin_fminimizer_size(minimizer.get()), 1e-6) == GSL_SUCCESS) {
      minimum.converged = true;
      break;
    }
  }
  minimum.tau = taus_from(gsl_multimin_fminimizer_x(minimizer.get()), problem.terms, problem.log_min, problem.log_max);
  minimum.extra = extra_from(gsl_multimin_fminimizer_x(minimizer.get()), problem);
  minimum.objective = gsl_multimin_fminimizer_minimum(minimizer.get());
  return minimum;
}

// Starting log taus: every ordered choice of `terms` among `levels` points spread evenly
// inside [log_min, log_max] (5 starts for 1 term, 6 for 2, 10 for 3).
std::vector<std::vector<double>> starting_points(int terms, double log_min, double log_max) {
  const int levels = terms == 2 ? 4 : 5;
  std::vector<std::vector<double>> starts;
  std::vector<int> choice(static_cast<std::size_t>(terms));
  std::function<void(int, int)> choose = [&](int position, int first) {
    if (position == terms) {
      std::vector<double> start;
      for (int level : choice) start.push_back(log_min + (log_max - log_min) * (level + 0.5) / levels);
      starts.push_back(start);
      return;
    }
    for (int level = first; level < levels; ++level) {
      choice[static_cast<std::size_t>(position)] = level;
      choose(position + 1, level + 1);
    }
  };
  choose(0, 0);
  return starts;
}

std::string tau_name(int terms, std::size_t i) {
  if (terms == 1) return "tau";
  if (i == 0) return "tau_fast";
  if (i + 1 == static_cast<std::size_t>(terms)) return "tau_slow";
  return "tau_mid";
}

void validate(std::span<const double> t, std::span<const double> y, const PronyFitOptions& options,
              const char* where) {
  if (options.terms < 1 || options.terms > 3) {
    throw_bad_value(where, "terms", std::to_string(options.terms), "1, 2 or 3");
  }
  if (!(options.tau_min > 0.0) || !(options.tau_max > options.tau_min) || !std::isfinite(options.tau_max)) {
    throw InputError(where, "tau bounds [" + format_double(options.tau_min) + ", " + format_double(options.tau_max) +
                                "] s: expected 0 < tau_min < tau_max");
  }
  if (t.size() != y.size()) throw InputError(where, "times and values differ in number");
  const std::size_t needed = 2 * static_cast<std::size_t>(options.terms) + 2;
  if (t.size() < needed) {
    throw InputError(where, std::to_string(t.size()) + " points: expected at least " + std::to_string(needed));
  }
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i]) || !std::isfinite(y[i])) throw InputError(where, "a time or value is not finite");
  }
}

// The 95 % profile-likelihood interval of the slowest tau (Eq. (R6b)): at each fixed slowest
// tau the other taus are searched again (the amplitudes by NNLS, as in the fit), and the
// interval is where the deviance n ln(RSS / RSS_min) stays below chi^2_1(0.95) = 3.84. With a
// record shorter than tau the slow exponential is nearly a line over the record and the
// linearized standard error says little (the residual is far from quadratic in ln tau); the
// profile follows the residual itself, and e_inf >= 0 bounds tau from above when the data do.
struct SlowInterval {
  double low = 0.0;
  double high = 0.0;
  bool low_found = false;
  bool high_found = false;
};

class SlowProfile {
 public:
  SlowProfile(const Basis& basis, const Eigen::VectorXd& y, const PronyFitOptions& options, double rss_min)
      : basis_(basis), y_(y), terms_(static_cast<std::size_t>(options.terms)), log_min_(std::log(options.tau_min)),
        rss_min_(std::max(rss_min, 1e-300)), n_(static_cast<double>(y.size())) {}

  // Deviance at ln tau_slow = log_slow; `faster` (ln of the other taus) is the warm start and
  // returns their optimum there, so that a walk along the profile continues from its last step.
  double deviance(double log_slow, std::vector<double>& faster) const {
    double rss = 0.0;
    if (terms_ == 1) {
      rss = project(basis_({std::exp(log_slow)}, 0.0), y_).rss;
    } else {
      const double slow = std::exp(log_slow);
      const Basis with_slow = [this, slow](const std::vector<double>& tau, double extra) {
        std::vector<double> all = tau;
        all.push_back(slow);
        return basis_(all, extra);
      };
      Problem problem{&with_slow, &y_, terms_ - 1, log_min_, log_slow, 1.0 / std::max(y_.squaredNorm(), 1e-300)};
      // The start strictly inside (log_min, log_slow) and ordered, as z_from needs.
      const double margin = (log_slow - log_min_) / (2.0 * static_cast<double>(terms_));
      for (std::size_t i = 0; i < faster.size(); ++i) {
        const double lowest = log_min_ + margin * static_cast<double>(i + 1);
        const double highest = log_slow - margin * static_cast<double>(faster.size() - i);
        faster[i] = std::clamp(faster[i], lowest, highest);
      }
      const Minimum minimum = minimize_from(faster, problem);
      for (std::size_t i = 0; i < faster.size(); ++i) faster[i] = std::log(minimum.tau[i]);
      rss = minimum.objective / problem.scale;
    }
    return n_ * std::log(std::max(rss, 1e-300) / rss_min_);
  }

 private:
  const Basis& basis_;
  const Eigen::VectorXd& y_;
  std::size_t terms_;
  double log_min_;
  double rss_min_;
  double n_;
};

constexpr double profile_threshold = 3.841458820694124;  // chi^2 quantile 0.95, 1 degree of freedom

// Walks from the estimate toward `limit` (ln tau) in growing steps until the deviance exceeds
// the threshold, then bisects to 0.2 % in tau. Returns the crossing, or `limit` not found.
std::pair<double, bool> profile_end(const SlowProfile& profile, double log_hat, std::vector<double> faster, double limit) {
  const double direction = limit > log_hat ? 1.0 : -1.0;
  double inside = log_hat, step = 0.05;
  std::vector<double> inside_faster = faster;
  while (direction * (limit - inside) > 1e-9) {
    const double trial = direction > 0 ? std::min(inside + step, limit) : std::max(inside - step, limit);
    std::vector<double> trial_faster = inside_faster;
    if (profile.deviance(trial, trial_faster) > profile_threshold) {
      double outside = trial;
      while (std::abs(outside - inside) > 2e-3) {
        const double middle = 0.5 * (inside + outside);
        std::vector<double> middle_faster = inside_faster;
        if (profile.deviance(middle, middle_faster) > profile_threshold) {
          outside = middle;
        } else {
          inside = middle;
          inside_faster = middle_faster;
        }
      }
      return {0.5 * (inside + outside), true};
    }
    inside = trial;
    inside_faster = trial_faster;
    step *= 1.5;
  }
  return {limit, false};
}

SlowInterval slow_interval(const Basis& basis, const Eigen::VectorXd& y, const PronyFitOptions& options,
                           const std::vector<double>& tau, double rss_min) {
  const SlowProfile profile(basis, y, options, rss_min);
  std::vector<double> faster;
  for (std::size_t i = 0; i + 1 < tau.size(); ++i) faster.push_back(std::log(tau[i]));
  const double log_hat = std::log(tau.back());
  // Below, the faster taus need room: each at least min_separation from the next.
  const double lowest = std::log(options.tau_min) + static_cast<double>(faster.size()) * std::log(options.min_separation);
  SlowInterval interval;
  const auto [high, high_found] = profile_end(profile, log_hat, faster, std::log(options.tau_max));
  const auto [low, low_found] = profile_end(profile, log_hat, faster, std::min(lowest, log_hat));
  interval.high = std::exp(high);
  interval.high_found = high_found;
  interval.low = std::exp(low);
  interval.low_found = low_found;
  return interval;
}

// The extra parameter's search interval [min, max]. The projected residual may not depend on it
// at all up to `flat_end` (the ramp-aware fit's ramp end before the first sample, see
// fit_ramp_hold): a minimum found there is reported at the middle of [min, min(max, flat_end)],
// not wherever the search happened to stop.
struct ExtraParameter {
  double min = 0.0;
  double max = 0.0;
  double flat_end = -std::numeric_limits<double>::infinity();
};

PronyFit fit(const Basis& basis, std::span<const double> values, const PronyFitOptions& options,
             const ExtraParameter& extra = {}) {
  const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
  Problem problem{&basis, &y, static_cast<std::size_t>(options.terms), std::log(options.tau_min), std::log(options.tau_max),
                  1.0 / std::max(y.squaredNorm(), 1e-300), extra.min, extra.max};

  Minimum best;
  for (const auto& start : starting_points(options.terms, problem.log_min, problem.log_max)) {
    Minimum candidate = minimize_from(start, problem);
    if (candidate.objective < best.objective) best = candidate;
  }
  if (best.extra <= extra.flat_end) best.extra = 0.5 * (extra.min + std::min(extra.max, extra.flat_end));

  const Eigen::MatrixXd columns = basis(best.tau, best.extra);
  const Projection projection = project(columns, y);
  const auto n = static_cast<double>(values.size());
  const int terms = options.terms;
  PronyFit result;
  result.points = values.size();
  result.tau = best.tau;
  result.ramp_time = best.extra;
  result.einf = projection.coefficients(0);
  for (int i = 0; i < terms; ++i) result.amplitude.push_back(projection.coefficients(i + 1));
  result.rms = std::sqrt(projection.rss / n);
  result.aic = n * std::log(std::max(projection.rss, 1e-300) / n) + 2.0 * (2.0 * terms + 1.0);

  // Linearized standard errors of ln tau_i (Gauss-Newton covariance s^2 (J^T J)^-1 over the
  // amplitudes and ln taus; the ln tau columns by central differences of the basis).
  const Eigen::Index p = 2 * terms + 1;
  Eigen::MatrixXd jacobian(columns.rows(), p);
  jacobian.leftCols(terms + 1) = columns;
  for (int i = 0; i < terms; ++i) {
    constexpr double h = 1e-4;
    std::vector<double> up = best.tau, down = best.tau;
    up[static_cast<std::size_t>(i)] *= std::exp(h);
    down[static_cast<std::size_t>(i)] *= std::exp(-h);
    jacobian.col(terms + 1 + i) = projection.coefficients(i + 1) * (basis(up, best.extra).col(i + 1) - basis(down, best.extra).col(i + 1)) / (2.0 * h);
  }
  const double variance = projection.rss / std::max(n - static_cast<double>(p), 1.0);
  const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(normal);
  for (int i = 0; i < terms; ++i) {
    double se = std::numeric_limits<double>::infinity();
    if (lu.isInvertible()) {
      const double entry = lu.inverse()(terms + 1 + i, terms + 1 + i) * variance;
      if (entry >= 0.0) se = std::sqrt(entry);
    }
    result.tau_relative_se.push_back(se);
  }

  auto describe_tau = [&](std::size_t i) {
    std::ostringstream text;
    text << std::setprecision(4) << tau_name(terms, i) << " = " << best.tau[i] << " s";
    return text.str();
  };
  SlowInterval interval;
  if (options.profile_slowest) {
    interval = slow_interval(basis, y, options, best.tau, projection.rss);
    result.tau_slow_low = interval.low;
    result.tau_slow_high = interval.high;
  }
  const double lower = options.tau_min * (1.0 + options.bound_margin);
  const double upper = options.tau_max / (1.0 + options.bound_margin);
  std::ostringstream upper_text;
  upper_text << std::setprecision(4);
  if (options.record_length > 0.0) {
    upper_text << options.tau_max / options.record_length << " x the record length " << options.record_length << " s";
  } else {
    upper_text << "record length";
  }
  const std::string upper_what = upper_text.str();
  for (std::size_t i = 0; i < best.tau.size() && result.reason.empty(); ++i) {
    if (!(result.amplitude[i] > 0.0)) {
      result.reason = describe_tau(i) + " has zero amplitude: the data hold fewer than " + std::to_string(terms) + " exponentials";
    } else if (best.tau[i] < lower) {
      result.reason = describe_tau(i) + " is at the lower bound " + format_double(options.tau_min) +
                      " s (sampling interval): faster than the record resolves";
    } else if (best.tau[i] > upper) {
      std::ostringstream text;
      text << std::setprecision(4) << describe_tau(i) << " is at the upper bound " << options.tau_max << " s (" << upper_what
           << "): slower than the record resolves";
      result.reason = text.str();
    }
  }
  for (std::size_t i = 0; i + 1 < best.tau.size() && result.reason.empty(); ++i) {
    if (best.tau[i + 1] < options.min_separation * best.tau[i]) {
      result.reason = describe_tau(i) + " and " + describe_tau(i + 1) + " are within " +
                      format_double(std::round(to_pct(options.min_separation - 1.0))) + " % of each other: not separable";
    }
  }
  if (options.profile_slowest && result.reason.empty() && !interval.low_found) {
    std::ostringstream text;
    text << std::setprecision(4) << describe_tau(best.tau.size() - 1)
         << " is not separated from the faster times: its 95 % profile interval [" << interval.low << ", "
         << interval.high << "] s reaches them";
    result.reason = text.str();
  }
  if (options.profile_slowest && !interval.high_found) {
    // Not a failure: the record bounds tau_slow from below, and the estimate is the residual's
    // minimum inside the allowed range; the interval's upper end is that range's limit.
    std::ostringstream text;
    text << std::setprecision(4) << "the 95 % profile interval of " << tau_name(terms, best.tau.size() - 1)
         << " is open above: the record bounds it from below only (" << interval.low << " s), up to the limit "
         << options.tau_max << " s (" << upper_what << ")";
    result.note = text.str();
  }
  for (std::size_t i = 0; i < best.tau.size() && result.reason.empty(); ++i) {
    if (options.profile_slowest && i + 1 == best.tau.size()) continue;  // its profile interval decides
    if (!(result.tau_relative_se[i] <= options.max_relative_se)) {
      result.reason = describe_tau(i) + " is undetermined by the data (standard error " +
                      (std::isfinite(result.tau_relative_se[i]) ? format_double(std::round(to_pct(result.tau_relative_se[i]))) + " %)"
                                                                 : std::string("unbounded)"));
    }
  }
  if (result.reason.empty() && !best.converged) result.reason = "the simplex search did not converge";
  result.ok = result.reason.empty();
  result.extrapolated = result.ok && options.record_length > 0.0 && best.tau.back() >= options.record_length;
  return result;
}

}  // namespace

PronyFit fit_prony(std::span<const double> t, std::span<const double> y, const PronyFitOptions& options) {
  validate(t, y, options, "fit_prony");
  // Eigen's packet exp (SIMD) builds the columns several times faster than scalar std::exp;
  // the basis is rebuilt for every trial set of taus, so this is most of a fit's time.
  const Eigen::ArrayXd times = Eigen::Map<const Eigen::ArrayXd>(t.data(), static_cast<Eigen::Index>(t.size()));
  const Basis basis = [times](const std::vector<double>& tau, double) {
    Eigen::MatrixXd columns(times.size(), static_cast<Eigen::Index>(tau.size() + 1));
    columns.col(0).setOnes();
    for (std::size_t i = 0; i < tau.size(); ++i) {
      columns.col(static_cast<Eigen::Index>(i + 1)) = (times * (-1.0 / tau[i])).exp().matrix();
    }
    return columns;
  };
  return fit(basis, y, options);
}

PronyFit fit_ramp_hold(std::span<const double> t, std::span<const double> force, double ramp_time_min,
                       double ramp_time_max, double indentation, const PronyFitOptions& options) {
  validate(t, force, options, "fit_ramp_hold");
  if (!(ramp_time_min >= 0.0) || !(ramp_time_max >= ramp_time_min) || !(indentation > 0.0)) {
    throw InputError("fit_ramp_hold", "expected 0 <= ramp_time_min <= ramp_time_max and indentation > 0");
  }
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!(t[i] >= 0.0) || (i > 0 && !(t[i] > t[i - 1]))) {
      throw InputError("fit_ramp_hold", "times must be increasing and >= 0 (from contact, the start of the ramp)");
    }
  }
  const Basis basis = [t, indentation](const std::vector<double>& tau, double ramp_time) {
    return maxwell_mode_responses(tau, ramp_time, indentation, t);
  };
  // A ramp that ends by the first sample after contact leaves no sample inside it: every hold
  // column is then delta exp(-t / tau_i) times (tau_i / t_r)(exp(t_r / tau_i) - 1), a factor
  // the amplitude absorbs, so the residual is the same for every such ramp end (to the
  // integrator's tolerance) and the data cannot tell them apart.
  ExtraParameter ramp_end{ramp_time_min, ramp_time_max};
  const auto first_after_contact = std::find_if(t.begin(), t.end(), [](double time) { return time > 0.0; });
  if (first_after_contact != t.end()) ramp_end.flat_end = *first_after_contact;
  return fit(basis, force, options, ramp_end);
}

}  // namespace growthuq
