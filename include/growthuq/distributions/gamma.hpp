// The gamma law with shape k and scale theta: f(x) = x^{k-1} e^{-x/theta} / (Gamma(k) theta^k).
// Accuracy: the quantile is accurate to a few eps (1 + |ln x|) relative for every shape, both
// tails included. pdf and cdf are GSL's; for shapes above ~100 they lose relative accuracy of
// order eps k ln k (their exponent's terms are that large): ~1e-12 at k = 1000.
#pragma once

namespace growthuq {

class Gamma {
 public:
  // Finite shape > 0 and scale > 0, else InputError naming the parameter.
  Gamma(double shape, double scale);

  double shape() const { return shape_; }
  double scale() const { return scale_; }

 private:
  double shape_;
  double scale_;
};

double pdf(const Gamma& distribution, double x);
double cdf(const Gamma& distribution, double x);
double quantile(const Gamma& distribution, double u);

}  // namespace growthuq
