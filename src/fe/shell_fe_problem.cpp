#include "shell_fe_problem.hpp"

#include <cmath>
#include <vector>

#include "fe/far_field.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"

namespace growthuq::fe {
namespace {

// The study's driver's first increment of its indentation step (initialInc = 0.0005 of a step
// whose time is the probe's depth in um: gmunglani/Chip, module.py), m: the damping factor of its
// stabilisation is set from that increment.
constexpr double driver_first_increment = 0.5e-9;

}  // namespace

ForwardProblem make_problem(const ShellFeOptions& options, double plasmolysed_diameter, double probe_radius,
                            double poisson) {
  ForwardProblem problem;
  problem.geometry = options.geometry;
  problem.mesh_file = options.mesh_file;
  problem.poisson = poisson;
  problem.law = options.law;
  problem.probe_radius = probe_radius / plasmolysed_diameter;
  problem.tube_length = options.tube_length / plasmolysed_diameter;
  problem.probe_distance = options.probe_distance / plasmolysed_diameter;
  problem.substrate = options.substrate;
  problem.bending = options.bending;
  problem.half_model = options.half_model;
  problem.contact = options.contact;
  problem.mesh = options.mesh;
  problem.stabilisation = options.stabilisation;
  if (options.stabilisation.active()) problem.first_increment = driver_first_increment / plasmolysed_diameter;
  return problem;
}

void check_shell_poisson(double poisson, std::string_view location) {
  if (!(poisson >= 0.0 && poisson < 0.5)) {
    throw_bad_value(location, "nu", format_double(poisson), "a Poisson ratio in [0, 0.5) for the shell (0.2 for the published FEM)");
  }
}

double far_field_unstressed_thickness(ShellFeLaw law, double pressure_over_young, double turgid_thickness,
                                      double poisson) {
  const FarFieldTurgidInflation inflated =
      far_field_inflation_to_turgid_thickness(far_field_law(law), pressure_over_young, turgid_thickness, poisson);
  return inflated.inflation.burst ? 0.0 : inflated.h0_over_d0;
}

void curve_in_si(const ForwardResult& result, double d0, double young, IndentationCurve& curve) {
  const double force_scale = young * d0 * d0, energy_scale = force_scale * d0;
  const auto scaled = [](const std::vector<double>& from, double scale, std::vector<double>& to) {
    to.clear();
    for (double value : from) to.push_back(value * scale);
  };
  scaled(result.depth, d0, curve.depth);
  scaled(result.force, force_scale, curve.force);
  scaled(result.contact_radius, d0, curve.contact_radius);
  scaled(result.strain_energy, energy_scale, curve.strain_energy);
  scaled(result.pressure_energy, energy_scale, curve.pressure_energy);
  scaled(result.dissipated_energy, energy_scale, curve.dissipated_energy);
  curve.damping_factor = result.damping_factor;
  curve.damping_lowerings = result.damping_lowerings;
  curve.turgid_diameter = result.turgid_diameter * d0;
  curve.axial_stretch = result.axial_stretch;
  curve.thickness_stretch = result.thickness_stretch;
  curve.newton_iterations += result.newton_iterations;
  curve.indentation_load_steps += result.load_steps;
  curve.indentation_newton_iterations += result.indentation_iterations;
  curve.seconds_assembly += result.seconds_assembly;
  curve.seconds_factorisation += result.seconds_factorisation;
  curve.factorisations += result.factorisations;
  curve.seconds_contact += result.seconds_contact;
}

ShellFeField field_in_si(const ForwardResult& result, double d0, double young) {
  ShellFeField field;
  field.reference = result.mesh.positions * d0;
  field.deformed = result.deformed * d0;
  field.faces = result.mesh.faces;
  for (const MembraneStress& stress : result.face_stress) {
    field.sigma1.push_back(stress.sigma1 * young);
    field.sigma2.push_back(stress.sigma2 * young);
    field.von_mises.push_back(stress.von_mises * young);
    field.thickness_stretch.push_back(stress.thickness_stretch);
  }
  return field;
}

}  // namespace growthuq::fe
