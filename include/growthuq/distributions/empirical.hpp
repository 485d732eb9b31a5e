// The law of a measured sample itself, for quantities no parametric family fits. Choice: the
// linearly interpolated empirical CDF between order statistics x(1) <= ... <= x(n), with
// F(x(i)) = (i - 1) / (n - 1), so the support is [min, max], the density is piecewise constant
// and the quantile is the linear interpolation of order statistics (Hyndman & Fan 1996, type 7,
// the default of R and numpy). It never extrapolates beyond the observed range.
#pragma once

#include <vector>

namespace growthuq {

class Empirical {
 public:
  // At least two finite values, not all equal; InputError naming the offending value otherwise.
  explicit Empirical(std::vector<double> data);

  const std::vector<double>& sorted_data() const { return sorted_; }
  double lower() const { return sorted_.front(); }
  double upper() const { return sorted_.back(); }

 private:
  std::vector<double> sorted_;
};

double pdf(const Empirical& distribution, double x);  // right-continuous at order statistics
double cdf(const Empirical& distribution, double x);
double quantile(const Empirical& distribution, double u);

}  // namespace growthuq
