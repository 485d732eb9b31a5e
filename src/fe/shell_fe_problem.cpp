#include "shell_fe_problem.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <memory>

#include "core/gsl_errors.hpp"
#include "fe/far_field.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"

namespace growthuq::fe {

ForwardProblem make_problem(const ShellFeOptions& options, double plasmolysed_diameter, double probe_radius,
                            double poisson) {
  ForwardProblem problem;
  switch (options.geometry) {
    case ShellFeGeometry::tube: problem.geometry = Geometry::tube; break;
    case ShellFeGeometry::sphere: problem.geometry = Geometry::sphere; break;
    case ShellFeGeometry::file: problem.geometry = Geometry::file; break;
  }
  problem.mesh_file = options.mesh_file;
  problem.poisson = poisson;
  problem.law = to_material_law(options.law);
  problem.probe_radius = probe_radius / plasmolysed_diameter;
  problem.tube_length = options.tube_length / plasmolysed_diameter;
  problem.probe_distance = options.probe_distance / plasmolysed_diameter;
  problem.substrate = options.substrate;
  problem.bending = options.bending;
  problem.half_model = options.half_model;
  switch (options.mesh) {
    case ShellFeMesh::coarse: problem.mesh = MeshLevel::coarse; break;
    case ShellFeMesh::standard: problem.mesh = MeshLevel::standard; break;
    case ShellFeMesh::fine: problem.mesh = MeshLevel::fine; break;
  }
  return problem;
}

void check_shell_poisson(double poisson, std::string_view location) {
  if (!(poisson >= 0.0 && poisson < 0.5)) {
    throw_bad_value(location, "nu", format_double(poisson), "a Poisson ratio in [0, 0.5) for the shell (0.2 for the published FEM)");
  }
}

ShellFeStatus to_shell_fe_status(FeStatus status) {
  switch (status) {
    case FeStatus::ok: return ShellFeStatus::ok;
    case FeStatus::not_converged: return ShellFeStatus::not_converged;
    case FeStatus::burst: return ShellFeStatus::burst;
    case FeStatus::contact_lost: return ShellFeStatus::contact_lost;
    case FeStatus::probe_beyond_mesh: return ShellFeStatus::probe_beyond_mesh;
    case FeStatus::invalid_input: return ShellFeStatus::invalid_input;
  }
  return ShellFeStatus::not_converged;
}

MaterialLaw to_material_law(ShellFeLaw law) {
  return law == ShellFeLaw::hencky ? MaterialLaw::hencky : MaterialLaw::saint_venant_kirchhoff;
}

FarFieldLaw to_far_field_law(ShellFeLaw law) {
  return law == ShellFeLaw::hencky ? FarFieldLaw::hencky : FarFieldLaw::saint_venant_kirchhoff;
}

namespace {

struct HoopProblem {
  FarFieldLaw law;
  double thickness, poisson, target;
};

// Hoop stretch minus its target at P = exp(log_p) (p/E = P h0/d0); a burst state counts as
// "too far" (+1), so the bracket's upper end may be a burst.
double hoop_mismatch(double log_p, void* parameters) {
  const auto& problem = *static_cast<const HoopProblem*>(parameters);
  const double p = std::exp(log_p) * problem.thickness;
  const FarFieldInflation state = far_field_inflation(problem.law, p, problem.thickness, problem.poisson);
  if (state.burst || !std::isfinite(state.hoop_stretch)) return 1.0;
  return state.hoop_stretch - problem.target;
}

// The P whose hoop stretch is `target` at h0/d0 = `thickness`; NaN when none below burst.
double hoop_root(FarFieldLaw law, double target, double thickness, double poisson) {
  HoopProblem problem{law, thickness, poisson, target};
  // ln(lambda) ~ P / 2 for a small stretch (hoop tension P/2 in E h0 units): start there and
  // bracket by factors of 2 (down for a mismatch above 0, up below).
  double lower = std::log(std::max(2.0 * std::log(target), 1e-300));
  double f_lower = hoop_mismatch(lower, &problem);
  double upper = lower, f_upper = f_lower;
  for (int i = 0; f_lower > 0 && i < 2000; ++i) {
    upper = lower;
    f_upper = f_lower;
    lower -= 0.6931471805599453;
    f_lower = hoop_mismatch(lower, &problem);
  }
  for (int i = 0; f_upper < 0 && i < 200; ++i) {
    lower = upper;
    f_lower = f_upper;
    upper += 0.6931471805599453;
    f_upper = hoop_mismatch(upper, &problem);
  }
  if (!(f_lower <= 0 && f_upper >= 0)) return std::nan("");
  if (f_lower == 0) return std::exp(lower);
  detail::gsl_errors_return();
  gsl_function function{&hoop_mismatch, &problem};
  const std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  gsl_root_fsolver_set(solver.get(), &function, lower, upper);
  int status = GSL_CONTINUE;
  for (int i = 0; status == GSL_CONTINUE && i < 200; ++i) {
    if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS) return std::nan("");
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()), gsl_root_fsolver_x_upper(solver.get()), 1e-12, 0.0);
  }
  if (status != GSL_SUCCESS) return std::nan("");
  // Brent also converges onto the jump where the wall bursts (the mismatch leaps from below 0
  // to the burst's +1): a stretch beyond the burst limit is no state.
  const double root = gsl_root_fsolver_root(solver.get());
  return std::abs(hoop_mismatch(root, &problem)) <= 1e-9 * target ? std::exp(root) : std::nan("");
}

}  // namespace

