// The offline training of fidelity `corrected` (`growthuq fit-correction`): the rows of the
// finite-element training data, which of them the fit uses and holds out, the least-squares fit
// and the C++ text the engine compiles in. Not part of the library's API: a campaign only reads
// the fitted Correction (corrected_closed_form.hpp). src/correction/README.md, "Training data and fit".
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "correction/kriging_fit.hpp"
#include "growthuq/correction/corrected_closed_form.hpp"

namespace growthuq {

// One tube of the training data (src/correction/training.csv) under one force window: a forward
// finite-element simulation's inputs and what an instrument measures of it, SI.
struct TrainingPoint {
  int index = 0;                                // the simulation's row
  double p = 0, E = 0, h = 0, d0 = 0, rho = 0;  // inputs (h turgid)
  double k = 0, d = 0;                          // measured: k over the window, turgid d
  std::array<double, 2> window{0.4e-6, 4e-6};   // the force window k is fitted over, N
  bool ok = false;                              // k and d present
};

// The rows of a training CSV (header index,p_MPa,E_MPa,h_nm,...,d0_um,rho_um,...,k_N_per_m,d_um,
// status,...), each with k over the default window 0.4-4 uN; InputError naming the file and line
// of a malformed row.
std::vector<TrainingPoint> read_training_csv(const std::string& path);

// The force windows the correction is fitted over, N: tops of 2, 3 and 4 uN, each with its bottom
// at 0.05, 0.1, 0.25 and 0.5 of the top. The bottom-over-top ratios span the force-curve
// software's conventions: a fixed bottom under the setpoint (0.4 of 4 uN: 0.1) and windows set
// relative to the curve's largest force (5-95 %: 0.053, 10-90 %: 0.11, 20-80 %: 0.25, 50-100 %:
// 0.5). The default window, 0.4-4 uN, is among them. k over a lower window is read from the curve
// run to the default window's top, whose load steps are then coarser than those of a run to the
// lower top: measured on six tubes, the two differ by up to 0.5 % at a top of 2 uN and 0.2 % at
// 3 uN (src/correction/README.md), and by more at 1 uN (0.6 % on the one tube run), which is why
// the tops stop at 2 uN.
std::vector<std::array<double, 2>> training_windows();

// Every tube of `rows` with a turgid state (d and h present, whatever its status over the
// default window: a curve that stopped short still serves a lower window) under every training
// window its force curve reaches, k fitted over the window as the instrument's software fits it
// (fe/force_window.hpp). The curves: a CSV of index,delta_um,F_uN (more columns ignored), the
// rows of each index consecutive and in the order of depth (tools/fe-correction/generate-training
// writes it). InputError naming the file and line of a malformed row or a curve of no row.
std::vector<TrainingPoint> under_training_windows(const std::vector<TrainingPoint>& rows, const std::string& curves_path);

// Whether a row is held out of the fit to test the correction: the shipped fit holds out fold 4
// (every fifth index: 4, 9, 14, ...); cross-validation holds out each fold in turn.
inline constexpr int correction_folds = 5;
inline bool held_out(const TrainingPoint& point, int fold = correction_folds - 1) {
  return point.index % correction_folds == fold;
}

// The rows the correction is fitted to and tested on: stiffnesses up to 20 N/m, the stiffest
// tubes of the shipped lines with a margin (xxt1_xxt2 reaches 15.5 N/m at the published scale).
// fit_correction writes this limit into the Correction it returns, with the widest fitted probe
// in bending lengths; corrected_inverse gives a tube beyond either outside_correction whatever its
// groups.
inline constexpr double correction_max_stiffness = 20.0;  // N/m
inline bool in_training_envelope(const TrainingPoint& point) { return point.ok && point.k <= correction_max_stiffness; }

// Least-squares fit of both polynomials to the fitting rows (in the envelope and not in the
// held-out fold) for the model options the data were made with, then the kriging of the modulus
// polynomial's residual, with `hyperparameters` or (null) the likeliest for these rows.
// InputError when fewer rows than twice the terms remain.
Correction fit_correction(std::span<const TrainingPoint> points, const ShellFeOptions& options, double poisson_ratio,
                          int held_out_fold = correction_folds - 1,
                          const KrigingHyperparameters* hyperparameters = nullptr);

// The C++ text of shipped_correction.inc for `correction` (every number to 17 digits).
std::string correction_source(const Correction& correction);

}  // namespace growthuq
