// The finite-element indentation model of a pressurised pollen tube, in SI units: its options
// (one struct, validated in one place), one forward simulation (p, E, h, d0 -> force curve, k,
// turgid diameter) and its inverse (k, h, d, d0 -> p, E). src/fe/README.md states the model.
// Every function here is pure (no global state): safe to call from any thread or process.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "growthuq/evaluation/sample_status.hpp"
#include "growthuq/fe/shell_fe_vocabulary.hpp"
#include "growthuq/mechanics/instrument.hpp"
#include "growthuq/mechanics/thin_shell.hpp"

namespace growthuq {

// ShellFeLaw, ShellFeGeometry, ShellFeMesh: shell_fe_vocabulary.hpp.
// How the probe and the substrate are kept out of the wall (src/fe/README.md, section 4):
// exact frictionless contact by an active set (default: no penetration, no parameter), or the
// smooth penalty it replaced, kept for comparison.
enum class ShellFeContact { active_set, penalty };  // "active_set" | "penalty"

// The model's options: the same struct is a campaign's [shell_fe] section (keys as named in
// validate()'s messages). All lengths in m, forces in N.
struct ShellFeOptions {
  ShellFeLaw law = ShellFeLaw::hencky;
  ShellFeGeometry geometry = ShellFeGeometry::tube;
  std::string mesh_file;                // geometry = file: a closed triangulated surface, / d0 units
  double tube_length = 100e-6;          // L, hemispherical tip included, m
  double probe_distance = 10e-6;        // a, the probe's axis behind the apex, m
  bool substrate = true;                // rigid frictionless plane under the tube, opposite the probe
  bool bending = true;                  // Kirchhoff-Love bending on (off: membrane only)
  bool half_model = true;               // mirror plane through the tube axis and the probe axis
  ShellFeMesh mesh = ShellFeMesh::standard;
  ShellFeContact contact = ShellFeContact::active_set;
  // The study's driver's viscous stabilisation of the indentation (shell_fe_vocabulary.hpp): an
  // ablation of its choice, set by `growthuq indent` only, never by a campaign.
  ShellFeStabilisation stabilisation;
  std::array<double, 2> force_window{0.4e-6, 4e-6};  // k is fitted over F in this window, N
  // Inverse: refine the far-field inflation with finite-element inflation of the mesh when the
  // turgid diameters differ by more than this (relative); 0 always refines, inf never.
  double inflation_tolerance = 1e-4;

