// A plant line's raw data file (raw.ini): where a lab's per-tube measurement tables and
// force-relaxation curves are and what their columns hold, so that the line's distributions
// can be fitted from them (raw_line_fit.hpp) instead of being typed in as medians and IQRs.
// Validated as strictly as line files; the format is documented in distributions/README.md
// ("Raw data: what a lab provides").
//
//   [line]                      name = wild_type, description = ... (optional)
//   [measurement VARIABLE]      one per variable measured tube by tube (k, h, d, d0, v_exp; tau
//                               and einf too when a lab has fitted its curves elsewhere):
//                               file = CSV, column = header name, unit = unit of the values,
//                               families = subset of lognormal, normal, gamma, weibull, beta
//                               (optional; beta only for einf, whose default list starts with it)
//   [relaxation]                optional; gives tau and einf: curves = CSV (curve,t_s,F_uN),
//                               meta = CSV (curve,delta_um,p_MPa,d_um,h_nm[,rho_um]; optional when
//                               the curves file has those columns), terms = 1|2|3 (2),
//                               fit = step|ramp_aware (step), families = ... (optional)
//   [force_curves]              optional; gives k per tube from raw force-indentation curves
//                               (forcecurves/): curves = CSV (a long table with a curve column),
//                               sheet = CSV (curve,tube,repetition,rho_um,k_sys_N_per_m),
//                               window = relative|absolute (relative), window_uN = a,b (4,0.5 or
//                               0.4,4), contact = deviation|piecewise (deviation),
//                               measurement_error = bootstrap|none (bootstrap), families = ...
#pragma once

#include <string>
#include <vector>

#include "growthuq/core/units.hpp"
#include "growthuq/distributions/fit.hpp"
#include "growthuq/forcecurves/curve_processing.hpp"

namespace growthuq {

// One variable measured tube by tube: a column of a CSV table.
struct RawMeasurement {
  std::string variable;             // k, h, d, d0, tau, einf or v_exp
  std::string file;                 // resolved against the raw file's folder
  std::string column;               // header name in `file`
  const Unit* unit = nullptr;       // of the values, of the variable's dimension
  std::vector<FitFamily> families;  // compared by AIC; the defaults (fit.hpp) unless restricted
  long line = 0;                    // of the section header, for messages
};

// Force-relaxation curves, fitted curve by curve to give the line's tau and einf.
struct RawRelaxation {
  std::string curves;               // resolved like RawMeasurement::file
  std::string meta;                 // empty: metadata columns are in the curves file
  int terms = 2;                    // exponentials of the Prony series
  bool ramp_aware = false;          // fit = ramp_aware
  std::vector<FitFamily> families;       // for the tau law (and einf's when listed in the file)
  std::vector<FitFamily> einf_families;  // the list given, or fraction_fit_families by default
  long line = 0;
};

// Raw force-indentation curves, processed curve by curve; each tube's mean k (of its ok curves)
// is one value of k.
struct RawForceCurves {
  std::string curves;               // resolved like RawMeasurement::file
  std::string sheet;
  CurveProcessingOptions options;   // window and contact from the section, the rest the defaults
  std::vector<FitFamily> families;
  // measurement_error = bootstrap (true, the default) | none: whether the data bootstrap draws
  // each tube's k within its uncertainty u (src/forcecurves/README.md, Eq. (C11)).
  bool measurement_error = true;
  long line = 0;
};

struct RawLineFile {
  std::string path;  // as given
  std::string name;
  std::string description;
  std::vector<RawMeasurement> measurements;  // in file order
  bool has_relaxation = false;
  RawRelaxation relaxation;
  bool has_force_curves = false;
  RawForceCurves force_curves;

  // The variables the file provides (the relaxation's tau and einf and the force curves' k
  // included), in file order.
  std::vector<std::string> variables() const;
};

// Reads and validates `path`: unknown sections or keys, a variable given twice (or tau/einf both
// as a measurement and by [relaxation]), a unit of the wrong dimension, a missing or unreadable
// file, an unknown family: each an InputError naming the raw file, line, key and value. The
// tables' columns are checked when the data are read (fit_raw_line), naming the table.
RawLineFile read_raw_line_file(const std::string& path);

}  // namespace growthuq
