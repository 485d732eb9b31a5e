// The lognormal law: ln X ~ Normal(mu, sigma). Stiffness and diameters of pollen tubes are
// right-skewed and published as median and IQR (Eq. (D1), src/distributions/README.md), hence
// from_median_iqr.
#pragma once

namespace growthuq {

class Lognormal {
 public:
  // mu and sigma of ln X; sigma > 0, both finite, else InputError naming the parameter.
  Lognormal(double mu, double sigma);

  // The lognormal with median m and interquartile range r: mu = ln m, and r = m (e^{z sigma} -
  // e^{-z sigma}) with z = Phi^-1(0.75) gives sigma = asinh(r / (2 m)) / z (Eq. (D1)).
  static Lognormal from_median_iqr(double median, double iqr);

  double mu() const { return mu_; }
  double sigma() const { return sigma_; }
  double median() const;
  double iqr() const;  // Q(0.75) - Q(0.25) = 2 m sinh(z sigma)

 private:
  double mu_;
  double sigma_;
};

double pdf(const Lognormal& distribution, double x);
double cdf(const Lognormal& distribution, double x);
double quantile(const Lognormal& distribution, double u);

}  // namespace growthuq
