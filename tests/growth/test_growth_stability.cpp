// Stability of the viscosity and growth evaluators over the numerical envelope of
// src/mechanics/README.md, edges included and beyond (p = p0 exactly, eta from subnormal
// to 1e300, d and h at their limits): every sample gets a finite value or a status, never a silent
// NaN, and out_of_range is given exactly when the true value (computed in long double, whose
// exponent range is far wider) is outside the normal double range.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "growthuq/growth/growth_rate.hpp"
#include "growthuq/growth/viscosity.hpp"

using namespace growthuq;

namespace {

constexpr double dbl_min = std::numeric_limits<double>::min();
constexpr double dbl_max = std::numeric_limits<double>::max();

}  // namespace

TEST_CASE("growth rate over the envelope: finite value or status, out_of_range exactly when due") {
  const double p0 = 1e5;
  const double kappa = 0.05;
  // 13 x 12 x 9 x 9 = 12636 points. Pa, Pa s, m, m.
  const std::vector<double> ps{0.0, 1e4, std::nextafter(p0, 0.0), p0, std::nextafter(p0, 1e300),
                               1.0000001e5, 2e5, 8e5, 2e6, 1e9, 1e300, 1.7e308, 5e-324};
  const std::vector<double> etas{5e-324, 1e-300, 1e-10, 1.0, 1e6, 1e7, 1e8, 1e11, 1e15, 1e100, 1e300, 1.7e308};
  const std::vector<double> ds{1e-300, 1e-12, 1e-6, 4e-6, 6.56e-6, 2e-5, 5e-5, 1.0, 1e100};
  const std::vector<double> hs{1e-300, 1e-10, 2e-8, 1e-7, 1.45e-7, 5e-7, 2e-6, 1e-3, 1e200};
  const std::size_t n = ps.size() * etas.size() * ds.size() * hs.size();
  REQUIRE(n >= 10000);

  std::vector<double> p, eta, d, h;
  for (double pi : ps)
    for (double ei : etas)
      for (double di : ds)
        for (double hi : hs) {
          p.push_back(pi);
          eta.push_back(ei);
          d.push_back(di);
          h.push_back(hi);
        }
  SampleBlock block(n);
  block.set_column("p", p);
  block.set_column("eta", eta);
  block.set_column("d", d);
  block.set_column("h", h);
  CHECK_NOTHROW(GrowthEvaluator({.p0 = p0, .kappa = kappa}).evaluate(block));
  const auto v = block.column("v");
  const auto status = block.status();

  std::size_t counts[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    CAPTURE(p[i]);
    CAPTURE(eta[i]);
    CAPTURE(d[i]);
    CAPTURE(h[i]);
    const long double exact = static_cast<long double>(kappa) * (static_cast<long double>(p[i]) - p0) * d[i] *
                              d[i] / (4.0L * eta[i] * h[i]);
    switch (status[i]) {
      case SampleStatus::ok:
        ++counts[0];
        REQUIRE(std::isfinite(v[i]));
        REQUIRE(v[i] > 0.0);
        // Six roundings in double against one exact-enough long double value.
        REQUIRE(std::abs(v[i] - exact) <= 8 * std::numeric_limits<double>::epsilon() * exact);
        break;
      case SampleStatus::no_growth:
        ++counts[1];
        REQUIRE(v[i] == 0.0);
        REQUIRE(p[i] <= p0);
        break;
      case SampleStatus::out_of_range:
        ++counts[2];
        REQUIRE(std::isnan(v[i]));
        REQUIRE((exact < dbl_min || exact > dbl_max));
        break;
      case SampleStatus::invalid_input:
        ++counts[3];
        REQUIRE(std::isnan(v[i]));
        break;
      default:
        FAIL("unexpected status " << static_cast<int>(status[i]));
    }
  }
  // Every input of the grid is finite and positive (or p = 0), so nothing is invalid; the grid
  // reaches every other outcome.
  CHECK(counts[3] == 0);
  CHECK(counts[0] > 1000);
  CHECK(counts[1] > 1000);
  CHECK(counts[2] > 1000);
  // Inside the envelope (src/mechanics/README.md) every growing sample has a value.
  for (std::size_t i = 0; i < n; ++i) {
    const bool in_envelope = p[i] > p0 && p[i] <= 2e6 && eta[i] >= 1e6 && eta[i] <= 1e11 && d[i] >= 1e-6 &&
                             d[i] <= 5e-5 && h[i] >= 2e-8 && h[i] <= 2e-6;
    if (in_envelope) REQUIRE(status[i] == SampleStatus::ok);
  }
}

TEST_CASE("viscosity over the envelope: finite value or status") {
  // tau 0-1e6 s, einf from 0 to just below 1 and beyond, E 1e-300 to 1e308 Pa: 10 x 9 x 8 points.
  const std::vector<double> taus{0.0, 5e-324, 1e-300, 1e-3, 0.5, 6.81, 100.0, 1e6, 1e300, 1.7e308};
  const std::vector<double> einfs{0.0, 1e-300, 0.5, 0.65, 0.99, 1 - 1e-12, std::nextafter(1.0, 0.0), 1.0, 2.0};
  const std::vector<double> moduli{1e-300, 1.0, 1e6, 5e7, 1e9, 1e100, 1e300, 1.7e308};
  std::vector<double> tau, einf, modulus;
  for (double t : taus)
    for (double e : einfs)
      for (double m : moduli) {
        tau.push_back(t);
        einf.push_back(e);
        modulus.push_back(m);
      }
  SampleBlock block(tau.size());
  block.set_column("tau", tau);
  block.set_column("einf", einf);
  block.set_column("E", modulus);
  CHECK_NOTHROW(ViscosityEvaluator().evaluate(block));
  const auto eta = block.column("eta");
  for (std::size_t i = 0; i < block.size(); ++i) {
    CAPTURE(tau[i]);
    CAPTURE(einf[i]);
    CAPTURE(modulus[i]);
    const long double exact = static_cast<long double>(tau[i]) * (1.0L - einf[i]) * modulus[i];
    const auto status = block.status()[i];
    if (!(tau[i] > 0) || einf[i] >= 1.0) {
      REQUIRE(status == SampleStatus::invalid_input);
    } else if (exact < dbl_min || exact > dbl_max) {
      REQUIRE(status == SampleStatus::out_of_range);
    } else {
      REQUIRE(status == SampleStatus::ok);
      REQUIRE(std::abs(eta[i] - exact) <= 4 * std::numeric_limits<double>::epsilon() * exact);
    }
    if (status != SampleStatus::ok) REQUIRE(std::isnan(eta[i]));
  }
}
