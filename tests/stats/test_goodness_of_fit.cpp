// Kolmogorov-Smirnov and Anderson-Darling statistics against scipy.stats on a fixed sample.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "growthuq/distributions/distribution.hpp"
#include "growthuq/stats/goodness_of_fit.hpp"

using namespace growthuq;

namespace {

const std::vector<double> sample{4.1, 5.3, 2.2, 6.8, 5.0, 3.9, 7.4, 4.6, 5.9, 3.1, 6.2, 4.8};

std::vector<double> sorted_cdf(const Distribution& law) {
  std::vector<double> values = sample;
  std::sort(values.begin(), values.end());
  for (double& x : values) x = cdf(law, x);
  return values;
}

}  // namespace

TEST_CASE("KS and AD statistics equal scipy.stats on a fixed sample") {
  // /usr/bin/python3 -c "import numpy as np, scipy.stats as st; d=np.array([4.1,5.3,2.2,6.8,5.0,3.9,7.4,4.6,5.9,3.1,6.2,4.8]);
  //   print(repr(st.kstest(d,'norm',args=(5.0,2.0)).statistic), repr(st.kstest(d,'lognorm',args=(0.4,0,5.0)).statistic),
  //         repr(st.anderson(d,'norm').statistic), repr(d.mean()), repr(d.std(ddof=1)))"   (scipy 1.10.1)
  // Each statistic is a max or sum of 12 terms of size <= 1 built from cdf values accurate to
  // ~1e-16, so agreement to 1e-14 absolute is expected; a wrong index or weight is off by > 1e-3.
  CHECK(kolmogorov_smirnov_statistic(sorted_cdf(Normal(5.0, 2.0))) == doctest::Approx(0.1244930201216797).epsilon(1e-14));
  CHECK(kolmogorov_smirnov_statistic(sorted_cdf(Lognormal(std::log(5.0), 0.4))) ==
        doctest::Approx(0.16351709151020088).epsilon(1e-14));
  // scipy's anderson(..., 'norm') uses the sample mean and the sd with divisor n - 1.
  CHECK(anderson_darling_statistic(sorted_cdf(Normal(4.941666666666666, 1.5066267760876422))) ==
        doctest::Approx(0.09861934156422691).epsilon(1e-13));
}

TEST_CASE("KS and AD: closed forms and edge cases") {
  // One point at F = 1/2: D = 1/2; A^2 = -1 - 2 ln(1/2) = 2 ln 2 - 1.
  const std::vector<double> half{0.5};
  CHECK(kolmogorov_smirnov_statistic(half) == 0.5);
  CHECK(anderson_darling_statistic(half) == doctest::Approx(2 * std::log(2.0) - 1).epsilon(1e-15));
  // Points at the centres of n equal strata: D = 1/(2n), the smallest possible.
  std::vector<double> centred(10);
  for (std::size_t i = 0; i < centred.size(); ++i) centred[i] = (static_cast<double>(i) + 0.5) / 10.0;
  CHECK(kolmogorov_smirnov_statistic(centred) == doctest::Approx(0.05).epsilon(1e-15));
  const std::vector<double> impossible{0.2, 1.0};
  CHECK(anderson_darling_statistic(impossible) == HUGE_VAL);
  const std::vector<double> unsorted{0.6, 0.2};
  CHECK_THROWS_AS(kolmogorov_smirnov_statistic(unsorted), std::invalid_argument);
  CHECK_THROWS_AS(anderson_darling_statistic(std::vector<double>{}), std::invalid_argument);
  CHECK_THROWS_AS(anderson_darling_statistic(std::vector<double>{0.1, std::nan("")}), std::invalid_argument);
}
