// Sample quantiles (type 7) against numpy.quantile's default method.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/stats/sample_summary.hpp"

using namespace growthuq;

namespace {

// numpy's figures for the sample {3.1, -1.0, 7.5, 2.2, 2.2, 10.0, 0.4}:
// /usr/bin/python3 -c "import numpy as np; x=np.array([3.1,-1.0,7.5,2.2,2.2,10.0,0.4]);
//   print([float(np.quantile(x,p)) for p in (0,0.1,0.25,0.5,0.75,0.9,1)])"
//   -> [-1.0, -0.1599999999999998, 1.3, 2.2, 5.3, 8.5, 10.0]
// Same arithmetic as numpy's up to one rounding of the interpolation: 4 ulps.
void check_numpy_figures(const SampleSummary& s) {
  CHECK(s.count == 7);
  CHECK(s.p10 == doctest::Approx(-0.1599999999999998).epsilon(4e-16));
  CHECK(s.q1 == doctest::Approx(1.3).epsilon(4e-16));
  CHECK(s.median == 2.2);
  CHECK(s.q3 == doctest::Approx(5.3).epsilon(4e-16));
  CHECK(s.p90 == doctest::Approx(8.5).epsilon(4e-16));
  CHECK(s.iqr() == doctest::Approx(4.0).epsilon(4e-16));
}

}  // namespace

TEST_CASE("summary equals numpy.quantile (method='linear')") {
  const std::vector<double> x{3.1, -1.0, 7.5, 2.2, 2.2, 10.0, 0.4};
  check_numpy_figures(summarize(x));
  const std::vector<double> sorted{-1.0, 0.4, 2.2, 2.2, 3.1, 7.5, 10.0};
  CHECK(sorted_quantile(sorted, 0.0) == -1.0);
  CHECK(sorted_quantile(sorted, 1.0) == 10.0);
  const std::vector<double> one{4.5};
  CHECK(summarize(one).median == 4.5);
}

TEST_CASE("summary rejects empty and non-finite samples") {
  CHECK_THROWS_AS(summarize({}), InputError);
  const std::vector<double> bad{1.0, INFINITY};
  CHECK_THROWS_WITH_AS(summarize(bad), "sample summary: value 2 is not finite", InputError);
}

TEST_CASE("the summary of sorted values is the numpy one too") {
  // The same sample, ascending (growthuq sample orders a column by its strata instead of
  // sorting it).
  const std::vector<double> sorted{-1.0, 0.4, 2.2, 2.2, 3.1, 7.5, 10.0};
  check_numpy_figures(summarize_sorted(sorted));
  CHECK_THROWS_AS(summarize_sorted({}), InputError);
}
