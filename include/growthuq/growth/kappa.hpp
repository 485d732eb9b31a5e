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

  // apply_kappa with the calibrated kappa (1 before calibrate()).
  void apply(std::span<double> v, std::span<SampleStatus> status) const { apply_kappa(v, status, kappa_); }

  double kappa() const noexcept { return kappa_; }
  bool calibrated() const noexcept { return calibrated_; }

 private:
  std::string reference_line_;
  double experimental_median_ = std::numeric_limits<double>::quiet_NaN();
  double kappa_ = 1.0;
  bool calibrated_ = false;
};

}  // namespace growthuq
