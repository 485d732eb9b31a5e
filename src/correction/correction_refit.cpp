#include "growthuq/correction/correction_refit.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "correction/correction_training.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/correction/corrected_closed_form.hpp"
#include "growthuq/io/csv.hpp"

namespace growthuq {
namespace {

struct Errors {
  int rows = 0, outside = 0;
  double max_p = 0, max_E = 0, max_closed_p = 0, max_closed_E = 0;
};

// The corrected inverse of a training row's measured tube (its own probe, the correction's nu).
CorrectedInverse corrected_for(const TrainingPoint& point, const Correction& correction) {
  Instrument instrument;
  instrument.probe_radius_m = point.rho;
  instrument.poisson_ratio = correction.poisson_ratio;
  return corrected_inverse(point.k, diameters_in_si(point.d, point.d0), point.h, instrument, point.window, correction);
}

// The largest relative errors of the corrected and the closed form against the training rows'
// finite-element p and E, over the rows `held` says.
Errors errors_of(const std::vector<TrainingPoint>& points, const Correction& correction, bool held) {
  Errors errors;
  for (const TrainingPoint& point : points) {
    if (!in_training_envelope(point) || held_out(point) != held) continue;
    const CorrectedInverse result = corrected_for(point, correction);
    if (result.status == SampleStatus::outside_correction) {
      ++errors.outside;
      continue;
    }
    if (result.status != SampleStatus::ok) continue;
    ++errors.rows;
    errors.max_p = std::max(errors.max_p, std::abs(result.p / point.p - 1));
    errors.max_E = std::max(errors.max_E, std::abs(result.E / point.E - 1));
    errors.max_closed_p = std::max(errors.max_closed_p, std::abs(result.closed_form_p / point.p - 1));
    errors.max_closed_E = std::max(errors.max_closed_E, std::abs(result.closed_form_E / point.E - 1));
  }
  return errors;
}

// Per training tube and window with a value: its groups, the finite-element p and E, and both
// fidelities' values (for the plot of tools/fe-correction/plot-errors).
std::string errors_table(const std::vector<TrainingPoint>& points, const Correction& correction) {
  CsvWriter writer({"index", "window_low_uN", "window_top_uN", "held_out", "lambda", "h_over_d", "rho_over_d", "k_N_per_m",
                    "p_fe_MPa", "E_fe_MPa", "p_closed_form_MPa", "E_closed_form_MPa", "p_corrected_MPa", "E_corrected_MPa",
                    "status"});
  for (const TrainingPoint& point : points) {
    if (!in_training_envelope(point)) continue;
    const CorrectedInverse r = corrected_for(point, correction);
    const auto mpa = [](double pa) { return std::isfinite(pa) ? format_double(pa * 1e-6) : std::string(); };
    writer.add_row({std::to_string(point.index), format_double(point.window[0] * 1e6), format_double(point.window[1] * 1e6),
                    held_out(point) ? "1" : "0", format_double(point.d / point.d0), format_double(point.h / point.d),
                    format_double(point.rho / point.d), format_double(point.k), mpa(point.p), mpa(point.E),
                    mpa(r.closed_form_p), mpa(r.closed_form_E), mpa(r.p), mpa(r.E), std::string(to_string(r.status))});
  }
  return writer.text();
}

// Five-fold cross-validation: each fold of the rows held out in turn, the correction refitted to
// the others and its errors on the fold collected. One held-out split can be lucky; this says
// how the form does on tubes it was not fitted on, over all the data.
struct CrossValidation {
  int predictions = 0, outside = 0, within_two_percent = 0;
  double sum_squares = 0, largest = 0;  // of the larger of the two errors (p, E) per tube
};

// Each fold's kriging keeps the hyperparameters of the shipped fit (`hyperparameters`): refitting
// them per fold would take a minute more each and move them little (the likelihood is flat near
// its maximum), while the polynomial and the kriging weights are refitted without the fold.
CrossValidation cross_validate(const std::vector<TrainingPoint>& points, double poisson_ratio,
                               const KrigingHyperparameters& hyperparameters) {
  CrossValidation cv;
  for (int fold = 0; fold < correction_folds; ++fold) {
    const Correction correction = fit_correction(points, ShellFeOptions{}, poisson_ratio, fold, &hyperparameters);
    for (const TrainingPoint& point : points) {
      if (!in_training_envelope(point) || !held_out(point, fold)) continue;
      const CorrectedInverse result = corrected_for(point, correction);
      if (result.status == SampleStatus::outside_correction) ++cv.outside;
      if (result.status != SampleStatus::ok) continue;
      const double error = std::max(std::abs(result.p / point.p - 1), std::abs(result.E / point.E - 1));
      ++cv.predictions;
      cv.within_two_percent += error <= 0.02 ? 1 : 0;
      cv.sum_squares += error * error;
      cv.largest = std::max(cv.largest, error);
    }
  }
  return cv;
}

std::string percent(double fraction) { return format_double(std::round(fraction * 1e4) / 1e2) + " %"; }

std::string line_of(std::string_view name, const Errors& errors) {
  return std::string(name) + ": " + std::to_string(errors.rows) + " rows (" + std::to_string(errors.outside) +
         " outside the fitted region); largest error corrected p " + percent(errors.max_p) + ", E " + percent(errors.max_E) +
         "; closed form p " + percent(errors.max_closed_p) + ", E " + percent(errors.max_closed_E) + "\n";
}

}  // namespace

CorrectionRefit refit_correction(const std::string& training_csv, const std::string& curves_csv) {
  const std::vector<TrainingPoint> points = under_training_windows(read_training_csv(training_csv), curves_csv);
  // The fit's refusals (too few usable rows, collinear groups) are the training file's.
  const Correction correction = [&] {
    try {
      return fit_correction(points, ShellFeOptions{}, Instrument{}.poisson_ratio);
    } catch (const InputError& error) {
      throw InputError(training_csv, error.problem());
    }
  }();
  CorrectionRefit refit;
  refit.report = line_of("fitted", errors_of(points, correction, false)) + line_of("held out", errors_of(points, correction, true));
  const ResidualKriging& kriging = correction.modulus_residual;
  const CrossValidation cv = cross_validate(points, Instrument{}.poisson_ratio,
                                            KrigingHyperparameters{kriging.length_scales, kriging.signal_sd, kriging.noise_sd});
  refit.report += "cross-validation (" + std::to_string(correction_folds) + " folds, each held out in turn and the rest "
                  "refitted, the kriging with the fit's hyperparameters): " + std::to_string(cv.predictions) + " predictions (" + std::to_string(cv.outside) +
                  " outside the fitted region), " + std::to_string(cv.within_two_percent) +
                  " within 2 % in p and E; larger of the two errors rms " +
                  percent(cv.predictions ? std::sqrt(cv.sum_squares / cv.predictions) : 0.0) + ", largest " +
                  percent(cv.largest) + "\n";
  refit.errors_table = errors_table(points, correction);
  refit.source = correction_source(correction);
  refit.fitted_rows = correction.training_points;
  return refit;
}

}  // namespace growthuq
