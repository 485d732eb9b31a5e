// The corrected closed form: evaluation (closed form, far field, two polynomials) and the
// least-squares fit that makes it. src/correction/README.md states the model.
#include "growthuq/correction/corrected_closed_form.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include <Eigen/Dense>

#include "fe/far_field.hpp"
#include "fe/shell_fe_problem.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "correction_training.hpp"

namespace growthuq {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The basis at z: 1, z_i, z_i z_j (i <= j), then z_0 z_i z_j (i <= j): a full quadratic plus
// the cubic terms in the hoop strain, the group along which the correction bends most (towards
// the law's pressure maximum; src/correction/README.md).
std::array<double, correction_terms> basis(const std::array<double, correction_groups>& z) {
  std::array<double, correction_terms> phi{};
  std::size_t t = 0;
  phi[t++] = 1.0;
  for (std::size_t i = 0; i < correction_groups; ++i) phi[t++] = z[i];
  for (const double factor : {1.0, z[0]}) {
    for (std::size_t i = 0; i < correction_groups; ++i) {
      for (std::size_t j = i; j < correction_groups; ++j) phi[t++] = factor * z[i] * z[j];
    }
  }
  return phi;
}

double polynomial(const std::array<double, correction_terms>& coefficients, const std::array<double, correction_terms>& phi) {
  double sum = 0.0;
  for (std::size_t t = 0; t < correction_terms; ++t) sum += coefficients[t] * phi[t];
  return sum;
}

// ln(groups) scaled onto [-1, 1] over the training box; false when outside it.
bool scaled(const std::array<double, correction_groups>& log_groups, const Correction& correction,
            std::array<double, correction_groups>& z) {
  for (std::size_t i = 0; i < correction_groups; ++i) {
    const double low = correction.low[i], high = correction.high[i];
    if (!(log_groups[i] >= low && log_groups[i] <= high)) return false;
    z[i] = (2.0 * log_groups[i] - low - high) / (high - low);
  }
  return true;
}

// A window's bottom over its top from its logarithm, to three digits (exp(ln 0.05) prints as
// 0.05000000000000001 in full).
std::string ratio_text(double log_ratio) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", std::exp(log_ratio));
  return text;
}

}  // namespace

std::array<double, correction_groups> correction_log_groups(double k_tube, const TubeDiameters& diameters, double h,
                                                            double probe_radius, const std::array<double, 2>& force_window,
                                                            const Correction& correction) {
  return {std::log(diameters.strain),
          std::log(h / diameters.d0),
          std::log(probe_radius / diameters.d0),
          std::log(force_window[1] / (k_tube * diameters.d0)),
          std::log(correction.probe_distance / diameters.d0),
          std::log(force_window[0] / force_window[1])};
}

