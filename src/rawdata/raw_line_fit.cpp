#include "growthuq/rawdata/raw_line_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/distributions/sampled_range.hpp"
#include "growthuq/forcecurves/curve_processing.hpp"
#include "growthuq/forcecurves/force_curve.hpp"
#include "growthuq/io/csv.hpp"

namespace growthuq {
namespace {

// A value more than this factor from its column's median is no tube of the line: tubes of one
// line differ by a factor of a few (the shipped data by less than 10), a typo (1e300 for 3.0, a
// value in another unit) by far more. One such value would stretch every fitted law and move
// the line's results (a median turgor of 6e4 MPa) without a word.
constexpr double gross_outlier_factor = 1000.0;

void refuse_gross_outliers(const CsvTable& table, const std::string& column, const std::vector<double>& values,
                           const std::vector<std::size_t>& rows) {
  if (values.empty()) return;
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  const double median = n % 2 == 1 ? sorted[n / 2] : sorted[n / 2 - 1] + 0.5 * (sorted[n / 2] - sorted[n / 2 - 1]);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i] <= median * gross_outlier_factor && values[i] >= median / gross_outlier_factor) continue;
    throw_bad_value(table.row_location(rows[i]), column, table.rows[rows[i]][table.column_index(column)],
                    "a value within a factor " + format_double(gross_outlier_factor) + " of the column's median " +
                        format_double(median) + " (a typo, or a value in another unit?)");
  }
}

// The values of one column, in its unit. Blank cells are tubes where the quantity was not
// measured; anything else must be a number of the quantity's physical range.
// A tube listed twice would count twice in the fit (and in the bootstrap's redraws): refused
// naming both rows. Only for tables with a `tube` column (synth writes one; it is optional).
void refuse_repeated_tubes(const CsvTable& table) {
  if (!table.has_column("tube")) return;
  const std::size_t column = table.column_index("tube");
  std::map<std::string, std::size_t> first_row;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    const std::string& id = table.rows[row][column];
    if (id.empty()) continue;
    const auto [at, inserted] = first_row.emplace(id, row);
    if (!inserted) {
      throw_bad_value(table.row_location(row), "tube", id,
                      "each tube once (it is also " + table.row_location(at->second) + ")");
    }
  }
}

std::vector<double> read_measurement_column(const RawMeasurement& measurement) {
  const CsvTable table = read_csv(measurement.file);
  refuse_repeated_tubes(table);
  const std::size_t column = table.column_index(measurement.column);
  const bool fraction = measurement.variable == "einf";
  std::vector<double> values;
  std::vector<std::size_t> rows;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    const std::string& cell = table.rows[row][column];
    if (cell.empty()) continue;
    const double value = parse_double(cell, table.row_location(row), "column " + measurement.column);
    const double si = value * measurement.unit->to_si;
    if (fraction ? !(si >= 0.0 && si < 1.0) : !(value > 0.0)) {
      throw_bad_value(table.row_location(row), measurement.column, cell,
                      fraction ? "a rescaled equilibrium modulus in [0, 1) (as a fraction; [0, 100) in %)"
                               : "a positive " + std::string(find_quantity(measurement.variable)->description));
    }
    values.push_back(value);
    rows.push_back(row);
  }
  if (!fraction) refuse_gross_outliers(table, measurement.column, values, rows);
  return values;
}

std::string format_number(double value, const char* format = "%.4g") {
  if (!std::isfinite(value)) return "-";
  char text[48];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string padded(const std::string& text, std::size_t width) {
  return text.size() >= width ? text + "  " : text + std::string(width - text.size(), ' ');
}

const Unit& unit_named(std::string_view symbol) { return find_unit(symbol, "unit table", "unit"); }

RelaxationFits fit_curves(const RawLineFile& raw, const RawFitSettings& settings) {
  RelaxationFits relaxation;
  relaxation.options.terms = raw.relaxation.terms;
  relaxation.options.ramp_aware = raw.relaxation.ramp_aware;
  relaxation.options.poisson_ratio = settings.instrument.poisson_ratio;
  relaxation.curves = read_relaxation_curves(raw.relaxation.curves, raw.relaxation.meta,
                                             given_probe_radius_m(settings.instrument));
  if (settings.fit_curves) {
    relaxation.fits = settings.fit_curves(relaxation.curves, relaxation.options);
    if (relaxation.fits.size() != relaxation.curves.size()) throw std::logic_error("curve fitter lost curves of " + raw.name);
    return relaxation;
  }
  relaxation.fits.reserve(relaxation.curves.size());
  for (const RelaxationCurve& curve : relaxation.curves) {
    relaxation.fits.push_back(analyze_relaxation_curve(curve, relaxation.options));
  }
  return relaxation;
}

}  // namespace

