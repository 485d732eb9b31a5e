// `growthuq synth`: a realistic raw data set of one plant line drawn from stated TRUE
// distributions (a line file) and a seed, in the files a lab would hand over
// (distributions/README.md, "Raw data"), so the raw-data path can be run and tested end to end
// against a known truth.
//
// As in the lab, each quantity is measured on its own tubes:
//   indentation.csv    tube,k_N_per_m,d_um      CFM stiffness and turgid diameter of indented tubes
//   plasmolysis.csv    tube,d0_um               diameter after 15 % mannitol, other tubes
//   tem_sections.csv   section,h_nm             wall thickness on TEM sections
//   growth.csv         tube,v_exp_um_per_s      growth rate from kymographs
//   relaxation_curves.csv, relaxation_meta.csv  force-relaxation curves of further tubes and the
//                                                tube sheet (delta, p, d, h, rho) kept with them
//   relaxation_truth.csv  each curve's true tau_slow, einf, fast phase and k0 (which no lab has;
//                         for checking fits, not named by raw.ini)
//   force_curves.csv, force_curves_sheet.csv, force_curves_truth.csv  on request
//                      (force_curve_repetitions > 0): raw force-indentation curves of every
//                      indented tube, that many per tube, drawn from the tube's true k (before
//                      rounding) by synthetic/indentation_curve.hpp, the contact uniform in
//                      [1.2, 1.8] um, the stage turning back at 6 uN; their sheet; and each
//                      curve's true k and contact (which no lab has). `growthuq curves` reads them,
//                      and raw.ini then takes k from them ([force_curves]) instead of indentation.csv.
//   raw.ini            the raw line file naming all of the above
// Values are independent draws from the true marginals (no correlation between quantities:
// they come from different tubes; a campaign imposes its rank correlation), rounded to the
// resolution of the instrument: k 0.01 N/m, d and d0 0.01 um, h 1 nm, v_exp 1e-4 um/s.
// A relaxation tube has its own k, d, d0 (drawn, redrawn until the thin-shell turgor exists and
// the drawn einf keeps E_inf above 1.5 x the membrane limit, see synthetic_line.cpp),
// its p from them (what `growthuq eval` gives the lab), h = the line's median thickness (TEM is
// destructive, so a lab writes the line's value), and tau_slow, einf drawn from the truth; its
// fast phase is illustrative (tau_fast lognormal, median 0.25 s, sigma 0.3, redrawn until
// tau_slow / tau_fast >= 4; fast share uniform in [0.2, 0.4]). relaxation_tube.hpp tells how the
// curve is simulated.
//
// Every random number derives from (seed, line name, table) through the keyed streams of
// sampling/random_stream.hpp, so a line's files depend only on the seed, its name and its truth.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "growthuq/core/units.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/mechanics/instrument.hpp"
#include "growthuq/relaxation/simulator.hpp"
#include "growthuq/synthetic/indentation_curve.hpp"

namespace growthuq {

struct CountRange {
  std::size_t low = 20;
  std::size_t high = 60;
};

struct SynthSettings {
  std::uint64_t seed = 1;
  CountRange tubes{20, 60};   // tubes per table and line, drawn uniformly in [low, high]
  CountRange curves{20, 40};  // relaxation curves per line
  // rho (0.5 um, written to the tube sheet) and nu; an ideal sensor (k_sys is not simulated).
  Instrument instrument{from_um(0.5), 0.2};
  // 100 um/s to 5 uN (a ramp of ~17 ms on a wild-type tube), a 30 s hold (tau_slow reaches
  // ~17 s at the wild type's 99th percentile; a fit needs the record to outlast it), exported
  // at 50 Hz: 1500 samples, which determine tau_slow to ~0.5-1 % at 0.2 % noise
  // (distributions/README.md).
  RampHoldProtocol protocol{100e-6, 5e-6, 30.0, 0.02};
  double force_noise = 0.002;  // standard deviation relative to the set point (10 nN at 5 uN)
  // Raw force curves per indented tube (0: none) and their instrument: speed, samples, sensor
  // stiffness, offset, drift and noise (the tube's k, the contact and the turning point are
  // drawn or derived).
  std::size_t force_curve_repetitions = 0;
  IndentationTruth force_curve{};
};

struct SynthFile {
  std::string name;  // file name inside the line's folder
  std::string text;
};

// The files of one line's folder, raw.ini first. Every file starts with '#' lines saying it is
// SYNTHETIC, naming the truth (`truth.path`) and `regenerate_command`. InputError when the truth
// lacks what a table needs (relaxation curves need k, d, d0, h, tau and einf) or when no valid
// tube can be drawn.
std::vector<SynthFile> synthesize_line(const LineDistributions& truth, const SynthSettings& settings,
                                       const std::string& regenerate_command);

}  // namespace growthuq