void require_fitted_for(const Correction& correction, const ShellFeOptions& options, const Instrument& instrument,
                        std::string_view location, OptionNames names) {
  // Each option by its campaign key and by the command-line flag that sets it.
  const auto refuse = [&](std::string_view key, std::string_view flag, const std::string& value, const std::string& fitted) {
    throw_bad_value(location, names == OptionNames::command_flags ? flag : key, value,
                    fitted + ", the value fidelity corrected was fitted for (src/correction/README.md; "
                             "another value needs fidelity shell_fe, or a correction refitted with growthuq fit-correction)");
  };
  const auto on_off = [](bool on) { return std::string(on ? "on" : "off"); };
  if (options.geometry != ShellFeGeometry::tube) refuse("geometry", "--geometry", std::string(to_string(options.geometry)), "tube");
  if (options.law != correction.law) {
    refuse("law", "--law", std::string(to_string(options.law)), std::string(to_string(correction.law)));
  }
  if (options.substrate != correction.substrate) refuse("substrate", "--substrate", on_off(options.substrate), on_off(correction.substrate));
  if (options.bending != correction.bending) refuse("bending", "--bending", on_off(options.bending), on_off(correction.bending));
  if (std::abs(options.tube_length - correction.tube_length) > 1e-9 * correction.tube_length) {
    refuse("tube_length_um", "--tube-length-um", format_micro(options.tube_length), format_micro(correction.tube_length));
  }
  if (std::abs(options.probe_distance - correction.probe_distance) > 1e-9 * correction.tube_length) {
    refuse("probe_distance_um", "--probe-distance-um", format_micro(options.probe_distance), format_micro(correction.probe_distance));
  }
  // The window's bottom over its top is one of the groups, the same for every sample: a window
  // outside the fitted ones is the campaign's, not a sample's.
  constexpr std::size_t window_ratio = correction_groups - 1;
  const double ratio = std::log(options.force_window[0] / options.force_window[1]);
  if (!(ratio >= correction.low[window_ratio] - 1e-12 && ratio <= correction.high[window_ratio] + 1e-12)) {
    throw_bad_value(location, names == OptionNames::command_flags ? "--window-uN" : "force_window_uN",
                    format_micro(options.force_window[0]) + "," + format_micro(options.force_window[1]),
                    "a force window whose bottom is " + ratio_text(correction.low[window_ratio]) + " to " +
                        ratio_text(correction.high[window_ratio]) +
                        " of its top, the windows fidelity corrected was fitted over (src/correction/README.md; "
                        "another needs fidelity shell_fe)");
  }
  if (std::abs(instrument.poisson_ratio - correction.poisson_ratio) > 1e-12) {
    refuse("poisson_ratio", "--nu", format_double(instrument.poisson_ratio), format_double(correction.poisson_ratio));
  }
}

CorrectedInverse corrected_inverse(double k_measured, const TubeDiameters& diameters, double h,
                                   const Instrument& instrument, const std::array<double, 2>& force_window,
                                   const Correction& correction) noexcept {
  CorrectedInverse result;
  const TurgorResult turgor = invert_turgor(k_measured, diameters, instrument);
  const ModulusResult modulus =
      turgor.status == SampleStatus::ok ? invert_modulus(turgor.p, diameters, h) : ModulusResult{nan, nan, nan, turgor.status};
  if (modulus.status != SampleStatus::ok) {
    result.status = modulus.status;
    result.p = result.E = nan;
    return result;
  }
  result.closed_form_p = turgor.p;
  result.closed_form_E = modulus.E;
  // A tube the wall law cannot inflate to d (past its burst) has no finite-element answer at all:
  // that, not the fitted range, is what it is told.
  const fe::FarFieldInverse far = fe::far_field_inverse(fe::far_field_law(correction.law), diameters.lambda,
                                                        h / diameters.d0, instrument.poisson_ratio);
  if (far.status != fe::FarFieldInverseStatus::ok) {
    result.status = SampleStatus::no_inflation_state;
    result.p = result.E = nan;
    return result;
  }
  const double k_tube = tube_stiffness(k_measured, instrument);
  std::array<double, correction_groups> z{};
  const double bending_length = std::sqrt(h * diameters.d0 / 2);
  if (k_tube > correction.max_stiffness ||  // stiffer than any fitted tube
      instrument.probe_radius_m / bending_length > correction.max_probe_over_bending_length ||  // as the fit divides
      !scaled(correction_log_groups(k_tube, diameters, h, instrument.probe_radius_m, force_window, correction), correction, z)) {
    result.status = SampleStatus::outside_correction;
    result.p = result.E = nan;
    return result;
  }
  const std::array<double, correction_terms> phi = basis(z);
  result.E = modulus.E * std::exp(polynomial(correction.modulus, phi) + correction.modulus_residual.value(z));
  result.p = result.E * far.pressure_over_E * std::exp(polynomial(correction.pressure_ratio, phi));
  return result;
}

