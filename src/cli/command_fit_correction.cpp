// growthuq fit-correction: fits fidelity corrected (src/correction/README.md) to the
// finite-element training data and writes the C++ text the engine compiles in; prints the
// errors in p and E of the corrected and the plain closed form against the finite-element
// values, on the fitted rows and on the held-out ones (every fifth index), and the five-fold
// cross-validation's.
#include <iostream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/correction/correction_refit.hpp"
#include "growthuq/io/output_file.hpp"
#include "options.hpp"

namespace growthuq::cli {
namespace {

constexpr std::string_view command = "growthuq fit-correction";
constexpr std::string_view usage = "[--training FILE] [--curves FILE] [--out FILE.inc] [--errors FILE.csv] [--force]";

// generate-training's packed curves of TABLE.csv: TABLE_curves.csv.
std::string curves_beside(const std::string& training) {
  const std::string_view suffix = ".csv";
  const bool csv = training.size() >= suffix.size() && training.ends_with(suffix);
  return (csv ? training.substr(0, training.size() - suffix.size()) : training) + "_curves.csv";
}

}  // namespace

int run_fit_correction(const Arguments& arguments) {
  std::string training = "src/correction/training.csv", curves, out = "src/correction/shipped_correction.inc", errors;
  bool force = false;
  po::options_description described("options");
  described.add_options()
      ("training", po::value(&training), "finite-element training data (default src/correction/training.csv, written by "
                                         "tools/fe-correction/generate-training)")
      ("curves", po::value(&curves), "their force curves: index,delta_um,F_uN per point (default: beside the "
                                     "training file, its name with _curves.csv, as the same tool writes them)")
      ("out", po::value(&out), "the correction as C++ text (default src/correction/shipped_correction.inc; rebuild "
                               "the engine to use it)")
      ("errors", po::value(&errors), "also write per training row the finite-element, closed-form and corrected p and "
                                     "E (CSV, for tools/fe-correction/plot-errors)")
      ("force", po::bool_switch(&force), "overwrite --out and --errors if they exist");
  po::variables_map values;
  if (!parse_arguments(arguments, "fit-correction", usage,
                       "Fits fidelity corrected: two polynomials (a quadratic and the cubic terms in the strain) in\n"
                       "the logarithms of the measured groups d/d0 - 1, h/d0, rho/d0, F_top/(k d0), a/d0 (a the\n"
                       "probe's distance behind the apex) and F_low/F_top (the force window), correcting the closed\n"
                       "form's E and the far field's p/E to the finite-element inverse, and a kriging interpolant of\n"
                       "the E polynomial's residual (hyperparameters by maximum likelihood; src/correction/README.md).\n"
                       "Each training tube counts once per force window its curve reaches (tops 2, 3 and 4 uN, bottoms\n"
                       "0.05-0.5 of the top). Fits the tubes with k <= 20 N/m whose index is not a multiple of 5 plus\n"
                       "4, reports the largest errors in p and E on them and on the held-out tubes, next to the plain\n"
                       "closed form's, and the five-fold cross-validation's, and writes the correction for the model\n"
                       "options the data were made with (the finite-element defaults: law log, substrate on, bending\n"
                       "on, L = 100 um, probe 10 um behind the apex, nu = 0.2).",
                       described, {}, values)) {
    return 0;
  }
  if (curves.empty()) curves = curves_beside(training);
  const Overwrite overwrite = force ? Overwrite::allow : Overwrite::refuse;
  check_can_write(out, overwrite);
  if (!errors.empty()) check_can_write(errors, overwrite);
  const CorrectionRefit refit = refit_correction(training, curves);
  std::cout << refit.report;
  // The coefficients and their error table commit together or not at all.
  std::vector<FileContent> results;
  if (!errors.empty()) results.push_back({errors, refit.errors_table});
  results.push_back({out, refit.source});
  write_files_together(results, overwrite);
  std::cout << "wrote " << out << " (" << refit.fitted_rows << " fitted rows)\n";
  if (!errors.empty()) std::cout << "wrote " << errors << "\n";
  return 0;
}

}  // namespace growthuq::cli
