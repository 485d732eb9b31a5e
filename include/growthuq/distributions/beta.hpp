// The beta law of a fraction: X = upper B with B ~ Beta(alpha, beta), density
// f(x) = (x/upper)^{alpha-1} (1 - x/upper)^{beta-1} / (upper B(alpha, beta)) on [0, upper]
// (Eq. (D9), src/distributions/README.md). `upper` is where the fraction is 1 in the values'
// unit (1 for frac, 100 for %); it is fixed by the unit, not estimated. Bounded on both sides, so
// no value it gives lies outside [0, 100] %, unlike the other families fitted to e_inf.
#pragma once

namespace growthuq {

class Beta {
 public:
  // Finite alpha > 0, beta > 0 and upper > 0, else InputError naming the parameter.
  Beta(double alpha, double beta, double upper = 1.0);

  double alpha() const { return alpha_; }
  double beta() const { return beta_; }
  double upper() const { return upper_; }

 private:
  double alpha_;
  double beta_;
  double upper_;
};

double pdf(const Beta& distribution, double x);
double cdf(const Beta& distribution, double x);
double quantile(const Beta& distribution, double u);

}  // namespace growthuq
