// Raw force-indentation curves of a cellular force microscope as a lab exports them (stage
// position and force, or sensor voltage), and the curve sheet naming each curve's tube,
// repetition, probe radius and sensor stiffness. File format: distributions/README.md, "Force
// curves"; what is done with a curve: src/forcecurves/README.md.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace growthuq {

struct ForceCurve {
  std::string name;
  std::string tube;
  int repetition = 0;
  std::string location;               // "<file>:<line>" of its first sample, for messages
  std::vector<double> position;       // stage position z (m), increasing towards the tube on approach
  std::vector<double> force;          // N, as recorded: baseline offset and drift not removed
  std::vector<double> time;           // s; empty when the file has no t_s column
  std::size_t approach_end = 0;       // samples [0, approach_end) are the approach, the rest the retract
  double probe_radius_m = 0.0;
  double sensor_stiffness_N_per_m = 0.0;  // k_sys; +inf for an ideal sensor (no series correction)
};

// An approach needs this many samples to hold a baseline, a contact and a fit window at all.
inline constexpr std::size_t minimum_approach_samples = 20;

// Reads the curves of `curves_path`, in order of first appearance: a CSV file, or a folder whose
// every *.csv file (the sheet excepted) is read, in name order. A file with a `curve` column is a
// long table of several curves; a file without one is one curve named by the file's stem.
// `sheet_path` empty: `<folder>/sheet.csv` for a folder (a file needs a sheet named).
// InputError naming file, line and column for: a missing or ambiguous column, a non-numeric cell,
// a position not increasing during the approach, a time not increasing, a segment other than
// approach/retract or an approach after a retract, fewer than minimum_approach_samples approach
// samples, a curve without a sheet row (or a sheet row without a curve, or twice), a repeated
// (tube, repetition), a probe radius or sensor stiffness out of range, a voltage column without
// a positive gain.
std::vector<ForceCurve> read_force_curves(const std::string& curves_path, const std::string& sheet_path);

// The curves as a long table `curve,t_s,z_um,F_uN,segment` (t_s when every curve has times) and
// their sheet `curve,tube,repetition,rho_um,k_sys_N_per_m`, as read_force_curves reads them back.
// `decimals` >= 0 rounds t_s, z_um and F_uN to that many decimals (trailing zeros dropped), as an
// instrument's reading has a resolution; -1 writes every double exactly.
std::string force_curves_csv(const std::vector<ForceCurve>& curves, int decimals = -1);
std::string curve_sheet_csv(const std::vector<ForceCurve>& curves);

}  // namespace growthuq
