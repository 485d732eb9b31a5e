// Calibration of the growth law's geometric factor kappa on one reference line (Eq. (G5),
// src/growth/README.md):
//   kappa = (experimental median growth rate) / (predicted median with kappa = 1).
// Every line of the campaign then uses this one kappa, so the other lines' rates are
// predictions, not fits.
#pragma once

#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "growthuq/evaluation/sample_status.hpp"

namespace growthuq {

// Median of the predicted rates `v` over the samples with status ok (growing tubes). The
// experimental rates come from kymographs of growing tubes, so non-growing (no_growth) and
// failed samples are left out. NaN when no sample is ok. v and status have the same size.
double median_growth_rate(std::span<const double> v, std::span<const SampleStatus> status);

// kappa = experimental_median / predicted_median, both in m/s, predicted with kappa = 1.
// v is linear in kappa, so the reference line's predicted median with this kappa equals its
// experimental median. InputError "<reference_line>: <which> median growth rate = '<value>
// um/s': expected a positive finite growth rate" when either median is not positive and
// finite (e.g. every reference sample was flagged), or when the ratio is not a normal double.
double calibrate_kappa(std::string_view reference_line, double experimental_median,
                       double predicted_median_at_unit_kappa);

// v *= kappa on the growing samples (status ok). v is linear in kappa (growth_rate.hpp), so this
// equals evaluating with kappa; a product that leaves the normal range becomes NaN with status
// out_of_range, as the growth evaluator would flag it. v and status have the same size.
void apply_kappa(std::span<double> v, std::span<SampleStatus> status, double kappa);

// One run's calibration: growth is evaluated with kappa = 1 on every line, the reference line
// (evaluated first) sets kappa, and every line's v, the reference's included, is scaled by it.
// The campaign run and each replicate of the data-uncertainty bootstrap hold one each.
class KappaCalibration {
 public:
  // The quantity it scales: the growth rate the growth evaluator writes (growth_rate.hpp).
  static constexpr std::string_view quantity = "v";

  // `experimental_median` [m/s]: the median of the reference line's v_exp law.
  KappaCalibration(std::string reference_line, double experimental_median)
      : reference_line_(std::move(reference_line)), experimental_median_(experimental_median) {}

  bool is_reference(std::string_view line) const noexcept { return line == reference_line_; }

  // On the reference line: kappa from its rates `v` at kappa = 1, given in a unit of `v_to_si`
  // m/s per unit (the values are converted to m/s first). InputError as calibrate_kappa.
  void calibrate(std::span<const double> v, double v_to_si, std::span<const SampleStatus> status);

  // A non-reference line's Monte Carlo 95 % CI [low, high] of its median v (kappa applied),
  // widened by kappa's own Monte Carlo error (Eq. (G5b), src/growth/README.md). kappa = E / P
  // divides the experimental median E by P, the median of the reference line's samples, which
  // holds Monte Carlo error: with [P_lo, P_hi] the distribution-free 95 % CI of P (order
  // statistics, quantity_summary.hpp), ln kappa lies within ln(P_hi / P) below and ln(P / P_lo)
  // above. The line's median m = kappa Q, Q its own median at kappa = 1, sampled independently of
  // P, so on the log scale the two half-widths add in quadrature (delta method on the product):
  //   low' = m exp(-sqrt(ln(m / low)^2 + ln(P_hi / P)^2)),  high' = m exp(sqrt(ln(high / m)^2 + ln(P / P_lo)^2)).
  // An end at 0 (tubes that do not grow) stays; with m = 0 only high widens, high' = high P / P_lo.
  // NaN ends stay NaN, and both become NaN when kappa's interval is undefined (5 or fewer
  // growing reference samples). Nothing before calibrate().
  void widen_median_interval(double median, double& low, double& high) const;

  // kappa's Monte Carlo 95 % CI (from [P_lo, P_hi] above); NaN before calibrate() or when undefined.
  double kappa_ci_low() const noexcept { return kappa_ci_low_; }
  double kappa_ci_high() const noexcept { return kappa_ci_high_; }

  // apply_kappa with the calibrated kappa (1 before calibrate()).
  void apply(std::span<double> v, std::span<SampleStatus> status) const { apply_kappa(v, status, kappa_); }

  double kappa() const noexcept { return kappa_; }
  bool calibrated() const noexcept { return calibrated_; }

 private:
  std::string reference_line_;
  double experimental_median_ = std::numeric_limits<double>::quiet_NaN();
  double kappa_ = 1.0;
  double kappa_ci_low_ = std::numeric_limits<double>::quiet_NaN();
  double kappa_ci_high_ = std::numeric_limits<double>::quiet_NaN();
  bool calibrated_ = false;
};

}  // namespace growthuq