VariableFit fit_variable_by_aic(std::string variable, const Unit& unit, std::vector<double> values,
                                std::vector<FitFamily> families, std::string source, std::string_view location) {
  VariableFit fit;
  fit.variable = std::move(variable);
  fit.unit = &unit;
  fit.source = std::move(source);
  fit.values = std::move(values);
  fit.families = std::move(families);
  double best = std::numeric_limits<double>::infinity();
  std::string failures;
  // Where the fraction is 1 in the values' unit (100 in %), for fractions (einf).
  const bool fraction = unit.dimension == Dimension::fraction;
  const double fraction_upper = 1.0 / unit.to_si;
  for (const FitFamily family : fit.families) {
    FamilyFit candidate;
    candidate.family = family;
    try {
      if (family == FitFamily::beta && !fraction) {
        throw InputError("", "the beta law is a law of fractions (einf); " + fit.variable + " is in " +
                                 std::string(unit.symbol));
      }
      FitResult result = fit_distribution(family, fit.values, fraction_upper);
      // A law that would draw inf or 0 (one mistyped value can stretch a fit that far) is no
      // fit: another family may still describe the data (sampled_range.hpp).
      if (const std::optional<std::string> problem = sampled_range_problem(result.distribution, unit.to_si)) {
        throw InputError("", describe(result.distribution) + " cannot be sampled: " + *problem);
      }
      // Nor is a law of a fraction that would draw values above 1 (100 %) or below 0: however
      // good its AIC, those samples are no tube's.
      if (fraction) {
        if (const std::optional<std::string> problem = fraction_range_problem(result.distribution, fraction_upper)) {
          throw InputError("", describe(result.distribution) + " would draw fractions outside [0, 1]: " + *problem);
        }
      }
      candidate.result = std::move(result);
      if (candidate.result->aic < best) {
        best = candidate.result->aic;
        fit.chosen = fit.candidates.size();
      }
    } catch (const InputError& error) {
      candidate.failure = error.problem();
      failures += (failures.empty() ? "" : "; ") + std::string(to_string(family)) + ": " + error.problem();
    }
    fit.candidates.push_back(std::move(candidate));
  }
  if (!std::isfinite(best)) {
    throw InputError(std::string(location), fit.variable + " (" + fit.source + "): no family could be fitted (" + failures + ")");
  }
  return fit;
}

std::size_t RelaxationFits::ok_count() const {
  std::size_t ok = 0;
  for (const CurveFit& fit : fits) ok += fit.ok ? 1 : 0;
  return ok;
}

LineDistributions line_distributions_of(const RawLineFile& raw, const std::vector<VariableFit>& variables) {
  LineDistributions line;
  line.name = raw.name;
  line.description = raw.description;
  line.path = raw.path;
  for (const VariableFit& variable : variables) {
    const FitResult& best = variable.best();
    line.variables.push_back(LineVariable{
        variable.variable, variable.unit, best.distribution,
        "maximum-likelihood " + std::string(to_string(best.family)) + " fit to " + std::to_string(best.sample_size) +
            " values of " + variable.source + " (least AIC of " + std::to_string(variable.families.size()) +
            " families; KS D " + format_number(best.ks_statistic, "%.3g") + ", AD A^2 " +
            format_number(best.ad_statistic, "%.3g") + ")",
        "", 0, best.sample_size});  // tubes: a line file written from it keeps its data uncertainty
  }
  return line;
}

