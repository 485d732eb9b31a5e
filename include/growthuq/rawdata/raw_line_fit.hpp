// From a lab's raw data (raw_line_file.hpp) to a plant line's distributions: every variable
// measured tube by tube is fitted by maximum likelihood with each candidate family and the
// family of least AIC is kept (Eqs. (D5), (D6), src/distributions/README.md); tau and einf come
// from fitting the force-relaxation curves one by one (relaxation/analysis.hpp) and then fitting
// their distributions the same way. Every fit is kept for the report: families that failed, curves
// whose fit failed (with the reason), the data themselves.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "growthuq/distributions/fit.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/forcecurves/tube_stiffness.hpp"
#include "growthuq/mechanics/instrument.hpp"
#include "growthuq/rawdata/raw_line_file.hpp"
#include "growthuq/relaxation/analysis.hpp"
#include "growthuq/relaxation/curves.hpp"

namespace growthuq {

// Fits a line's relaxation curves: one CurveFit per curve, in the curves' order, each
// analyze_relaxation_curve(curve, options).
using CurveFitter =
    std::function<std::vector<CurveFit>(const std::vector<RelaxationCurve>& curves, const RelaxationOptions& options)>;

struct RawFitSettings {
  // nu of the wall for E_r(t), and the probe radius of curves whose tube sheet has no rho_um
  // column (NaN: every tube sheet must have one). The sensor stiffness is not used.
  Instrument instrument;
  // Where the curve fits run (most of a raw line's fitting time): one after the other here when
  // empty; a campaign shares them out over its processes (campaign/shared_raw_fits.hpp).
  CurveFitter fit_curves;
};

// One family's attempt: the ML fit, or why it failed (e.g. a non-positive value for a positive law).
struct FamilyFit {
  FitFamily family = FitFamily::lognormal;
  std::optional<FitResult> result;
  std::string failure;
};

struct VariableFit {
  std::string variable;
  const Unit* unit = nullptr;         // of `values` and of the fitted law
  std::string source;                 // where the values come from, for reports and line files
  std::vector<double> values;         // the data fitted, in `unit`
  // Each value's measurement uncertainty (same unit), drawn within in the data bootstrap
  // (campaign/data_uncertainty.hpp); empty: the values are taken as exact. Only k of force
  // curves has them ([force_curves] measurement_error = bootstrap).
  std::vector<double> uncertainties;
  std::vector<FitFamily> families;    // compared, in this order
  std::vector<FamilyFit> candidates;  // one per family
  std::size_t chosen = 0;             // least AIC among the successful candidates

  const FitResult& best() const { return *candidates[chosen].result; }
};

// Fits `values` with every family and keeps the one of least AIC (ties: the earlier family).
// A family fails (kept with its reason) when its law cannot be sampled (sampled_range.hpp), and
// for a fraction (a unit of Dimension::fraction: einf) also when its law would draw a value
// outside [0, 1] (fraction_range_problem); the beta law fails for any other variable.
// InputError at `location` naming the variable and every family's failure when none fits.
VariableFit fit_variable_by_aic(std::string variable, const Unit& unit, std::vector<double> values,
                                std::vector<FitFamily> families, std::string source, std::string_view location);

struct RelaxationFits {
  RelaxationOptions options;
  std::vector<RelaxationCurve> curves;  // as read, SI
  std::vector<CurveFit> fits;           // one per curve, same order

  std::size_t ok_count() const;
};

// The force curves of [force_curves], processed (src/forcecurves/README.md).
struct ForceCurveFits {
  std::vector<ForceCurve> data;     // as read, SI
  std::vector<CurveResult> curves;  // one per curve, same order
  std::vector<TubeStiffness> tubes;
};

struct RawLineFit {
  RawLineFile raw;
  std::vector<VariableFit> variables;       // measurements in file order, then tau and einf, then k of force curves
  std::optional<RelaxationFits> relaxation;
  std::optional<ForceCurveFits> force_curves;
  LineDistributions distributions;          // the chosen laws, as a line file would give them
};

// Reads every table and curve the raw file names and fits them. InputError naming the table
// and row for a non-numeric or physically impossible value (a stiffness, length, time or rate
// that is not positive, an einf outside [0, 1)), naming the raw file when a variable has fewer
// than two values or when fewer than two curves fit. Blank cells are not measurements and are
// skipped (a table may hold tubes with some quantities missing).
RawLineFit fit_raw_line(const RawLineFile& raw, const RawFitSettings& settings);

// The line distributions of a set of variable fits (their chosen laws), named after `raw`; each
// law states as tubes the number of values it was fitted to.
LineDistributions line_distributions_of(const RawLineFile& raw, const std::vector<VariableFit>& variables);

// A readable table of the fits of one line: per variable n, family, parameters, the law's median
// and IQR, KS D, AD A^2 and the AIC gap to the other families; then the curves' fit summary with
// every failed curve and its reason; then the force curves' report (curves per tube, rated how).
std::string format_raw_fit_report(const RawLineFit& fit);

// "mu=1.05, sigma=0.21" from describe()'s "lognormal(mu=1.05, sigma=0.21)".
std::string distribution_parameters(const Distribution& distribution);

// The fitted line as a line file (distributions/<line>.ini format), for `growthuq fit-line`.
std::string fitted_line_file_text(const RawLineFit& fit);

}  // namespace growthuq
