// Processing of force-indentation curves against independent references: closed-form curves
// (noiseless recovery to rounding), the Savitzky-Golay weights' textbook values and exactness on
// a quadratic, coverage of the stated uncertainty over many seeds, and one curve per status.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "growthuq/forcecurves/curve_processing.hpp"
#include "growthuq/forcecurves/tube_stiffness.hpp"
#include "growthuq/synthetic/indentation_curve.hpp"

using namespace growthuq;

namespace {

// The measured slope of a tube of stiffness k behind a sensor of k_sys (the series of Eq. (M8)).
double in_series(double k, double k_sys) { return std::isinf(k_sys) ? k : k * k_sys / (k + k_sys); }

double sample_spacing(const IndentationTruth& truth) {
  return (truth.end - truth.start) / static_cast<double>(truth.approach_samples - 1);
}

}  // namespace

TEST_CASE("Savitzky-Golay: the textbook weights, and a quadratic passes unchanged") {
  // A unit impulse returns the weights: (-3, 12, 17, 12, -3) / 35 for 5 samples (Savitzky and
  // Golay 1964, Table I).
  std::vector<double> impulse(11, 0.0), out(11);
  impulse[5] = 1.0;
  savitzky_golay_quadratic(impulse.data(), out.data(), impulse.size(), 5);
  CHECK(out[5] == doctest::Approx(17.0 / 35.0).epsilon(1e-15));
  CHECK(out[4] == doctest::Approx(12.0 / 35.0).epsilon(1e-15));
  CHECK(out[3] == doctest::Approx(-3.0 / 35.0).epsilon(1e-15));
  CHECK(out[2] == 0.0);
  std::vector<double> quadratic(40), smoothed(40);
  for (std::size_t i = 0; i < quadratic.size(); ++i) {
    const double x = static_cast<double>(i);
    quadratic[i] = 0.5 - 0.25 * x + 0.03 * x * x;
  }
  for (const int window : {5, 7, 11, 21}) {
    savitzky_golay_quadratic(quadratic.data(), smoothed.data(), quadratic.size(), window);
    for (std::size_t i = 0; i < quadratic.size(); ++i) CHECK(smoothed[i] == doctest::Approx(quadratic[i]).epsilon(1e-12));
  }
}

TEST_CASE("a noiseless curve gives the tube's k to rounding, the contact within two samples") {
  for (const double k_sys : {std::numeric_limits<double>::infinity(), 100.0, 10.0}) {
    for (const ContactMethod method : {ContactMethod::deviation, ContactMethod::piecewise}) {
      IndentationTruth truth;
      truth.noise = 0.0;
      truth.sensor_stiffness = k_sys;
      const ForceCurve curve = simulate_indentation_curve(truth, 1, "c", "t", 1);
      CurveProcessingOptions options;
      options.contact = method;
      const CurveResult result = process_force_curve(curve, options);
      REQUIRE(result.status == CurveStatus::ok);
      CHECK(result.measured_stiffness == doctest::Approx(in_series(truth.stiffness, k_sys)).epsilon(1e-9));
      CHECK(result.stiffness == doctest::Approx(truth.stiffness).epsilon(1e-9));
      CHECK(std::abs(result.contact_position_m - truth.contact) <= 2.0 * sample_spacing(truth));
      CHECK(result.baseline_tilt_N_per_m == doctest::Approx(truth.drift / truth.speed).epsilon(1e-9));
      // The relative window: F_max - 4 uN to F_max - 0.5 uN, F_max = k_m (end - z_c).
      const double force_max = in_series(truth.stiffness, k_sys) * (truth.end - truth.contact);
      CHECK(result.force_max_N == doctest::Approx(force_max).epsilon(1e-9));
      CHECK(result.window_low_N == doctest::Approx(force_max - 4e-6).epsilon(1e-9));
      CHECK(result.window_high_N == doctest::Approx(force_max - 0.5e-6).epsilon(1e-9));
    }
  }
}

TEST_CASE("an offset-only baseline (the group's script) leaves the drift in the slope: k_m + drift / speed") {
  IndentationTruth truth;
  truth.drift = 0.0;
  truth.noise = 0.0;
  CurveProcessingOptions options;
  options.baseline_tilt = false;
  options.window = {WindowConvention::absolute, 0.4e-6, 4e-6};
  const CurveResult without_drift = process_force_curve(simulate_indentation_curve(truth, 1, "c", "t", 1), options);
  REQUIRE(without_drift.status == CurveStatus::ok);
  CHECK(without_drift.stiffness == doctest::Approx(truth.stiffness).epsilon(1e-9));
  // With the default drift (0.01 N/m of tilt, about 9 standard errors of the slope) and noise,
  // the slope is the tube's plus the tilt; the tilted baseline removes it.
  truth = IndentationTruth{};
  const ForceCurve curve = simulate_indentation_curve(truth, 1, "c", "t", 1);
  const CurveResult offset_only = process_force_curve(curve, options);
  REQUIRE(offset_only.status == CurveStatus::ok);
  const double tilt = truth.drift / truth.speed;
  CHECK(std::abs(offset_only.measured_stiffness - (truth.stiffness + tilt)) <= 4.0 * offset_only.se_fit);
  CHECK(std::abs(offset_only.measured_stiffness - truth.stiffness) > 4.0 * offset_only.se_fit);
  options.baseline_tilt = true;
  const CurveResult tilted = process_force_curve(curve, options);
  CHECK(std::abs(tilted.stiffness - truth.stiffness) <= 4.0 * tilted.uncertainty_statistical);
}

