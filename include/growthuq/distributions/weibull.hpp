// The Weibull law with shape k and scale lambda: F(x) = 1 - exp(-(x/lambda)^k), x >= 0.
#pragma once

namespace growthuq {

class Weibull {
 public:
  // Finite shape > 0 and scale > 0, else InputError naming the parameter.
  Weibull(double shape, double scale);

  double shape() const { return shape_; }
  double scale() const { return scale_; }

 private:
  double shape_;
  double scale_;
};

double pdf(const Weibull& distribution, double x);
double cdf(const Weibull& distribution, double x);
double quantile(const Weibull& distribution, double u);

}  // namespace growthuq
