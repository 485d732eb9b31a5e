// growthuq fit-line: a plant line's distributions fitted from its raw data (raw.ini), printed
// as the fit report a campaign shows and written as a line file for inspection or reuse.
#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "curve_fit_progress.hpp"
#include "growthuq/campaign/progress_mode.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/mechanics/instrument.hpp"
#include "growthuq/rawdata/raw_line_file.hpp"
#include "growthuq/rawdata/raw_line_fit.hpp"
#include "growthuq/relaxation/analysis.hpp"
#include "options.hpp"
#include "result_output.hpp"

namespace growthuq::cli {

int run_fit_line(const Arguments& arguments) {
  std::string raw_path, out;
  std::string rho_um, nu = "0.2";
  bool force = false, quiet = false;
  po::options_description described("options");
  described.add_options()
      ("raw", po::value(&raw_path)->required(), "raw line file (raw.ini)")
      ("out", po::value(&out), "write the fitted line file here (distributions/<line>.ini format); - writes it to "
                               "standard output (the report then goes to standard error)")
      ("rho-um", po::value(&rho_um), "probe radius (um) for relaxation curves whose tube sheet has no rho_um column")
      ("nu", po::value(&nu)->default_value(nu), "Poisson ratio of the wall (maps force to E_r(t))")
      ("force", po::bool_switch(&force), "overwrite --out")
      ("quiet", po::bool_switch(&quiet), "no progress on stderr (the relaxation curve fits, seconds)");
  po::positional_options_description positional;
  positional.add("raw", 1);
  po::variables_map values;
  if (!parse_arguments(arguments, "fit-line", "RAW.ini [--out line.ini] [options]",
                       "Fits every variable of a raw line file by maximum likelihood (lognormal, normal, gamma,\n"
                       "Weibull, or the families the file allows) and keeps the family of least AIC; tau and einf\n"
                       "come from fitting each relaxation curve (the step or ramp-aware fit of growthuq relax) and\n"
                       "then their distribution. Prints the fit report a campaign with raw = FILE prints (n, family,\n"
                       "median, IQR, KS D, AD A^2, the other families' AIC, failed curves with their reason).",
                       described, positional, values)) {
    return 0;
  }
  const std::string where = "growthuq fit-line";
  RawFitSettings settings;
  // --rho-um is optional: curves whose tube sheet has a rho_um column use their own.
  InstrumentEntries entries = instrument_flags(where, rho_um, nu, "");
  if (values.count("rho-um")) entries.probe_radius_um.text = rho_um;  // given, even if empty
  settings.instrument = parse_instrument(entries, ProbeRadius::optional);
  const Overwrite overwrite = force ? Overwrite::allow : Overwrite::refuse;
  if (!out.empty()) check_result_target(out, overwrite);
  // The curve fits are most of the time (about 5 s for the shipped example lines): not a silent
  // wait, as in a campaign's run and check (campaign/shared_raw_fits.cpp).
  const ProgressMode mode = choose_progress_mode(quiet);
  settings.fit_curves = [mode](const std::vector<RelaxationCurve>& curves, const RelaxationOptions& options) {
    return fit_curves_showing_progress(curves, options, mode);
  };
  const RawLineFit fit = fit_raw_line(read_raw_line_file(raw_path), settings);
  std::ostream& report = report_stream(out);
  report << format_raw_fit_report(fit);
  if (!out.empty()) {
    write_result(out, fitted_line_file_text(fit), overwrite);
    report << wrote(out) << "\n";
  }
  return 0;
}

}  // namespace growthuq::cli