// Coverage over seeds: with Gaussian noise the slope's and the
// baseline tilt's standard errors are exact for least squares, so k_true lies within
// +-1.96 u_statistical in 95 % of curves; 1000 curves give a binomial sd of 0.7 %, and the
// accepted band [0.93, 0.97] is about 3 sd wide each way. The total uncertainty adds the
// contact and window sensitivities and must cover at least as often. The contact lies within
// threshold_sigma noise sd of force (converted to position by k_m) plus two samples of the truth.
TEST_CASE("coverage of k's stated uncertainty and the contact's tolerance over 1000 seeds") {
  for (const WindowConvention convention : {WindowConvention::relative, WindowConvention::absolute}) {
    for (const ContactMethod method : {ContactMethod::deviation, ContactMethod::piecewise}) {
      IndentationTruth truth;
      truth.sensor_stiffness = 100.0;
      CurveProcessingOptions options;
      options.contact = method;
      if (convention == WindowConvention::absolute) options.window = {convention, 0.4e-6, 4e-6};
      const double k_m = in_series(truth.stiffness, truth.sensor_stiffness);
      const double contact_tolerance = options.threshold_sigma * truth.noise / k_m + 2.0 * sample_spacing(truth);
      std::size_t covered = 0, covered_total = 0, contact_within = 0;
      const std::size_t seeds = 1000;
      for (std::size_t seed = 1; seed <= seeds; ++seed) {
        const CurveResult result = process_force_curve(simulate_indentation_curve(truth, seed, "c", "t", 1), options);
        REQUIRE(result.status == CurveStatus::ok);
        const double error = std::abs(result.stiffness - truth.stiffness);
        covered += error <= 1.96 * result.uncertainty_statistical ? 1 : 0;
        covered_total += error <= 1.96 * result.uncertainty ? 1 : 0;
        contact_within += std::abs(result.contact_position_m - truth.contact) <= contact_tolerance ? 1 : 0;
      }
      const double rate = static_cast<double>(covered) / seeds;
      MESSAGE("window " << (convention == WindowConvention::relative ? "relative" : "absolute") << ", contact "
                        << (method == ContactMethod::deviation ? "deviation" : "piecewise") << ": coverage of +-1.96 u_stat "
                        << rate << ", of +-1.96 u " << static_cast<double>(covered_total) / seeds << ", contact within "
                        << contact_tolerance * 1e9 << " nm " << contact_within << "/" << seeds);
      CHECK(rate >= 0.93);
      CHECK(rate <= 0.97);
      CHECK(covered_total >= covered);
      CHECK(static_cast<double>(covered_total) / seeds >= 0.95);
      CHECK(contact_within == seeds);
    }
  }
}

// A tube's mean over 5 repetitions lies within +-1.96 of its uncertainty (the larger of the
// spread's and the curves' own) at least 95 % of the time over 400 tubes.
TEST_CASE("per tube: the mean of repeated curves and its uncertainty cover the truth") {
  IndentationTruth truth;
  truth.sensor_stiffness = 100.0;
  std::size_t covered = 0;
  const std::size_t tubes = 400;
  for (std::size_t t = 0; t < tubes; ++t) {
    std::vector<CurveResult> results;
    for (int repetition = 1; repetition <= 5; ++repetition) {
      results.push_back(process_force_curve(
          simulate_indentation_curve(truth, 100000 + 10 * t + static_cast<std::size_t>(repetition), "c", "tube", repetition),
          CurveProcessingOptions{}));
    }
    const std::vector<TubeStiffness> tube = tube_stiffness(results);
    REQUIRE(tube.size() == 1);
    REQUIRE(tube[0].ok == 5);
    covered += std::abs(tube[0].stiffness - truth.stiffness) <= 1.96 * tube[0].uncertainty ? 1 : 0;
  }
  MESSAGE("tubes: coverage of +-1.96 u_tube " << static_cast<double>(covered) / tubes);
  CHECK(static_cast<double>(covered) / tubes >= 0.95);
}

