// Viscosity and growth-rate evaluators and the kappa calibration, against exact rational
// values, exact power-of-two scalings, and the calibration's defining property.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/growth/growth_rate.hpp"
#include "growthuq/growth/kappa.hpp"
#include "growthuq/growth/viscosity.hpp"

using namespace growthuq;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

bool close(double value, double reference, double relative) {
  return std::abs(value - reference) <= relative * std::abs(reference);
}

SampleBlock growth_block(std::vector<double> p, std::vector<double> d, std::vector<double> eta,
                         std::vector<double> h) {
  SampleBlock block(p.size());
  block.set_column("p", p);
  block.set_column("d", d);
  block.set_column("eta", eta);
  block.set_column("h", h);
  return block;
}

}  // namespace

TEST_CASE("viscosity eta = tau (1 - einf) E with statuses for bad or extreme inputs") {
  // Wild-type medians (published data, distributions/README.md) and E = 50 MPa.
  // Exact: 6.81 * 0.35 * 5e7 = 119175000 (python3 fractions). Three inputs rounded to double
  // and two products: at most 2.5 eps relative, 4 eps allowed.
  const std::vector<double> tau{6.81, 0.0, -1.0, not_a_number, inf, 5.0, 5.0, 5.0, 5.0, 5.0, 1e-300, 1e10, 5.0};
  const std::vector<double> einf{0.65, 0.5, 0.5, 0.5, 0.5, -0.01, 1.0, not_a_number, 0.5, 0.5, 0.5, 0.5, 0.0};
  const std::vector<double> modulus{5e7, 5e7, 5e7, 5e7, 5e7, 5e7, 5e7, 5e7, 0.0, inf, 1e-10, 1e300, 5e7};
  SampleBlock block(tau.size());
  block.set_column("tau", tau);
  block.set_column("einf", einf);
  block.set_column("E", modulus);
  block.flag(12, SampleStatus::lambda_not_above_one);  // flagged upstream: must be skipped
  ViscosityEvaluator().evaluate(block);
  const auto eta = block.column("eta");
  const auto status = block.status();

  CHECK(status[0] == SampleStatus::ok);
  CHECK(close(eta[0], 119175000.0, 4 * eps));
  for (std::size_t i = 1; i <= 9; ++i) {
    CAPTURE(i);
    CHECK(status[i] == SampleStatus::invalid_input);
    CHECK(std::isnan(eta[i]));
  }
  CHECK(status[10] == SampleStatus::out_of_range);  // 5e-311 Pa s: subnormal
  CHECK(status[11] == SampleStatus::out_of_range);  // 5e309 Pa s: overflow
  CHECK(std::isnan(eta[10]));
  CHECK(std::isnan(eta[11]));
  CHECK(status[12] == SampleStatus::lambda_not_above_one);
  CHECK(std::isnan(eta[12]));
}

TEST_CASE("growth rate v = kappa (p - p0) d^2 / (4 eta h)") {
  // p = 0.3 MPa, p0 = 0.1 MPa, d = 6.56 um, eta = 119.175 MPa s, h = 145 nm, kappa = 1.
  // Exact value with exact decimal inputs (python3 fractions):
  //   (3e5 - 1e5) * (6.56e-6)^2 / (4 * 119175000 * 145e-9) = 1.2451581635236504e-07 m/s.
  // Rounding the five inputs (<= 0.5 eps each, d twice) and six operations: <= 6 eps; 8 allowed.
  const GrowthEvaluator growth({.p0 = 1e5, .kappa = 1.0});
  SampleBlock block = growth_block({3e5}, {6.56e-6}, {119175000.0}, {145e-9});
  growth.evaluate(block);
  CHECK(block.status()[0] == SampleStatus::ok);
  CHECK(close(block.column("v")[0], 1.2451581635236504e-07, 8 * eps));
}

