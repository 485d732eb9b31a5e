// The offline training of fidelity `corrected` (`growthuq fit-correction`): the rows of the
// finite-element training data, which of them the fit uses and holds out, the least-squares fit
// and the C++ text the engine compiles in. Not part of the library's API: a campaign only reads
// the fitted Correction (corrected_closed_form.hpp). src/correction/README.md, "Training data and fit".
#pragma once

#include <span>
#include <string>
#include <vector>

#include "growthuq/correction/corrected_closed_form.hpp"

namespace growthuq {

// One row of the training data (src/correction/training.csv): a forward finite-element
// simulation's inputs and what an instrument measures of it, SI.
struct TrainingPoint {
  int index = 0;
  double p = 0, E = 0, h = 0, d0 = 0, rho = 0;  // inputs (h turgid)
  double k = 0, d = 0;                          // measured: k over the window, turgid d
  bool ok = false;                              // status ok (k and d present)
};

// The rows of a training CSV (header index,p_MPa,E_MPa,h_nm,d0_um,rho_um,k_N_per_m,d_um,status,...);
// InputError naming the file and line of a malformed row.
std::vector<TrainingPoint> read_training_csv(const std::string& path);

// Whether a row is held out of the fit to test the correction: the shipped fit holds out fold 4
// (every fifth index: 4, 9, 14, ...); cross-validation holds out each fold in turn.
inline constexpr int correction_folds = 5;
inline bool held_out(const TrainingPoint& point, int fold = correction_folds - 1) {
  return point.index % correction_folds == fold;
}

// The rows the correction is fitted to and tested on: the physiological stiffness, k <= 10 N/m
// (fit_correction writes this limit and the next into the Correction it returns, as data).
// The training design's stiffest tubes (k up to 15 N/m, p up to 2.6 MPa) are no Arabidopsis
// tube's, and with them one held-out tube was 2.8 % off; corrected_inverse gives a tube above
// this stiffness outside_correction whatever its groups.
inline constexpr double correction_max_stiffness = 10.0;  // N/m
// The widest probe of the training tubes with a value, in bending lengths sqrt(h d0 / 2) (turgid
// h): 0.998. The design's wider probes all stayed below the force window's top, and a probe wider
// than the bending length is where the finite-element mesh refines its contact (src/fe/README.md,
// section 5): corrected_inverse gives such a tube outside_correction whatever its groups.
inline constexpr double correction_max_probe_over_bending_length = 1.0;
inline bool in_training_envelope(const TrainingPoint& point) { return point.ok && point.k <= correction_max_stiffness; }

// Least-squares fit of both polynomials to the fitting rows (in the envelope and not in the
// held-out fold) for the model options the data were made with. InputError when fewer rows than
// twice the terms remain.
Correction fit_correction(std::span<const TrainingPoint> points, const ShellFeOptions& options, double poisson_ratio,
                          int held_out_fold = correction_folds - 1);

// The C++ text of shipped_correction.inc for `correction` (every number to 17 digits).
std::string correction_source(const Correction& correction);

}  // namespace growthuq
