// The last step of the inverse: the Young's modulus E that gives a measured stiffness k over
// the force window on one dimensionless force curve. At fixed p/E, h0/d0, rho/d0 (and the rest
// of the geometry) the force is F = E d0^2 G(delta/d0), so every E reads the same curve G with
// the window [F_low, F_high] / (E d0^2): a 1-D root in E, no further finite-element solve.
#pragma once

#include <span>

namespace growthuq::fe {

enum class ModulusMatchStatus {
  ok,
  curve_too_short,  // the root lies at an E whose window top F_high/(E d0^2) is beyond the curve
  no_root,          // k is not reached by any E the curve can serve (or Brent did not converge)
  invalid_input,
};

struct ModulusMatch {
  ModulusMatchStatus status = ModulusMatchStatus::ok;
  double young = 0.0;              // E, Pa
  double fitted_stiffness = 0.0;   // k of the curve at that E, N/m
  double least_young = 0.0;        // the smallest E the curve serves (window top = its largest G)
  int iterations = 0;
};

// `depth` = delta/d0 and `force` = F/(E d0^2) of one curve; `stiffness` the tube's k (sensor
// correction already applied), N/m; `d0` m; the force window in N; `estimate` a first E (e.g.
// the closed-form inverse's), Pa. The root is found on ln E by Brent's method (GSL) to a
// relative width of 1e-10.
ModulusMatch match_modulus(std::span<const double> depth, std::span<const double> force, double stiffness, double d0,
                           double window_low, double window_high, double estimate);

// k over the window at modulus E on the dimensionless curve, N/m (NaN when the window top is
// beyond the curve): what match_modulus solves k(E) = stiffness for.
double curve_stiffness(std::span<const double> depth, std::span<const double> force, double young, double d0,
                       double window_low, double window_high);

}  // namespace growthuq::fe