TEST_CASE("growth rate scales exactly as d^2, 1/eta, 1/h and kappa") {
  // Scaling an input by a power of two scales every intermediate exactly, so v must scale
  // exactly (bit for bit), which checks each exponent of the law.
  const std::vector<double> p{3e5, 3e5, 3e5, 3e5};
  const std::vector<double> d{6e-6, 12e-6, 6e-6, 6e-6};
  const std::vector<double> eta{1e8, 1e8, 2e8, 1e8};
  const std::vector<double> h{2e-7, 2e-7, 2e-7, 8e-7};
  SampleBlock block = growth_block(p, d, eta, h);
  GrowthEvaluator({.p0 = 1e5, .kappa = 1.0}).evaluate(block);
  const auto v = block.column("v");
  CHECK(v[1] == 4.0 * v[0]);
  CHECK(v[2] == 0.5 * v[0]);
  CHECK(v[3] == 0.25 * v[0]);

  SampleBlock scaled = growth_block(p, d, eta, h);
  GrowthEvaluator({.p0 = 1e5, .kappa = 0.125}).evaluate(scaled);
  CHECK(scaled.column("v")[0] == 0.125 * v[0]);
}

TEST_CASE("no growth at or below the yield pressure: v = 0 and status no_growth") {
  const double p0 = 2e5;
  const double just_above = std::nextafter(p0, inf);
  SampleBlock block = growth_block({p0, 1e5, 0.0, just_above}, {6e-6, 6e-6, 6e-6, 6e-6},
                                   {1e8, 1e8, 1e8, 1e8}, {2e-7, 2e-7, 2e-7, 2e-7});
  GrowthEvaluator({.p0 = p0, .kappa = 1.0}).evaluate(block);
  const auto v = block.column("v");
  for (std::size_t i = 0; i < 3; ++i) {
    CAPTURE(i);
    CHECK(block.status()[i] == SampleStatus::no_growth);
    CHECK(v[i] == 0.0);
  }
  // One ulp above p0 (2.9e-11 Pa) still grows, at the exact rate of that overpressure.
  CHECK(block.status()[3] == SampleStatus::ok);
  CHECK(close(v[3], (just_above - p0) / 1e8 * (6e-6 / 2e-7) * 6e-6 / 4, 4 * eps));
}

TEST_CASE("growth rate flags invalid inputs and keeps upstream statuses") {
  SampleBlock block = growth_block({-1.0, not_a_number, 3e5, 3e5, 3e5, 3e5, 3e5, 3e5},
                                   {6e-6, 6e-6, 0.0, inf, 6e-6, 6e-6, 6e-6, 6e-6},
                                   {1e8, 1e8, 1e8, 1e8, -1e8, not_a_number, 1e8, 1e8},
                                   {2e-7, 2e-7, 2e-7, 2e-7, 2e-7, 2e-7, 0.0, 2e-7});
  block.flag(7, SampleStatus::beyond_membrane_limit);
  GrowthEvaluator({.p0 = 0.0, .kappa = 1.0}).evaluate(block);
  for (std::size_t i = 0; i < 7; ++i) {
    CAPTURE(i);
    CHECK(block.status()[i] == SampleStatus::invalid_input);
    CHECK(std::isnan(block.column("v")[i]));
  }
  CHECK(block.status()[7] == SampleStatus::beyond_membrane_limit);
  CHECK(std::isnan(block.column("v")[7]));
}

TEST_CASE("growth parameters are validated with the location and the value") {
  CHECK_THROWS_WITH_AS(validate(GrowthParameters{.p0 = -1e5, .kappa = 1.0}, "campaign.ini:7"),
                       "campaign.ini:7: p0 = '-0.1 MPa': expected a finite yield pressure >= 0 MPa",
                       InputError);
  CHECK_THROWS_WITH_AS(validate(GrowthParameters{.p0 = 0.0, .kappa = 0.0}, "campaign.ini:8"),
                       "campaign.ini:8: kappa = '0': expected a finite dimensionless factor > 0",
                       InputError);
  CHECK_THROWS_AS(GrowthEvaluator({.p0 = not_a_number, .kappa = 1.0}), InputError);
  CHECK_THROWS_AS(GrowthEvaluator({.p0 = 0.0, .kappa = inf}), InputError);
  CHECK_NOTHROW(validate(GrowthParameters{.p0 = 0.0, .kappa = 1.0}, "campaign.ini:9"));
}

