// Force-relaxation curves as a lab exports them. Forces: a long-format CSV, one row per
// sample, `curve,t_s,F_uN`. Metadata per curve (`curve,delta_um,p_MPa,d_um,h_nm[,rho_um]`):
// either a second CSV with one row per curve (--meta; the tube sheet a lab already keeps), or
// the same columns in the force file, repeated on every row of a curve. Format in
// distributions/README.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace growthuq {

struct RelaxationCurve {
  std::string name;
  std::string location;          // "<file>:<line>" of its first sample, for messages
  std::vector<double> t;         // s, increasing; the record starts at contact (ramp start)
  std::vector<double> force;     // N, >= 0
  double indentation = 0.0;      // delta: probe displacement during the hold (m)
  double turgor = 0.0;           // p (Pa)
  double diameter = 0.0;         // d, turgid (m)
  double thickness = 0.0;        // h (m)
  double probe_radius_m = 0.0;   // rho, from the tube sheet or the instrument
};

// A curve needs this many samples (ramp and hold together) to be fitted at all.
inline constexpr std::size_t minimum_curve_samples = 20;

// Reads and validates the curves, in order of first appearance. `meta_path` empty: metadata
// columns are read from the force file and must be constant within a curve. `probe_radius_m`
// is used when no rho_um column exists; with one, a row whose rho_um differs from it is an
// error (never silently overridden). InputError naming file and line for: a missing
// column, a non-numeric cell, time not increasing within a curve, a negative force, fewer than
// minimum_curve_samples samples, a curve without metadata (or metadata without a curve, or
// twice), a metadata value that is not positive, no probe radius at all.
std::vector<RelaxationCurve> read_relaxation_curves(const std::string& curves_path,
                                                    const std::string& meta_path,
                                                    std::optional<double> probe_radius_m);

}  // namespace growthuq