CorrectedTurgorModulus::CorrectedTurgorModulus(const Instrument& instrument, const ShellFeOptions& options,
                                               std::string_view location, OptionNames names,
                                               const Correction& correction)
    : instrument_(instrument), force_window_(options.force_window), correction_(correction) {
  validate(instrument_, location);
  if (correction_.training_points == 0) {
    throw InputError(std::string(location), "fidelity corrected: this build holds no fitted correction "
                                            "(src/correction/shipped_correction.inc; growthuq fit-correction writes it)");
  }
  require_fitted_for(correction_, options, instrument_, location, names);
}

void CorrectedTurgorModulus::evaluate(SampleBlock& block) const {
  const std::span<const double> k = std::as_const(block).column("k");
  const std::span<const double> d = std::as_const(block).column("d");
  const std::span<const double> d0 = std::as_const(block).column("d0");
  const std::span<const double> h = std::as_const(block).column("h");
  const std::span<const double> strain =
      block.has("hoop_strain") ? std::as_const(block).column("hoop_strain") : std::span<const double>();
  const SampleInstruments instruments(block, instrument_);
  const std::span<double> p = block.add_column("p");
  const std::span<double> E = block.add_column("E");
  const std::span<SampleStatus> status = block.status();
  for (std::size_t i = 0; i < block.size(); ++i) {
    if (status[i] != SampleStatus::ok) continue;
    const TubeDiameters diameters = strain.empty() ? diameters_in_si(d[i], d0[i]) : TubeDiameters{d[i], d0[i], 1.0 + strain[i], strain[i]};
    if (!(std::isfinite(h[i]) && h[i] > 0.0)) {
      status[i] = SampleStatus::invalid_input;
      continue;
    }
    const CorrectedInverse result = corrected_inverse(k[i], diameters, h[i], instruments[i], force_window_, correction_);
    if (result.status != SampleStatus::ok) {
      status[i] = result.status;
      continue;
    }
    p[i] = result.p;
    E[i] = result.E;
  }
}

