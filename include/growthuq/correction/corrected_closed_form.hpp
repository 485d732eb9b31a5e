// Fidelity `corrected`: the thin shell's closed-form inverse (hoop and Arnoldi relations,
// mechanics/thin_shell.hpp) times a correction fitted to the finite-element inverse
// (fe/indentation.hpp) over the Arabidopsis-like envelope, at closed-form speed.
// src/correction/README.md states the model, its training data and its error.
//
// The finite-element model depends on p/E, h0/d0, rho/d0, a/d0 (and L/d0, nu, the force window
// over E d0^2); a measured tube and its force window give six dimensionless groups from which all
// of these follow:
//   s = d/d0 - 1 (hoop strain), h/d0 (turgid thickness), rho/d0, w = F_top / (k d0), a/d0,
//   r = F_low / F_top,
// w being the depth at which the tube's k would reach the force window's top, over d0, a the
// probe's distance behind the apex (fixed by the options, so a/d0 carries d0 itself), and r the
// window's bottom over its top (0.1 for the default 0.4-4 uN; a window set relative to the
// curve's largest force, such as 10-90 %, gives 1/9 whatever the force).
// The correction is two polynomials in the logarithms of these groups (each scaled onto [-1, 1]
// over the training data), a full quadratic plus the cubic terms that contain s, and for the
// modulus a kriging interpolant of what its polynomial leaves (residual_kriging.hpp):
//   E       = E_closed_form * exp(c_E(z) + g_E(z))
//   p / E   = (p/E)_far_field * exp(c_pE(z))
// where (p/E)_far_field is the model's own far-field inflation inverted exactly (the log law:
// src/fe/README.md, section 2) and c_pE is the small correction of the meshed tube's inflation.
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "growthuq/correction/residual_kriging.hpp"
#include "growthuq/evaluation/evaluator.hpp"
#include "growthuq/fe/indentation.hpp"
#include "growthuq/mechanics/instrument.hpp"
#include "growthuq/mechanics/probe_radius_column.hpp"
#include "growthuq/mechanics/thin_shell.hpp"

namespace growthuq {

inline constexpr std::size_t correction_groups = 6;  // s, h/d0, rho/d0, w, a/d0, r
// 1, z_i, z_i z_j (i <= j), and s z_i z_j (i <= j): 1 + 6 + 21 + 21.
inline constexpr std::size_t correction_terms = 49;

struct Correction {
  // What it was fitted for: a campaign's [shell_fe] options and nu must match (fitted_for()).
  ShellFeLaw law = ShellFeLaw::hencky;
  bool substrate = true;
  bool bending = true;
  double tube_length = 100e-6;                        // m
  double probe_distance = 10e-6;                      // m
  double poisson_ratio = 0.2;
  // The training data's range of ln(group), per group: outside it, no value (the force window
  // among them, through w and r).
  std::array<double, correction_groups> low{}, high{};
  // Beyond the groups' ranges, the tubes the fit left out (correction_training.hpp says why):
  double max_stiffness = 20.0;                  // N/m, the tube's k after the sensor
  double max_probe_over_bending_length = 1.0;   // rho / sqrt(h d0 / 2), turgid h: the widest fitted
  std::array<double, correction_terms> modulus{};         // c_E
  std::array<double, correction_terms> pressure_ratio{};  // c_pE
  ResidualKriging modulus_residual;                       // g_E, over the scaled groups z
  int training_points = 0;
};

// The correction compiled into the engine (src/correction/shipped_correction.inc, written by
// `growthuq fit-correction` from src/correction/training.csv).
const Correction& shipped_correction();

// What a refusal calls an option: a campaign's key ([shell_fe] law, ..., [instrument]
// poisson_ratio) or the command-line flag a command reads it from (--law, ..., --nu).
enum class OptionNames { campaign_keys, command_flags };

// InputError naming `location` and the first option that differs from what `correction` was
// fitted for (the geometry, law, substrate, bending, tube length, probe distance, nu; a force
// window whose bottom over top lies outside the fitted windows'), by its key or by its flag.
void require_fitted_for(const Correction& correction, const ShellFeOptions& options, const Instrument& instrument,
                        std::string_view location, OptionNames names = OptionNames::campaign_keys);

// ln of the six groups of a measured tube and its force window (low, top; N); k is the tube's own
// stiffness over that window (after the sensor).
std::array<double, correction_groups> correction_log_groups(double k_tube, const TubeDiameters& diameters, double h,
                                                            double probe_radius, const std::array<double, 2>& force_window,
                                                            const Correction& correction);

struct CorrectedInverse {
  double p = 0.0, E = 0.0;              // Pa
  double closed_form_p = 0.0, closed_form_E = 0.0;
  SampleStatus status = SampleStatus::ok;  // the closed form's, no_inflation_state, outside_correction
};

// (k_measured over force_window, d, d0, h; rho, nu, k_sys) -> (p, E) at fidelity corrected.
CorrectedInverse corrected_inverse(double k_measured, const TubeDiameters& diameters, double h,
                                   const Instrument& instrument, const std::array<double, 2>& force_window,
                                   const Correction& correction) noexcept;

// Fidelity corrected as a campaign's evaluator: reads k, d, d0, h; writes p, E.
class CorrectedTurgorModulus final : public Evaluator {
 public:
  // InputError naming `location` when the instrument is invalid or the options are not those
  // the correction was fitted for (naming the option as `names` says).
  CorrectedTurgorModulus(const Instrument& instrument, const ShellFeOptions& options, std::string_view location,
                         OptionNames names = OptionNames::campaign_keys,
                         const Correction& correction = shipped_correction());
  std::string_view name() const override { return "corrected_turgor_modulus"; }
  std::vector<std::string> reads() const override { return reads_with_probe_radius({"k", "d", "d0", "h"}, instrument_); }
  std::vector<std::string> writes() const override { return {"p", "E"}; }
  void evaluate(SampleBlock& block) const override;

 private:
  Instrument instrument_;
  std::array<double, 2> force_window_;  // N, the campaign's [shell_fe] force_window_uN
  Correction correction_;
};

}  // namespace growthuq
