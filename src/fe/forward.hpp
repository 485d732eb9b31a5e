// The forward indentation protocol of the shell model: inflate the wall from its plasmolysed
// (unstressed) state to p/E, measure the turgid state, place the substrate under it, then press
// the rigid probe in -x, displacement-controlled, recording force against depth. Dimensionless:
// lengths / d0, stresses / E, forces / (E d0^2).
#pragma once

#include <Eigen/Core>

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "fe/material_law.hpp"
#include "fe/membrane.hpp"
#include "fe/mesh.hpp"
#include "fe/shell_objective.hpp"
#include "growthuq/evaluation/sample_status.hpp"

namespace growthuq::fe {

struct ForwardProblem {            // all dimensionless
  ShellFeGeometry geometry = ShellFeGeometry::tube;
  std::string mesh_file;           // ShellFeGeometry::file only (closed triangulated surface)
  double pressure = 0.0;           // p/E
  double thickness = 0.0;          // h0/d0
  double poisson = 0.2;
  ShellFeLaw law = ShellFeLaw::hencky;
  double probe_radius = 0.0;       // rho/d0
  double tube_length = 0.0;        // L/d0 (tube only)
  double probe_distance = 0.0;     // a/d0 behind the apex (tube only)
  double max_depth = 0.0;          // deepest indentation, / d0
  // The depth the load steps are sized from (/ d0; 0: max_depth): the first a 48th of it, none
  // larger than an eighth of it or of the depth reached. A curve that stops at a force
  // (`long_enough`) sizes its steps from its first estimate of the depth and runs on past it.
  double step_depth = 0.0;
  // Called after each converged indentation step with the curve so far (depth / d0, force
  // / (E d0^2), whole tube); true ends the curve there (status ok), short of max_depth, which
  // then only bounds it. Unset: the curve runs to max_depth.
  std::function<bool(std::span<const double>, std::span<const double>)> long_enough;
  // Called after each converged indentation step with its depth (/ d0), for a progress display.
  std::function<void(double)> on_depth;
  bool substrate = true;
  bool bending = true;
  bool half_model = true;
  ShellFeMesh mesh = ShellFeMesh::standard;
  ContactMethod contact = ContactMethod::active_set;
  // The study's driver's viscous stabilisation of the indentation steps (viscous_stabilisation.hpp;
  // off by default), and the depth of a stabilised indentation's first increment, from which its
  // damping factor is set (/ d0; 0: the load stepping's own, 1/48 of the curve).
  ShellFeStabilisation stabilisation;
  double first_increment = 0.0;
};

// The deepest indentation (/ d0) that simulate_forward accepts, and that indent() and the inverse
// ask for when they choose the depth themselves. A soft tube (pme48's) can need more than 0.45 d0
// to reach the window's top; the turgid tube is 1.1-1.3 d0 wide, so at 0.6 d0 probe and
// substrate still leave half a diameter between them (src/fe/README.md, "Deep curves").
inline constexpr double deepest_automatic_depth = 0.6;

// A curve whose load steps stall with its contact radius at or beyond this fraction of the probe
// radius ends probe_engulfed rather than not_converged: the wall has wrapped the probe down to
// its equator, where the stalls of the soft, thin walls under small probes happen (src/fe/README.md,
// "Statuses and deep curves", has the measurements the fraction comes from).
inline constexpr double engulfed_contact_fraction = 0.95;

struct ForwardResult {
  SampleStatus status = SampleStatus::ok;
  std::string message;             // why, when status != ok
  std::vector<double> depth;       // indentation delta / d0, starting at 0
  std::vector<double> force;       // F / (E d0^2), whole tube (half model doubled)
  std::vector<double> contact_radius;  // / d0
  // At each depth, whole tube, / (E d0^3): the strain energy (membrane + bending), the pressure's
  // potential -p V, and the energy the viscous stabilisation has dissipated so far (0 without it).
  std::vector<double> strain_energy, pressure_energy, dissipated_energy;
  double damping_factor = 0.0;     // the stabilisation's c at the end (solver units), 0 off
  int damping_lowerings = 0;       // steps solved again with c lowered under the adaptive cap
  double turgid_diameter = 0.0;    // / d0, far from tip and ends (tube), or sphere diameter
  double axial_stretch = 0.0;      // tube only
  double thickness_stretch = 0.0;  // h/h0 there
  double max_penetration = 0.0;    // deepest node in the probe or substrate over the path, / d0
  int load_steps = 0;              // converged indentation steps
  int indentation_iterations = 0;  // Newton iterations of the indentation alone
  int newton_iterations = 0;
  double seconds_assembly = 0, seconds_factorisation = 0, seconds_contact = 0;
  int factorisations = 0;          // sparse Cholesky factorisations (shifted retries included)
  // Final state for field output: mesh, deformed positions, per-face stresses.
  TriangleMesh mesh;
  Eigen::Matrix3Xd deformed;
  std::vector<MembraneStress> face_stress;
};

// Inflate to `pressure`, then indent to `max_depth` (or until `long_enough`). A pure function of its input: no global
// state, safe to call concurrently from several threads or processes. Never throws for a
// numerical failure (status instead); throws InputError only for an unreadable mesh file.
//
// The supports, the symmetry plane, where the probe presses and the part of the wall the turgid
// state is read from belong to the geometry (tube_geometry.cpp, sphere_geometry.cpp,
// file_geometry.cpp; the interface in geometry.hpp).
ForwardResult simulate_forward(const ForwardProblem&);
// Inflation alone (for the inverse's 1-D root on the turgid diameter, and validation).
ForwardResult simulate_inflation(const ForwardProblem&);

}  // namespace growthuq::fe