  // Throws InputError("<location>", "<key> = '<value>': expected <range>") for the first bad
  // option; keys: law, geometry, mesh_file, tube_length_um, probe_distance_um, mesh,
  // force_window_uN, stabilisation_fraction, stabilisation_ratio.
  void validate(std::string_view location) const;
};

std::string_view to_string(ShellFeLaw);       // "log", "stvk"
std::string_view to_string(ShellFeGeometry);  // "tube", "sphere", "file"
std::string_view to_string(ShellFeMesh);      // "coarse", "default", "fine", "finer"
std::string_view to_string(ShellFeContact);   // "active_set", "penalty"
std::string_view to_string(ShellFeStabilisationEnergy);  // "model", "step"
// The option's value from its text as typed (a campaign's [shell_fe] value or a command's flag,
// one parser and one message for both); InputError("<location>", "<key> = '<text>': expected
// ...") otherwise.
ShellFeLaw parse_shell_fe_law(std::string_view text, std::string_view location, std::string_view key);
ShellFeGeometry parse_shell_fe_geometry(std::string_view text, std::string_view location, std::string_view key);
ShellFeMesh parse_shell_fe_mesh(std::string_view text, std::string_view location, std::string_view key);
ShellFeContact parse_shell_fe_contact(std::string_view text, std::string_view location, std::string_view key);
ShellFeStabilisationEnergy parse_shell_fe_stabilisation_energy(std::string_view text, std::string_view location,
                                                               std::string_view key);
// The stabilisation's fraction >= 0 and ratio in [0, 1), the ratio 0 unless the fraction is above 0;
// InputError naming `fraction_key` or `ratio_key` (a flag's name or the option's) otherwise.
void validate_stabilisation(const ShellFeStabilisation& stabilisation, std::string_view location,
                            std::string_view fraction_key, std::string_view ratio_key);
bool parse_shell_fe_switch(std::string_view text, std::string_view location, std::string_view key);  // on | off
// um in [5, 1e6] -> m.
double parse_shell_fe_tube_length(std::string_view text, std::string_view location, std::string_view key);
// um in [0, tube_length) -> m; a reader that has no tube length yet passes 1 m and leaves the
// rest to ShellFeOptions::validate().
double parse_shell_fe_probe_distance(std::string_view text, std::string_view location, std::string_view key,
                                     double tube_length);
// "LOW,HIGH" in uN with 0 <= LOW < HIGH -> N.
std::array<double, 2> parse_shell_fe_force_window(std::string_view text, std::string_view location, std::string_view key);
// An option's length in um or force in uN, from SI, as typed, for messages and headers: 12
// significant digits drop the binary residue of the SI conversion (4e-6 * 1e6 = 3.9999999999999996).
std::string format_micro(double si);

// Why a simulation or an inverse has no value (never a NaN, never an exception from a batch): a
// SampleStatus (growthuq/evaluation/sample_status.hpp), the finite-element model's own among them.

// Which thickness IndentationInput::thickness is.
enum class ThicknessKind {
  turgid,      // measured h, the inflated wall (h0 follows through the law's thickness stretch)
  unstressed,  // h0, the plasmolysed wall
};

// One forward simulation's input, SI. Diameters are mid-surface diameters.
struct IndentationInput {
  double pressure = 0.0;              // turgor p, Pa
  double young = 0.0;                 // E, Pa
  double thickness = 0.0;             // m, see thickness_kind
  ThicknessKind thickness_kind = ThicknessKind::turgid;
  double plasmolysed_diameter = 0.0;  // d0 (unstressed), m
  double depth = 0.0;                 // deepest indentation, m; 0: until the force passes the window's top
  Instrument instrument;     // probe radius rho, Poisson ratio nu (k_sys: the k reported
                                      // is the tube's, as the sensor measures it in series)
};

// The deformed state for field output (filled when asked, see indent()). SI: m, Pa.
struct ShellFeField {
  Eigen::Matrix3Xd reference;              // unstressed vertex positions
  Eigen::Matrix3Xd deformed;               // final vertex positions
  std::vector<std::array<int, 3>> faces;   // counter-clockwise seen from outside
  std::vector<double> sigma1, sigma2;      // principal Cauchy membrane stresses per face, Pa
  std::vector<double> von_mises;           // of the plane-stress state per face, Pa
  std::vector<double> thickness_stretch;   // h/h0 per face
};

struct IndentationCurve {
  SampleStatus status = SampleStatus::ok;
  std::string message;                   // why, when status != ok
  std::vector<double> depth;             // indentation delta, m, from 0
  std::vector<double> force;             // probe force, whole tube, N
  std::vector<double> contact_radius;    // m
  // At each depth, J: strain energy (membrane + bending), the pressure's potential -p V, and the
  // energy the viscous stabilisation dissipated so far (0 without it). Whole tube.
  std::vector<double> strain_energy, pressure_energy, dissipated_energy;
  double damping_factor = 0.0;           // the stabilisation's c (solver units: / E d0, per unit of the
                                         // step's time, the whole indentation being 1), 0 off
  int damping_lowerings = 0;             // steps solved again with c lowered under the adaptive cap
  double stiffness = 0.0;                // k over the force window, N/m (tube alone)
  double measured_stiffness = 0.0;       // k in series with the sensor, N/m
  double turgid_diameter = 0.0;          // far from tip and ends (tube), the sphere's otherwise, m
  double axial_stretch = 0.0;            // tube only
  double thickness_stretch = 0.0;        // h/h0 in the far field
  double unstressed_thickness = 0.0;     // h0, m
  double window_contact_radius = 0.0;    // contact radius at the window's top, m
  int newton_iterations = 0;             // inflation and indentation
  int indentation_load_steps = 0;        // converged steps of the probe
  int indentation_newton_iterations = 0;
  double seconds = 0.0;                  // wall time of the whole call
  double seconds_assembly = 0.0, seconds_factorisation = 0.0, seconds_contact = 0.0;
  int factorisations = 0;                // sparse Cholesky factorisations, shifted retries included
  ShellFeField field;                    // empty unless asked for
};

// Progress of indent(): after each converged indentation step, its depth and the deepest the
// curve may go (m): the depth asked for, or fe::deepest_automatic_depth (0.6 d0) for a curve that
// stops at the window's top.
using IndentationProgress = std::function<void(double depth, double max_depth)>;

// One forward simulation: inflate to p, indent to `input.depth` (or, when 0, until the force
// passes the window's top, at most 0.6 d0: one curve, its steps sized from the closed form's
// estimate of the depth and continued past it), fit k.
// `keep_field` fills `field` with the final state; `progress`, if given, follows the
// indentation. Throws InputError only for invalid input or options and an unreadable mesh
// file; a numerical failure is a status.
IndentationCurve indent(const IndentationInput& input, const ShellFeOptions& options, bool keep_field = false,
                        const IndentationProgress& progress = {});

// The inverse's input: one measured tube, SI.
struct ShellFeMeasurement {
  double stiffness = 0.0;             // measured k (probe and tube in series), N/m
  double thickness = 0.0;             // turgid h, m
  double diameter = 0.0;              // turgid d, m
  double plasmolysed_diameter = 0.0;  // d0, m
};

struct ShellFeInverse {
  SampleStatus status = SampleStatus::ok;
  std::string message;
  double pressure = 0.0;              // p, Pa
  double young = 0.0;                 // E, Pa
  double pressure_over_young = 0.0;   // p/E
  double unstressed_thickness = 0.0;  // h0, m
  double far_field_pressure_over_young = 0.0;  // p/E of the far-field inflation alone
  int inflation_solves = 0;           // finite-element inflations of the refinement
  double far_field_diameter_error = 0.0;  // the mesh's inflated d at the far field's p/E over the
                                          // measured d, minus 1 (what the refinement corrected)
  double closed_form_young = 0.0;     // the thin-shell inverse's E (the root's first estimate), Pa
  double fitted_stiffness = 0.0;      // k of the model at (p, E) over the window, N/m
  int newton_iterations = 0;
  double seconds = 0.0;
};

// (k, h, d, d0; rho, nu, k_sys) -> (p, E): p/E and h0 from the turgid diameter and thickness,
// then E from one dimensionless force curve (forces scale as E d0^2 at fixed p/E). Never throws
// for a measurement outside the model (a status); throws InputError for invalid options.
ShellFeInverse invert_indentation(const ShellFeMeasurement& measurement, const Instrument& instrument,
                                  const ShellFeOptions& options);

}  // namespace growthuq