TEST_CASE("per tube: mean, spread and status counts against a hand computation") {
  std::vector<CurveResult> curves(4);
  const double k[] = {2.0, 3.0, 4.0, 9.0};
  for (std::size_t i = 0; i < 4; ++i) {
    curves[i].tube = "a";
    curves[i].stiffness = k[i];
    curves[i].uncertainty = 0.1;
  }
  curves[3].status = CurveStatus::slip;
  const auto tubes = tube_stiffness(curves);
  REQUIRE(tubes.size() == 1);
  CHECK(tubes[0].curves == 4);
  CHECK(tubes[0].ok == 3);
  CHECK(tubes[0].statuses == "ok 3, slip 1");
  CHECK(tubes[0].stiffness == doctest::Approx(3.0).epsilon(1e-15));
  CHECK(tubes[0].spread == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(tubes[0].uncertainty_spread == doctest::Approx(1.0 / std::sqrt(3.0)).epsilon(1e-15));
  CHECK(tubes[0].uncertainty_measurement == doctest::Approx(std::sqrt(0.03) / 3.0).epsilon(1e-15));
  CHECK(tubes[0].uncertainty == tubes[0].uncertainty_spread);
}

TEST_CASE("each failure gets its status") {
  IndentationTruth truth;
  truth.sensor_stiffness = 100.0;
  const CurveProcessingOptions defaults;
  const ForceCurve good = simulate_indentation_curve(truth, 7, "c", "t", 1);
  REQUIRE(process_force_curve(good, defaults).status == CurveStatus::ok);
  const std::size_t contact = static_cast<std::size_t>(std::round((truth.contact - truth.start) / sample_spacing(truth)));

  // The good curve under options it cannot satisfy.
  const auto rated_with = [&](auto change) {
    CurveProcessingOptions options;
    change(options);
    return process_force_curve(good, options).status;
  };
  SUBCASE("options the curve cannot satisfy: a window above its maximum, an exacting R^2, a baseline past contact") {
    CHECK(rated_with([](auto& o) { o.window = {WindowConvention::absolute, 0.4e-6, 20e-6}; }) == CurveStatus::window_not_reached);
    CHECK(rated_with([](auto& o) { o.minimum_r_squared = 0.9999999; }) == CurveStatus::poor_linearity);
    CHECK(rated_with([](auto& o) { o.baseline_fraction = 0.5; }) == CurveStatus::no_baseline);
  }
  SUBCASE("no contact: the probe turns back before touching") {
    IndentationTruth short_of = truth;
    short_of.contact = truth.end - 2.0 * sample_spacing(truth);
    CHECK(process_force_curve(simulate_indentation_curve(short_of, 7, "c", "t", 1), defaults).status == CurveStatus::no_contact);
  }
  SUBCASE("saturated: the reading clipped") {
    ForceCurve clipped = good;
    for (double& f : clipped.force) f = std::min(f, 5e-6);
    CHECK(process_force_curve(clipped, defaults).status == CurveStatus::saturated);
  }
  SUBCASE("slip: a sudden drop in contact") {
    ForceCurve slipped = good;
    for (std::size_t i = contact + 600; i < slipped.approach_end; ++i) slipped.force[i] -= 1e-6;
    CHECK(process_force_curve(slipped, defaults).status == CurveStatus::slip);
  }
  SUBCASE("snap-in: an attractive jump before contact") {
    ForceCurve snapped = good;
    for (std::size_t i = contact - 5; i < contact; ++i) snapped.force[i] -= 0.5e-6;
    CHECK(process_force_curve(snapped, defaults).status == CurveStatus::snap_in);
  }
  SUBCASE("non-monotonic: the force sinks gradually in the window") {
    ForceCurve sinking = good;
    const std::size_t from = sinking.approach_end - 300;
    for (std::size_t i = from; i < sinking.approach_end; ++i) {
      sinking.force[i] -= std::min(0.5e-6, 0.01e-6 * static_cast<double>(i - from));
    }
    CHECK(process_force_curve(sinking, defaults).status == CurveStatus::non_monotonic);
  }
  SUBCASE("sensor limited: the slope above the sheet's k_sys") {
    ForceCurve stiff_tube = good;
    stiff_tube.sensor_stiffness_N_per_m = 1.0;
    CHECK(process_force_curve(stiff_tube, defaults).status == CurveStatus::sensor_limited);
  }
}

TEST_CASE("smoothing keeps a linear curve's slope within the unsmoothed fit's uncertainty") {
  IndentationTruth truth;
  CurveProcessingOptions smooth;
  smooth.smoothing_window = 11;
  const ForceCurve curve = simulate_indentation_curve(truth, 3, "c", "t", 1);
  const CurveResult plain = process_force_curve(curve, CurveProcessingOptions{});
  const CurveResult smoothed = process_force_curve(curve, smooth);
  REQUIRE(smoothed.status == CurveStatus::ok);
  CHECK(std::abs(smoothed.stiffness - truth.stiffness) <= 4.0 * plain.uncertainty_statistical);
}

TEST_CASE("options are checked with a message naming the flag") {
  CurveProcessingOptions options;
  CHECK(options.invalid_reason().empty());
  options.smoothing_window = 4;
  CHECK(options.invalid_reason().find("--smooth") != std::string::npos);
  options = {};
  options.window = {WindowConvention::relative, 0.5e-6, 4e-6};
  CHECK(options.invalid_reason().find("a > b") != std::string::npos);
}
