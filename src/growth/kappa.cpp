#include "growthuq/growth/kappa.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "finite_checks.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/stats/quantity_summary.hpp"

namespace growthuq {
namespace {

// Messages give rates in um/s, the unit of the distribution files.
std::string in_um_per_s(double rate) {
  return std::isfinite(rate) ? format_double(rate * 1e6) + " um/s" : format_double(rate);
}

}  // namespace

double median_growth_rate(std::span<const double> v, std::span<const SampleStatus> status) {
  std::vector<double> growing;
  for (std::size_t i = 0; i < v.size() && i < status.size(); ++i) {
    if (status[i] == SampleStatus::ok) growing.push_back(v[i]);
  }
  if (growing.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t middle = growing.size() / 2;
  std::nth_element(growing.begin(), growing.begin() + static_cast<std::ptrdiff_t>(middle), growing.end());
  const double upper = growing[middle];
  if (growing.size() % 2 == 1) return upper;
  const double lower = *std::max_element(growing.begin(), growing.begin() + static_cast<std::ptrdiff_t>(middle));
  return lower + 0.5 * (upper - lower);
}

double calibrate_kappa(std::string_view reference_line, double experimental_median,
                       double predicted_median_at_unit_kappa) {
  const std::string location = "reference line '" + std::string(reference_line) + "'";
  if (!growth_detail::positive_finite(experimental_median)) {
    throw_bad_value(location, "experimental median growth rate", in_um_per_s(experimental_median),
                    "a positive finite growth rate");
  }
  if (!growth_detail::positive_finite(predicted_median_at_unit_kappa)) {
    throw_bad_value(location, "predicted median growth rate (kappa = 1)",
                    in_um_per_s(predicted_median_at_unit_kappa),
                    "a positive finite growth rate (nan: no sample of the line grows)");
  }
  const double kappa = experimental_median / predicted_median_at_unit_kappa;
  if (!growth_detail::positive_normal(kappa)) {
    throw_bad_value(location, "kappa", format_double(kappa),
                    "a ratio of experimental to predicted median within double range; the two "
                    "medians differ by more than 300 orders of magnitude (units?)");
  }
  return kappa;
}

void apply_kappa(std::span<double> v, std::span<SampleStatus> status, double kappa) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (status[i] != SampleStatus::ok) continue;
    v[i] *= kappa;
    if (!std::isnormal(v[i])) {
      v[i] = std::numeric_limits<double>::quiet_NaN();
      status[i] = SampleStatus::out_of_range;
    }
  }
}

void KappaCalibration::calibrate(std::span<const double> v, double v_to_si, std::span<const SampleStatus> status) {
  std::vector<double> v_si(v.begin(), v.end());
  for (double& value : v_si) value *= v_to_si;
  const double predicted = median_growth_rate(v_si, status);
  kappa_ = calibrate_kappa(reference_line_, experimental_median_, predicted);
  calibrated_ = true;
  // kappa's Monte Carlo error: the order-statistic 95 % CI of the growing samples' median.
  std::vector<double> growing;
  for (std::size_t i = 0; i < v_si.size() && i < status.size(); ++i) {
    if (status[i] == SampleStatus::ok) growing.push_back(v_si[i]);
  }
  const MedianConfidenceRanks ranks = median_confidence_ranks(growing.size());
  if (!ranks.reached) return;
  std::sort(growing.begin(), growing.end());
  const double predicted_low = growing[ranks.lower - 1], predicted_high = growing[ranks.upper - 1];
  if (!(predicted_low > 0.0)) return;  // a growing sample's rate is positive; no interval otherwise
  kappa_ci_low_ = experimental_median_ / predicted_high;
  kappa_ci_high_ = experimental_median_ / predicted_low;
}

void KappaCalibration::widen_median_interval(double median, double& low, double& high) const {
  if (!calibrated_) return;
  if (!std::isfinite(kappa_ci_low_) || !std::isfinite(kappa_ci_high_)) {
    low = high = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  const double below = std::log(kappa_ / kappa_ci_low_);   // ln(P_hi / P)
  const double above = std::log(kappa_ci_high_ / kappa_);  // ln(P / P_lo)
  if (!(median > 0.0)) {
    if (high > 0.0) high *= std::exp(above);
    return;
  }
  if (low > 0.0) low = median * std::exp(-std::hypot(std::log(median / low), below));
  if (high > 0.0) high = median * std::exp(std::hypot(std::log(high / median), above));
}

}  // namespace growthuq