TEST_CASE("median growth rate counts only growing samples") {
  const std::vector<double> v{5.0, 0.0, 1.0, 3.0, not_a_number, 2.0};
  const std::vector<SampleStatus> status{SampleStatus::ok, SampleStatus::no_growth, SampleStatus::ok,
                                         SampleStatus::ok, SampleStatus::burst, SampleStatus::ok};
  CHECK(median_growth_rate(v, status) == 2.5);  // {1, 2, 3, 5}
  const std::vector<SampleStatus> odd{SampleStatus::ok, SampleStatus::no_growth, SampleStatus::ok,
                                      SampleStatus::ok, SampleStatus::burst, SampleStatus::burst};
  CHECK(median_growth_rate(v, odd) == 3.0);  // {1, 3, 5}
  const std::vector<SampleStatus> none(v.size(), SampleStatus::no_growth);
  CHECK(std::isnan(median_growth_rate(v, none)));
}

TEST_CASE("calibrated kappa makes the reference line's predicted median its experimental one") {
  // A reference line of 101 tubes (deterministic spread), predicted with kappa = 1.
  const std::size_t n = 101;
  std::vector<double> p(n), d(n), eta(n), h(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) / static_cast<double>(n - 1);
    p[i] = 1e5 + 4e5 * s;
    d[i] = 5e-6 + 3e-6 * std::sin(7.0 * s);
    eta[i] = 2e7 + 2e8 * s * s;
    h[i] = 1e-7 + 2e-7 * std::cos(3.0 * s) * std::cos(3.0 * s);
  }
  const GrowthParameters unit{.p0 = 1.5e5, .kappa = 1.0};
  SampleBlock block = growth_block(p, d, eta, h);
  GrowthEvaluator(unit).evaluate(block);
  const double predicted = median_growth_rate(block.column("v"), block.status());
  const double experimental = 0.028e-6;  // wild type, distributions/README.md
  const double kappa = calibrate_kappa("wild_type", experimental, predicted);
  CHECK(kappa == experimental / predicted);

  SampleBlock calibrated = growth_block(p, d, eta, h);
  GrowthEvaluator({.p0 = unit.p0, .kappa = kappa}).evaluate(calibrated);
  // v is linear in kappa and the ordering of samples is unchanged, so the median scales: equal
  // up to the rounding of the product kappa * v (a few eps).
  CHECK(close(median_growth_rate(calibrated.column("v"), calibrated.status()), experimental, 4 * eps));
}

TEST_CASE("kappa calibration rejects medians that are not positive and finite") {
  CHECK_THROWS_WITH_AS(calibrate_kappa("wild_type", -0.5e-6, 1e-7),
                       "reference line 'wild_type': experimental median growth rate = '-0.5 um/s': "
                       "expected a positive finite growth rate",
                       InputError);
  CHECK_THROWS_WITH_AS(calibrate_kappa("wild_type", 0.028e-6, not_a_number),
                       "reference line 'wild_type': predicted median growth rate (kappa = 1) = 'nan': "
                       "expected a positive finite growth rate (nan: no sample of the line grows)",
                       InputError);
  CHECK_THROWS_AS(calibrate_kappa("pme48", 0.0, 1e-7), InputError);
  CHECK_THROWS_AS(calibrate_kappa("pme48", 1e-7, inf), InputError);
  CHECK_THROWS_AS(calibrate_kappa("pme48", 1e300, 1e-300), InputError);
}