RawLineFit fit_raw_line(const RawLineFile& raw, const RawFitSettings& settings) {
  RawLineFit result;
  result.raw = raw;
  for (const RawMeasurement& measurement : raw.measurements) {
    result.variables.push_back(fit_variable_by_aic(measurement.variable, *measurement.unit,
                                                   read_measurement_column(measurement), measurement.families,
                                                   measurement.file + ", column " + measurement.column,
                                                   file_location(raw.path, measurement.line)));
  }
  if (raw.has_relaxation) {
    result.relaxation = fit_curves(raw, settings);
    std::vector<double> tau, einf;
    for (const CurveFit& fit : result.relaxation->fits) {
      if (!fit.ok) continue;
      tau.push_back(fit.tau.back());
      einf.push_back(fit.einf);
    }
    const std::string location = file_location(raw.path, raw.relaxation.line);
    const std::size_t curves = result.relaxation->curves.size();
    if (tau.size() < 2) {
      std::string reasons;
      for (const CurveFit& fit : result.relaxation->fits) {
        if (!fit.ok && reasons.size() < 400) reasons += (reasons.empty() ? "" : "; ") + fit.curve + ": " + fit.reason;
      }
      throw InputError(location, std::to_string(tau.size()) + " of " + std::to_string(curves) + " curves of " +
                                     raw.relaxation.curves + " were fitted: expected at least 2 to fit tau and einf (" +
                                     reasons + ")");
    }
    const std::string source = raw.relaxation.curves + ", " + std::to_string(tau.size()) + " of " +
                               std::to_string(curves) + " curves fitted";
    result.variables.push_back(fit_variable_by_aic("tau", unit_named("s"), std::move(tau), raw.relaxation.families,
                                                   "tau_slow of " + source, location));
    result.variables.push_back(fit_variable_by_aic("einf", unit_named("frac"), std::move(einf), raw.relaxation.einf_families,
                                                   "E_inf/E_r(0) of " + source, location));
  }
  if (raw.has_force_curves) {
    // k per tube: the mean of its ok curves (Eq. (C10), src/forcecurves/README.md).
    const RawForceCurves& source = raw.force_curves;
    ForceCurveFits fits;
    fits.data = read_force_curves(source.curves, source.sheet);
    for (const ForceCurve& curve : fits.data) fits.curves.push_back(process_force_curve(curve, source.options));
    fits.tubes = tube_stiffness(fits.curves);
    std::vector<double> k, u;
    for (const TubeStiffness& tube : fits.tubes) {
      if (tube.ok == 0) continue;
      k.push_back(tube.stiffness);
      u.push_back(tube.uncertainty);
    }
    const std::string location = file_location(raw.path, source.line);
    if (k.size() < 2) {
      throw InputError(location, std::to_string(k.size()) + " of " + std::to_string(fits.tubes.size()) + " tubes of " +
                                     source.curves + " have an ok curve: expected at least 2 to fit k (growthuq curves "
                                     "names each curve's status and reason)");
    }
    const std::string described = "k per tube of " + source.curves + ", " + std::to_string(k.size()) + " of " +
                                  std::to_string(fits.tubes.size()) + " tubes with an ok curve";
    result.variables.push_back(fit_variable_by_aic("k", unit_named("N/m"), std::move(k), source.families, described, location));
    if (source.measurement_error) result.variables.back().uncertainties = std::move(u);
    result.force_curves = std::move(fits);
  }
  result.distributions = line_distributions_of(raw, result.variables);
  return result;
}

std::string distribution_parameters(const Distribution& distribution) {
  const std::string text = describe(distribution);
  const std::size_t open = text.find('(');
  return text.substr(open + 1, text.size() - open - 2);
}