FarFieldState far_field_state(ShellFeLaw law, double hoop_stretch, double turgid_thickness, double poisson) {
  FarFieldState state;
  if (!(hoop_stretch > 1.0 && std::isfinite(hoop_stretch) && turgid_thickness > 0 && std::isfinite(turgid_thickness))) {
    return state;
  }
  const FarFieldLaw far_law = to_far_field_law(law);
  double thickness = turgid_thickness;
  for (int pass = 0; pass < 50; ++pass) {
    const double p_over_t = hoop_root(far_law, hoop_stretch, thickness, poisson);
    if (!std::isfinite(p_over_t)) return state;
    const FarFieldInflation inflated = far_field_inflation(far_law, p_over_t * thickness, thickness, poisson);
    const double next = turgid_thickness / inflated.thickness_stretch;
    state.pressure_over_young = p_over_t * next;
    state.thickness = next;
    state.thickness_stretch = inflated.thickness_stretch;
    state.axial_stretch = inflated.axial_stretch;
    if (std::abs(next - thickness) <= 1e-13 * next) {
      state.found = true;
      return state;
    }
    thickness = next;
  }
  return state;
}

double far_field_unstressed_thickness(ShellFeLaw law, double pressure_over_young, double turgid_thickness,
                                      double poisson) {
  const FarFieldLaw far_law = to_far_field_law(law);
  double thickness = turgid_thickness;
  for (int pass = 0; pass < 100; ++pass) {
    const FarFieldInflation inflated = far_field_inflation(far_law, pressure_over_young, thickness, poisson);
    if (inflated.burst || !(inflated.thickness_stretch > 0)) return 0.0;
    const double next = turgid_thickness / inflated.thickness_stretch;
    if (std::abs(next - thickness) <= 1e-13 * next) return next;
    thickness = next;
  }
  return 0.0;
}

void curve_in_si(const ForwardResult& result, double d0, double young, IndentationCurve& curve) {
  const double force_scale = young * d0 * d0;
  curve.depth.clear();
  curve.force.clear();
  curve.contact_radius.clear();
  for (double delta : result.depth) curve.depth.push_back(delta * d0);
  for (double force : result.force) curve.force.push_back(force * force_scale);
  for (double radius : result.contact_radius) curve.contact_radius.push_back(radius * d0);
  curve.turgid_diameter = result.turgid_diameter * d0;
  curve.axial_stretch = result.axial_stretch;
  curve.thickness_stretch = result.thickness_stretch;
  curve.newton_iterations += result.newton_iterations;
  curve.seconds_assembly += result.seconds_assembly;
  curve.seconds_factorisation += result.seconds_factorisation;
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