Correction fit_correction(std::span<const TrainingPoint> points, const ShellFeOptions& options, double poisson_ratio,
                          int held_out_fold, const KrigingHyperparameters* hyperparameters) {
  Correction correction;
  correction.law = options.law;
  correction.substrate = options.substrate;
  correction.bending = options.bending;
  correction.tube_length = options.tube_length;
  correction.probe_distance = options.probe_distance;
  correction.poisson_ratio = poisson_ratio;
  Instrument instrument;
  instrument.poisson_ratio = poisson_ratio;

  // Per fitting row: ln groups, and the two targets ln(E/E_cf), ln((p/E)/(p/E)_far).
  std::vector<std::array<double, correction_groups>> groups;
  double widest_probe = 0.0;  // rho over the bending length sqrt(h d0 / 2)
  std::vector<double> modulus_target, ratio_target;
  for (const TrainingPoint& point : points) {
    if (!in_training_envelope(point) || held_out(point, held_out_fold)) continue;
    instrument.probe_radius_m = point.rho;
    const TubeDiameters diameters = diameters_in_si(point.d, point.d0);
    const TurgorResult turgor = invert_turgor(point.k, diameters, instrument);
    if (turgor.status != SampleStatus::ok) continue;
    const ModulusResult modulus = invert_modulus(turgor.p, diameters, point.h);
    const fe::FarFieldInverse far = fe::far_field_inverse(fe::far_field_law(options.law), diameters.lambda,
                                                          point.h / point.d0, poisson_ratio);
    if (modulus.status != SampleStatus::ok || far.status != fe::FarFieldInverseStatus::ok) continue;
    groups.push_back(correction_log_groups(point.k, diameters, point.h, point.rho, point.window, correction));
    widest_probe = std::max(widest_probe, point.rho / std::sqrt(point.h * point.d0 / 2));
    modulus_target.push_back(std::log(point.E / modulus.E));
    ratio_target.push_back(std::log(point.p / point.E / far.pressure_over_E));
  }
  const std::size_t rows = groups.size();
  if (rows < 2 * correction_terms) {
    throw InputError("fit-correction", std::to_string(rows) + " usable fitting rows: expected at least " +
                                           std::to_string(2 * correction_terms) + " (twice the polynomial's " +
                                           std::to_string(correction_terms) + " terms)");
  }
  for (std::size_t i = 0; i < correction_groups; ++i) {
    correction.low[i] = correction.high[i] = groups[0][i];
    for (const auto& row : groups) {
      correction.low[i] = std::min(correction.low[i], row[i]);
      correction.high[i] = std::max(correction.high[i], row[i]);
    }
  }
  Eigen::MatrixXd design(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(correction_terms));
  Eigen::VectorXd modulus(static_cast<Eigen::Index>(rows)), ratio(static_cast<Eigen::Index>(rows));
  for (std::size_t r = 0; r < rows; ++r) {
    std::array<double, correction_groups> z{};
    scaled(groups[r], correction, z);
    const auto phi = basis(z);
    for (std::size_t t = 0; t < correction_terms; ++t) design(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(t)) = phi[t];
    modulus(static_cast<Eigen::Index>(r)) = modulus_target[r];
    ratio(static_cast<Eigen::Index>(r)) = ratio_target[r];
  }
  // Householder QR with column pivoting: the least-squares solution without forming the normal
  // equations (whose condition number is the square of the design's).
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
  // Rows whose groups move together (one probe radius for every row) leave the polynomial's
  // terms collinear: least squares then returns huge coefficients that cancel (+-6e12 were
  // written), right on the rows and wild between them. Refused by the pivoted R's diagonal: its
  // smallest entry relative to its largest estimates the design's reciprocal condition: 0.019
  // to 0.023 for the shipped training set and its folds, 3.7e-17 with one probe radius for
  // every row (measured); 1e-9 lies far from both.
  const Eigen::VectorXd pivots = qr.matrixR().diagonal().cwiseAbs();
  const double conditioning = pivots.minCoeff() / pivots.maxCoeff();
  if (!(conditioning > 1e-9)) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2g", conditioning);
    throw InputError("fit-correction", std::to_string(rows) + " fitting rows whose groups are collinear (the design's "
                                           "reciprocal condition is " + std::string(text) +
                                           ", below 1e-9): expected rows that vary d/d0, h/d0, rho/d0, F_top/(k d0), a/d0 "
                                           "and F_low/F_top "
                                           "independently (e.g. more than one probe radius)");
  }
  const Eigen::VectorXd modulus_coefficients = qr.solve(modulus);
  const Eigen::VectorXd ratio_coefficients = qr.solve(ratio);
  for (std::size_t t = 0; t < correction_terms; ++t) {
    correction.modulus[t] = modulus_coefficients(static_cast<Eigen::Index>(t));
    correction.pressure_ratio[t] = ratio_coefficients(static_cast<Eigen::Index>(t));
  }
  // The modulus polynomial's residual, interpolated (residual_kriging.hpp): one polynomial over
  // the envelope leaves a few percent (src/correction/README.md, "Training data and fit").
  std::vector<double> centres, residuals;
  for (std::size_t r = 0; r < rows; ++r) {
    std::array<double, correction_groups> z{};
    scaled(groups[r], correction, z);
    centres.insert(centres.end(), z.begin(), z.end());
    residuals.push_back(modulus_target[r] - polynomial(correction.modulus, basis(z)));
  }
  correction.modulus_residual =
      fit_kriging(centres, correction_groups, residuals,
                  hyperparameters ? *hyperparameters : likeliest_hyperparameters(centres, correction_groups, residuals));
  correction.training_points = static_cast<int>(rows);
  correction.max_stiffness = correction_max_stiffness;
  correction.max_probe_over_bending_length = widest_probe;
  return correction;
}

}  // namespace growthuq