std::string format_raw_fit_report(const RawLineFit& fit) {
  std::string text = "line " + fit.raw.name + ": distributions fitted to raw data (" + fit.raw.path +
                     "), family of least AIC\n";
  text += "  " + padded("variable", 10) + padded("unit", 6) + padded("n", 5) + padded("family", 11) + padded("median", 10) +
          padded("IQR", 10) + padded("KS D", 8) + padded("AD A^2", 8) + "AIC of the others (+ = worse)\n";
  for (const VariableFit& variable : fit.variables) {
    const FitResult& best = variable.best();
    const double q1 = quantile(best.distribution, 0.25), q3 = quantile(best.distribution, 0.75);
    std::string others;
    for (const FamilyFit& candidate : variable.candidates) {
      if (candidate.family == best.family) continue;
      others += (others.empty() ? "" : ", ") + std::string(to_string(candidate.family)) + " " +
                (candidate.result ? format_number(candidate.result->aic - best.aic, "%+.1f") : "failed: " + candidate.failure);
    }
    text += "  " + padded(variable.variable, 10) + padded(std::string(variable.unit->symbol), 6) +
            padded(std::to_string(best.sample_size), 5) + padded(std::string(to_string(best.family)), 11) +
            padded(format_number(quantile(best.distribution, 0.5)), 10) + padded(format_number(q3 - q1), 10) +
            padded(format_number(best.ks_statistic, "%.3f"), 8) + padded(format_number(best.ad_statistic, "%.3f"), 8) +
            (others.empty() ? "-" : others) + "\n";
  }
  if (fit.relaxation) {
    const RelaxationFits& relaxation = *fit.relaxation;
    const std::size_t ok = relaxation.ok_count();
    std::size_t extrapolated = 0;
    for (const CurveFit& curve_fit : relaxation.fits) extrapolated += curve_fit.extrapolated ? 1 : 0;
    text += "  relaxation curves: " + std::to_string(relaxation.curves.size()) + ", " + std::to_string(ok) + " fitted (" +
            std::to_string(relaxation.options.terms) + "-term " + (relaxation.options.ramp_aware ? "ramp-aware" : "step") +
            " fit; " + std::to_string(extrapolated) + " of them extrapolated: tau_slow beyond the hold), " +
            std::to_string(relaxation.curves.size() - ok) + " fit_failed (left out of tau and einf)\n";
    double worst_se = 0.0;
    const CurveFit* widest = nullptr;  // of the 95 % profile intervals (step fit), by high / low
    for (const CurveFit& curve_fit : relaxation.fits) {
      if (!curve_fit.ok) {
        text += "    " + curve_fit.curve + ": fit_failed: " + curve_fit.reason + "\n";
        continue;
      }
      worst_se = std::max(worst_se, curve_fit.tau_slow_relative_se);
      const auto width = [](const CurveFit& f) { return f.tau_slow_high / f.tau_slow_low; };
      if (std::isfinite(width(curve_fit)) && (widest == nullptr || width(curve_fit) > width(*widest))) widest = &curve_fit;
    }
    // An extrapolated tau_slow's linearized standard error means little; its interval says how
    // well the curve determines it (Eq. (R6b), src/relaxation/README.md).
    if (widest != nullptr) {
      text += "    widest 95 % interval of a fitted tau_slow: " + widest->curve + " [" + format_number(widest->tau_slow_low) +
              ", " + format_number(widest->tau_slow_high) + "] s\n";
    } else if (ok > 0) {
      text += "    largest standard error of a fitted tau_slow: " + format_number(100.0 * worst_se, "%.2g") + " %\n";
    }
  }
  if (fit.force_curves) {
    const ForceCurveFits& force_curves = *fit.force_curves;
    std::map<std::string, std::size_t> counts;
    for (const CurveResult& curve : force_curves.curves) ++counts[std::string(to_string(curve.status))];
    std::string rated;
    for (const auto& [status, count] : counts) rated += (rated.empty() ? "" : ", ") + status + " " + std::to_string(count);
    std::size_t with_k = 0;
    for (const TubeStiffness& tube : force_curves.tubes) with_k += tube.ok > 0 ? 1 : 0;
    text += "  force curves: " + std::to_string(force_curves.curves.size()) + " of " +
            std::to_string(force_curves.tubes.size()) + " tubes (" + rated + "); k of " + std::to_string(with_k) +
            " tubes, the mean of their ok curves\n";
    for (const CurveResult& curve : force_curves.curves) {
      if (curve.status != CurveStatus::ok) {
        text += "    " + curve.curve + ": " + std::string(to_string(curve.status)) + ": " + curve.reason + "\n";
      }
    }
  }
  return text;
}

std::string fitted_line_file_text(const RawLineFit& fit) {
  std::string text = "# Written by growthuq fit-line from " + fit.raw.path +
                     ": maximum-likelihood fits of the raw data,\n# the family of least AIC for every variable.\n"
                     "[line]\nname = " + fit.raw.name + "\n";
  if (!fit.raw.description.empty()) text += "description = " + fit.raw.description + "\n";
  for (const LineVariable& variable : fit.distributions.variables) text += "\n" + format_line_variable(variable);
  return text;
}

}  // namespace growthuq
