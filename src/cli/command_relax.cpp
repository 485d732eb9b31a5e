// growthuq relax: generalized Maxwell fits of force-relaxation curves, one row per curve in a
// CSV, a summary on stdout and, on request, distribution entries for tau (lognormal) and e_inf
// (beta, bounded like the fraction) in the line-file format (Eqs. (R1)-(R7),
// src/relaxation/README.md).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>

#include "commands.hpp"
#include "curve_fit_progress.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/distributions/fit.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/mechanics/instrument.hpp"
#include "growthuq/relaxation/analysis.hpp"
#include "growthuq/relaxation/curves.hpp"
#include "options.hpp"
#include "result_output.hpp"

namespace growthuq::cli {
namespace {

struct RelaxOptions {
  std::string curves;
  std::string meta;
  std::string out;
  std::string distributions_out;
  Instrument instrument;  // no probe radius unless --rho-um: the tube sheet's rho_um column then
  RelaxationOptions analysis;
  Overwrite overwrite = Overwrite::refuse;
  bool quiet = false;
};

RelaxOptions parse(const Arguments& arguments, bool& run) {
  RelaxOptions options;
  po::options_description described("options");
  std::string rho_um, nu = "0.2";
  described.add_options()
      ("curves", po::value(&options.curves)->required(), "force curves: CSV curve,t_s,F_uN")
      ("meta", po::value(&options.meta), "per-curve metadata: CSV curve,delta_um,p_MPa,d_um,h_nm[,rho_um] "
                                         "(default: the same columns in the curves file)")
      ("out", po::value(&options.out)->required(), "fits, one row per curve (CSV); - writes them to standard output "
                                                   "(the report then goes to standard error)")
      ("terms", po::value(&options.analysis.terms)->default_value(2), "exponentials in the Prony series: 1, 2 or 3")
      ("ramp-aware", po::bool_switch(&options.analysis.ramp_aware),
       "fit the simulated ramp and hold instead of a step at the force maximum")
      ("drop-ramp-multiple", po::value(&options.analysis.drop_ramp_multiple)->default_value(0.0),
       "step fit: leave out hold samples with t < this x ramp time")
      ("rho-um", po::value(&rho_um), "probe radius (um) of every curve; a rho_um column, if any, must agree")
      ("nu", po::value(&nu)->default_value(nu), "Poisson ratio of the wall")
      ("fit-distributions", po::value(&options.distributions_out),
       "write [tau] (lognormal) and [einf] (beta) line-file sections fitted to the ok curves (- for standard output)")
      ("force", "overwrite existing outputs")
      ("quiet", po::bool_switch(&options.quiet), "no progress on stderr (the curve fits, seconds)");
  po::positional_options_description positional;
  positional.add("curves", 1);
  po::variables_map values;
  run = parse_arguments(arguments, "relax", "CURVES.csv --out FITS.csv [options]",
                        "Fits a generalized Maxwell (Prony) series to every force-relaxation curve and derives\n"
                        "tau_slow, E_inf/E_r(0), E0 = (1 - E_inf/E_r(0)) E_r(0) and the wall viscosity\n"
                        "eta = tau_slow E0. The fits' progress goes to stderr (--quiet: none).",
                        described, positional, values);
  if (!run) return options;
  const int terms = options.analysis.terms;
  if (terms < 1 || terms > 3) throw_bad_value("growthuq relax", "--terms", std::to_string(terms), "1, 2 or 3");
  InstrumentEntries entries = instrument_flags("growthuq relax", rho_um, nu, "");
  if (values.count("rho-um")) entries.probe_radius_um.text = rho_um;  // given, even if empty
  options.instrument = parse_instrument(entries, ProbeRadius::optional);
  options.analysis.poisson_ratio = options.instrument.poisson_ratio;
  const double drop = options.analysis.drop_ramp_multiple;
  if (!(drop >= 0.0) || !std::isfinite(drop)) {
    throw_bad_value("growthuq relax", "--drop-ramp-multiple", format_double(drop), "a number >= 0");
  }
  if (options.analysis.ramp_aware && drop > 0.0) {
    throw InputError("growthuq relax", "--drop-ramp-multiple applies to the step fit only, not with --ramp-aware");
  }
  if (values.count("force")) options.overwrite = Overwrite::allow;
  return options;
}

std::string number_or_blank(bool present, double value) {
  return present && std::isfinite(value) ? format_double(value) : std::string();
}

std::string fits_csv(const std::vector<CurveFit>& fits, int terms) {
  CsvWriter writer({"curve", "status", "reason", "terms", "tau_fast_s", "tau_mid_s", "tau_slow_s", "tau_slow_low_s",
                    "tau_slow_high_s", "einf_frac", "E0_MPa", "eta_MPa_s", "Er0_MPa", "tau_slow_se_pct", "rms", "aic",
                    "ramp_time_s", "points"});
  for (const CurveFit& fit : fits) {
    const bool fitted = fit.ok && !fit.tau.empty();
    writer.add_row({fit.curve, std::string(fit_status(fit)), fit.reason, std::to_string(terms),
                    number_or_blank(fitted && terms > 1, fit.tau.empty() ? 0.0 : fit.tau.front()),
                    number_or_blank(fitted && terms == 3, fit.tau.size() == 3 ? fit.tau[1] : 0.0),
                    number_or_blank(fitted, fit.tau.empty() ? 0.0 : fit.tau.back()),
                    number_or_blank(fitted, fit.tau_slow_low), number_or_blank(fitted, fit.tau_slow_high),
                    number_or_blank(fitted, fit.einf), number_or_blank(fitted, to_MPa(fit.relaxing_modulus)),
                    number_or_blank(fitted, to_MPa_s(fit.viscosity)), number_or_blank(fitted, to_MPa(fit.modulus0)),
                    number_or_blank(fitted, to_pct(fit.tau_slow_relative_se)),
                    number_or_blank(fit.points > 0, fit.rms), number_or_blank(fit.points > 0, fit.aic),
                    format_double(fit.ramp_time), std::to_string(fit.points)});
  }
  return writer.text();
}

// Lognormal maximum likelihood: mu = mean ln x, sigma = sqrt(mean (ln x - mu)^2) (the 1/N
// estimator is the maximum-likelihood one).
std::string lognormal_section(std::string_view name, std::string_view unit, const std::vector<double>& values,
                              std::string_view source) {
  double mu = 0.0;
  for (double v : values) mu += std::log(v);
  mu /= static_cast<double>(values.size());
  double variance = 0.0;
  for (double v : values) variance += (std::log(v) - mu) * (std::log(v) - mu);
  const double sigma = std::sqrt(variance / static_cast<double>(values.size()));
  std::ostringstream out;
  out << "[" << name << "]\nlaw = lognormal\nmu = " << format_double(mu) << "\nsigma = " << format_double(sigma)
      << "\nunit = " << unit << "\nsource = " << source << "\n";
  return out.str();
}

// einf is a fraction: its section is the beta ML fit (Eq. (D5), src/distributions/README.md), a law
// that never draws above 1; a lognormal's upper tail reaches past 1, and line files refuse it.
std::string beta_section(const std::vector<double>& einf, const std::string& source) {
  try {
    const FitResult fit = fit_distribution(FitFamily::beta, einf);
    return format_line_variable(
        LineVariable{"einf", &find_unit("frac", "growthuq relax", "unit"), fit.distribution, source, "", 0});
  } catch (const InputError& error) {
    throw InputError("--fit-distributions", "einf of the ok curves: " + error.problem());
  }
}

std::string distributions_text(const std::vector<CurveFit>& fits, const std::string& curves_path) {
  std::vector<double> tau, einf;
  for (const CurveFit& fit : fits) {
    if (!fit.ok) continue;  // extrapolated fits are fits (ok): their tau and einf count
    tau.push_back(fit.tau.back());
    einf.push_back(fit.einf);
  }
  if (tau.size() < 2) {
    throw InputError("--fit-distributions", std::to_string(tau.size()) +
                                                " curve(s) with status ok: expected at least 2 to fit a lognormal");
  }
  const std::string source = "fitted from " + curves_path + ", " + std::to_string(tau.size()) + " curves";
  return "# Written by growthuq relax: maximum-likelihood fits to the per-curve slow relaxation time\n"
         "# (lognormal) and rescaled equilibrium modulus E_inf/E_r(0) (beta) of the curves with status ok.\n" +
         lognormal_section("tau", "s", tau, source) + "\n" + beta_section(einf, source);
}

void print_summary(const std::vector<CurveFit>& fits, const RelaxOptions& options, std::ostream& report) {
  report << "growthuq relax: " << fits.size() << " curve(s) from " << options.curves << ", "
            << options.analysis.terms << "-term " << (options.analysis.ramp_aware ? "ramp-aware" : "step") << " fit\n";
  std::size_t ok = 0, extrapolated = 0;
  for (const CurveFit& fit : fits) {
    report << "  " << fit.curve << ": ";
    if (fit.ok) {
      ++(fit.extrapolated ? extrapolated : ok);
      report << "tau_slow " << format_double(std::round(fit.tau.back() * 1e3) / 1e3) << " s";
      if (std::isfinite(fit.tau_slow_low)) {
        report << " [" << format_double(std::round(fit.tau_slow_low * 1e2) / 1e2) << ", "
               << format_double(std::round(fit.tau_slow_high * 1e2) / 1e2) << "]";
      }
      if (fit.extrapolated) report << " (extrapolated: beyond the hold)";
      report << ", E_inf/E_r(0) "
                << format_double(std::round(fit.einf * 1e3) / 1e3) << ", eta "
                << format_double(std::round(to_MPa_s(fit.viscosity) * 10) / 10) << " MPa s\n";
    } else {
      report << "fit_failed: " << fit.reason << "\n";
    }
  }
  report << ok << " ok, " << extrapolated << " extrapolated (tau_slow beyond the hold), " << fits.size() - ok - extrapolated
         << " failed; fits in " << (is_standard_output(options.out) ? "standard output" : options.out) << "\n";
}

}  // namespace

int run_relax(const Arguments& arguments) {
  bool run = true;
  const RelaxOptions options = parse(arguments, run);
  if (!run) return 0;
  if (is_standard_output(options.out) && is_standard_output(options.distributions_out)) {
    throw InputError("growthuq relax", "--out and --fit-distributions are both -: standard output takes one result");
  }
  check_result_target(options.out, options.overwrite);
  if (!options.distributions_out.empty()) check_result_target(options.distributions_out, options.overwrite);

  const std::vector<RelaxationCurve> curves = read_relaxation_curves(options.curves, options.meta, given_probe_radius_m(options.instrument));
  const std::vector<CurveFit> fits =
      fit_curves_showing_progress(curves, options.analysis, choose_progress_mode(options.quiet));

  const std::string distributions =
      options.distributions_out.empty() ? std::string() : distributions_text(fits, options.curves);
  // fits.csv and the fitted distributions commit together or not at all.
  std::vector<FileContent> results{{options.out, fits_csv(fits, options.analysis.terms)}};
  if (!options.distributions_out.empty()) results.push_back({options.distributions_out, distributions});
  write_results_together(results, options.overwrite);
  const bool to_stdout = is_standard_output(options.out) || is_standard_output(options.distributions_out);
  print_summary(fits, options, to_stdout ? std::cerr : std::cout);
  return 0;
}

}  // namespace growthuq::cli
