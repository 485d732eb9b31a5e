// Calibration of the growth law's geometric factor kappa on one reference line (Eq. (G5),
// src/growth/README.md):
//   kappa = (experimental median growth rate) / (predicted median with kappa = 1).
// Every line of the campaign then uses this one kappa, so the other lines' rates are
// predictions, not fits.
#pragma once

#include <span>
#include <string_view>

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

}  // namespace growthuq
