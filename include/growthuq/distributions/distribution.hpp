// The probability laws a variable of a plant line can follow, as immutable values (in the
// manner of Boost.Math distributions): constructors validate their parameters and throw
// InputError naming the bad one; pdf, cdf and quantile are free functions. `Distribution` is
// the closed set of laws the engine knows, used wherever a law is read from a file.
//
// CONTRACT (fixed; other components rely on these signatures):
//   double pdf(const Distribution&, double x);
//   double cdf(const Distribution&, double x);
//   double quantile(const Distribution&, double u);        // u in (0,1): finite, no 0/inf at the tails
//   void quantiles(const Distribution&, std::span<const double> u, std::span<double> x);  // batch, fast
//   std::string_view family_name(const Distribution&);     // "lognormal", "normal", ...
//   std::string describe(const Distribution&);             // "lognormal(mu=1.05, sigma=0.21)"
#pragma once

#include <utility>

#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace growthuq {

class Lognormal;
class Normal;
class TruncatedNormal;
class Uniform;
class Gamma;
class Weibull;
class Beta;
class Empirical;

}  // namespace growthuq

#include "growthuq/distributions/families.hpp"

namespace growthuq {

using Distribution = std::variant<Lognormal, Normal, TruncatedNormal, Uniform, Gamma, Weibull, Beta, Empirical>;

double pdf(const Distribution& distribution, double x);
double cdf(const Distribution& distribution, double x);
double quantile(const Distribution& distribution, double u);
void quantiles(const Distribution& distribution, std::span<const double> u, std::span<double> x);
std::string_view family_name(const Distribution& distribution);
std::string describe(const Distribution& distribution);

// The parameters describe() prints, by name and unrounded, in its order: lognormal mu, sigma;
// normal mean, sd; truncated_normal mean, sd, lower, upper; uniform lower, upper; gamma and
// weibull shape, scale; beta alpha, beta, upper; empirical n, min, max. For files that keep fits as numbers (results.h5).
std::vector<std::pair<std::string, double>> parameter_values(const Distribution& distribution);

}  // namespace growthuq
