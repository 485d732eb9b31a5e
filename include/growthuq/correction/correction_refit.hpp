// Refitting fidelity corrected (src/correction/README.md, "Training data and fit") to
// finite-element training data: what `growthuq fit-correction` writes and prints. The training
// rows, the fit and its envelope stay private to the correction; this is their one entry point.
#pragma once

#include <cstddef>
#include <string>

namespace growthuq {

struct CorrectionRefit {
  std::string source;        // the correction as the C++ text the engine compiles in (shipped_correction.inc)
  std::string errors_table;  // CSV per training tube and window in the envelope: groups, finite-element, closed-form and corrected p and E
  // Three lines: the largest errors in p and E of the corrected and the closed form on the
  // fitted rows and on the held-out ones (index 4 mod 5), then the five-fold cross-validation's.
  std::string report;
  std::size_t fitted_rows = 0;
};

// Fits the correction for the finite-element defaults the training data were made with
// (ShellFeOptions{}, Instrument{}.poisson_ratio) to every tube of `training_csv` under every
// training window its force curve in `curves_csv` reaches. InputError naming the file (its line
// and column for a malformed row) when it cannot be read or fitted (too few usable rows,
// collinear groups).
CorrectionRefit refit_correction(const std::string& training_csv, const std::string& curves_csv);

}  // namespace growthuq
