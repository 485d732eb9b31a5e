// The normal law N(mean, sd) restricted to [lower, upper] and renormalized. mean and sd are
// the PARENT normal's parameters, not the moments of the truncated law. pdf, cdf and quantile
// keep their relative accuracy up to both truncation points and in the parent's far tails.
#pragma once

namespace growthuq {

class TruncatedNormal {
 public:
  // Finite mean, finite sd > 0, lower < upper (either bound may be infinite for one-sided
  // truncation, never NaN), and [lower, upper] must hold a parent probability above 1e-300
  // (below that the law cannot be represented in double precision). InputError otherwise.
  TruncatedNormal(double mean, double sd, double lower, double upper);

  double mean() const { return mean_; }
  double sd() const { return sd_; }
  double lower() const { return lower_; }
  double upper() const { return upper_; }

  // The window in standard units, precomputed once for pdf/cdf/quantile. A window right of
  // the mean (standardized lower end > 0) is stored mirrored, so that the normal
  // probabilities used are lower-tail values that keep full relative accuracy.
  struct Window {
    double alpha = 0;          // standardized lower end after mirroring (<= 0)
    double beta = 0;           // standardized upper end after mirroring
    bool mirrored = false;     // X = mean - sd Z instead of mean + sd Z
    double phi_alpha = 0;      // Phi(alpha)
    double q_beta = 0;         // Q(beta) = 1 - Phi(beta)
    double mass = 0;           // Phi(beta) - Phi(alpha), the parent probability of the window
  };
  const Window& window() const { return window_; }

 private:
  double mean_;
  double sd_;
  double lower_;
  double upper_;
  Window window_;
};

double pdf(const TruncatedNormal& distribution, double x);
double cdf(const TruncatedNormal& distribution, double x);
double quantile(const TruncatedNormal& distribution, double u);

}  // namespace growthuq
