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

TEST_CASE("apply_kappa scales growing samples only and flags a product beyond double range") {
  std::vector<double> v{2e-8, 0.0, not_a_number, 1e-300, 3e-8};
  std::vector<SampleStatus> status{SampleStatus::ok, SampleStatus::no_growth, SampleStatus::burst, SampleStatus::ok,
                                   SampleStatus::ok};
  apply_kappa(v, status, 1e-20);
  CHECK(v[0] == 2e-8 * 1e-20);  // one rounding, as evaluating with kappa would give
  CHECK(v[1] == 0.0);           // a tube that does not grow stays at 0 whatever kappa is
  CHECK(std::isnan(v[2]));
  CHECK(std::isnan(v[3]));      // 1e-320 is subnormal: out of the normal range
  CHECK(status[3] == SampleStatus::out_of_range);
  CHECK(v[4] == 3e-8 * 1e-20);
  CHECK(status[0] == SampleStatus::ok);
  CHECK(status[1] == SampleStatus::no_growth);
  CHECK(status[2] == SampleStatus::burst);
}

TEST_CASE("a kappa calibration takes rates in a display unit, calibrates on them, and scales every line") {
  // Rates in um/s (to_si = 1e-6), as the campaign holds them; median of the growing {2, 3, 5}
  // is 3 um/s, the experimental median 0.06 um/s, so kappa = 0.02 (up to the unit's rounding).
  KappaCalibration calibration("wild_type", 0.06e-6);
  CHECK(calibration.is_reference("wild_type"));
  CHECK_FALSE(calibration.is_reference("pme48"));
  CHECK(calibration.kappa() == 1.0);
  CHECK_FALSE(calibration.calibrated());
  std::vector<double> v{5.0, 0.0, 2.0, 3.0};
  std::vector<SampleStatus> status{SampleStatus::ok, SampleStatus::no_growth, SampleStatus::ok, SampleStatus::ok};
  calibration.calibrate(v, 1e-6, status);
  CHECK(calibration.calibrated());
  CHECK(calibration.kappa() == calibrate_kappa("wild_type", 0.06e-6, 3.0 * 1e-6));
  CHECK(close(calibration.kappa(), 0.02, 4 * eps));  // three roundings: 0.06e-6, 3 * 1e-6, the ratio
  calibration.apply(v, status);
  CHECK(v[3] == 3.0 * calibration.kappa());
  CHECK(v[1] == 0.0);
  // No growing sample on the reference line: the calibration's InputError names it.
  KappaCalibration none("pme48", 0.06e-6);
  const std::vector<SampleStatus> flagged(v.size(), SampleStatus::no_growth);
  CHECK_THROWS_WITH_AS(none.calibrate(v, 1e-6, flagged),
                       "reference line 'pme48': predicted median growth rate (kappa = 1) = 'nan': "
                       "expected a positive finite growth rate (nan: no sample of the line grows)",
                       InputError);
}

TEST_CASE("kappa's Monte Carlo error widens another line's interval of v as the delta method on ln(kappa Q) says") {
  // Reference rates 1..11 um/s (shuffled, one non-growing sample left out): P = 6. The 95 %
  // order-statistic CI of a median of 11 is [X(2), X(10)] = [2, 10]: P(B <= 1) = 12/2048 keeps
  // 98.8 %, P(B <= 2) = 67/2048 would keep 93.5 % (B ~ binomial(11, 1/2)). E = 3 um/s, so kappa =
  // 0.5 and its interval [E / 10, E / 2] = [0.3, 1.5].
  KappaCalibration calibration("wild_type", 3e-6);
  std::vector<double> v{7, 2, 11, 0, 5, 1, 9, 3, 10, 4, 8, 6};
  std::vector<SampleStatus> status(v.size(), SampleStatus::ok);
  status[3] = SampleStatus::no_growth;
  double low = 2.0, high = 10.0;
  calibration.widen_median_interval(4.0, low, high);  // before calibration: nothing
  CHECK(low == 2.0);
  CHECK(high == 10.0);
  calibration.calibrate(v, 1e-6, status);
  CHECK(calibration.kappa() == doctest::Approx(0.5).epsilon(1e-14));
  CHECK(calibration.kappa_ci_low() == doctest::Approx(0.3).epsilon(1e-14));
  CHECK(calibration.kappa_ci_high() == doctest::Approx(1.5).epsilon(1e-14));
  // A line with median 4 and Monte Carlo CI [2, 10]: by hand, 4 exp(-sqrt(ln(4/2)^2 + ln(10/6)^2))
  // = 1.690883 and 4 exp(sqrt(ln(10/4)^2 + ln(6/2)^2)) = 16.724369.
  calibration.widen_median_interval(4.0, low, high);
  CHECK(low == doctest::Approx(1.690883047656252).epsilon(1e-12));
  CHECK(high == doctest::Approx(16.724368660601623).epsilon(1e-12));
  // An end at 0 (a line whose lower samples do not grow) stays; with a median of 0 only the
  // upper end widens, by P / P_lo = 3.
  double zero_low = 0.0, zero_high = 2.0;
  calibration.widen_median_interval(0.0, zero_low, zero_high);
  CHECK(zero_low == 0.0);
  CHECK(zero_high == doctest::Approx(6.0).epsilon(1e-14));
  // Five growing reference samples reach no 95 % interval: kappa's error is unknown, and so is the line's.
  KappaCalibration few("wild_type", 3e-6);
  few.calibrate(std::vector<double>{1, 2, 3, 4, 5}, 1e-6, std::vector<SampleStatus>(5, SampleStatus::ok));
  double few_low = 2.0, few_high = 10.0;
  few.widen_median_interval(4.0, few_low, few_high);
  CHECK(std::isnan(few_low));
  CHECK(std::isnan(few_high));
}

TEST_CASE("the growth evaluator declares v valued under no_growth, and nothing else") {
  const GrowthEvaluator growth({.p0 = 1e5, .kappa = 1.0});
  CHECK(growth.valued_statuses("v") == StatusSet{SampleStatus::no_growth});
  CHECK(growth.valued_statuses("p").empty());
  CHECK(KappaCalibration::quantity == growth.writes().front());
}
