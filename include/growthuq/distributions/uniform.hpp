// The uniform law on [lower, upper].
#pragma once

namespace growthuq {

class Uniform {
 public:
  // Finite lower < upper, else InputError naming the parameter.
  Uniform(double lower, double upper);

  double lower() const { return lower_; }
  double upper() const { return upper_; }

 private:
  double lower_;
  double upper_;
};

double pdf(const Uniform& distribution, double x);
double cdf(const Uniform& distribution, double x);
double quantile(const Uniform& distribution, double u);

}  // namespace growthuq
