// The normal law N(mean, sd).
#pragma once

namespace growthuq {

class Normal {
 public:
  // Finite mean, finite sd > 0, else InputError naming the parameter.
  Normal(double mean, double sd);

  double mean() const { return mean_; }
  double sd() const { return sd_; }

 private:
  double mean_;
  double sd_;
};

double pdf(const Normal& distribution, double x);
double cdf(const Normal& distribution, double x);
double quantile(const Normal& distribution, double u);

}  // namespace growthuq
