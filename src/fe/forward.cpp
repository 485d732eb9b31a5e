#include "fe/forward.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "fe/assembly.hpp"
#include "fe/equilibrium.hpp"
#include "fe/geometry.hpp"
#include "fe/newton.hpp"
#include "growthuq/core/error.hpp"

namespace growthuq::fe {
namespace {

// The active set's band under a probe wider than the bending length (/ d0): above the gap's
// rounding (1e-16) and the touching test (1e-12, active_set_contact.cpp), far below the patch's
// lift-off there (src/fe/README.md, section 8).
constexpr double wide_probe_band = 1e-9;

bool finite_all(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

// An empty string when the problem is admissible, else what is wrong (one line).
std::string check(const ForwardProblem& p, const WallGeometry& geometry, SampleStatus& status) {
  status = SampleStatus::invalid_input;
  if (!finite_all({p.pressure, p.thickness, p.poisson, p.probe_radius, p.max_depth, p.step_depth})) {
    return "non-finite input";
  }
  if (p.pressure < 0) return "pressure p/E = " + std::to_string(p.pressure) + ": expected >= 0";
  if (!(p.thickness > 0 && p.thickness < 0.5)) {
    return "thickness h0/d0 = " + std::to_string(p.thickness) + ": expected in (0, 0.5)";
  }
  if (!(p.poisson >= 0 && p.poisson < 0.5)) {
    return "poisson = " + std::to_string(p.poisson) + ": expected in [0, 0.5)";
  }
  if (!(p.probe_radius > 0)) return "probe radius rho/d0 = " + std::to_string(p.probe_radius) + ": expected > 0";
  if (!(p.max_depth >= 0 && p.max_depth <= deepest_automatic_depth)) {
    return "max depth / d0 = " + std::to_string(p.max_depth) + ": expected in [0, " +
           std::to_string(deepest_automatic_depth) + "]";
  }
  if (!(p.step_depth >= 0 && p.step_depth <= p.max_depth)) {
    return "step depth / d0 = " + std::to_string(p.step_depth) + ": expected in [0, max depth " +
           std::to_string(p.max_depth) + "]";
  }
  return geometry.check(status).value_or(std::string());
}

// The turgid state: the geometry's diameter (and axial stretch), and the mean thickness stretch
// over the measured part of the wall.
void measure_turgid(const WallGeometry& geometry, const WallSetup& s, const ShellAssembly& assembly,
                    const Eigen::Matrix3Xd& x, ForwardResult& result) {
  geometry.measure_turgid(s, x, result);
  const Eigen::Matrix3Xd& X = s.mesh.positions;
  double stretch = 0;
  const WallMaterial& material = assembly.problem().material;
  for (int f : s.measured_faces) {
    const auto& face = s.mesh.faces[static_cast<std::size_t>(f)];
    Eigen::Matrix<double, 9, 1> xf;
    for (int k = 0; k < 3; ++k) xf.segment<3>(3 * k) = x.col(face[static_cast<std::size_t>(k)]);
    const MembraneReference reference =
        make_membrane_reference(X.col(face[0]), X.col(face[1]), X.col(face[2]));
    stretch += membrane_stress(material, reference, xf).thickness_stretch;
  }
  result.thickness_stretch = stretch / static_cast<double>(s.measured_faces.size());
}

void fill_fields(const WallSetup& s, const ShellAssembly& assembly, const Eigen::Matrix3Xd& x, ForwardResult& result) {
  result.mesh = s.mesh;
  result.deformed = x;
  result.face_stress.clear();
  result.face_stress.reserve(s.mesh.faces.size());
  for (const auto& face : s.mesh.faces) {
    Eigen::Matrix<double, 9, 1> xf;
    for (int k = 0; k < 3; ++k) xf.segment<3>(3 * k) = x.col(face[static_cast<std::size_t>(k)]);
    const MembraneReference reference = make_membrane_reference(
        s.mesh.positions.col(face[0]), s.mesh.positions.col(face[1]), s.mesh.positions.col(face[2]));
    result.face_stress.push_back(membrane_stress(assembly.problem().material, reference, xf));
  }
}

// The time of one pass (a solver and its objective) added to the result's.
void add_timing(const NewtonSolver& solver, const ShellObjective& objective, ForwardResult& result) {
  const SolverTiming& part = solver.timing();
  result.seconds_assembly += part.assembly;
  result.seconds_factorisation += part.factorisation;
  result.seconds_contact += objective.contact_seconds();
  result.factorisations += part.factorisations;
}

ForwardResult run(const ForwardProblem& p, bool indent) {
  ForwardResult result;
  SampleStatus status = SampleStatus::ok;
  const std::unique_ptr<WallGeometry> geometry = make_wall_geometry(p);
  if (std::string why = check(p, *geometry, status); !why.empty()) {
    result.status = status;
    result.message = why;
    return result;
  }
  // The mesh is finest where the probe will press: at first where the geometry expects it, then
  // (one remeshing, if inflation moved the target by more than half the fine region's radius)
  // where inflation actually brings it.
  const double tolerance = 1e-3 * p.probe_radius;  // the stated bound on any node's penetration
  const MeshSizing sizing = mesh_sizing(p.mesh, p.probe_radius, p.thickness);
  const std::optional<double> first_focus = geometry->first_focus(result);
  if (!first_focus) return result;
  double focus_distance = *first_focus;
  WallSetup setup;
  std::optional<ShellAssembly> assembly;
  std::optional<ShellObjective> objective;
  std::unique_ptr<NewtonSolver> solver;
  Eigen::Matrix3Xd x;
  for (int pass = 0; pass < 2; ++pass) {
    try {
      setup = geometry->setup(focus_distance);
      ShellProblem problem;
      problem.mesh = setup.mesh;
      problem.material = WallMaterial{p.law, 1.0, p.poisson, p.thickness};
      problem.bending = p.bending;
      problem.mirror_y0 = setup.half;
      problem.fixed = setup.fixed;
      problem.loads.penalty = PenaltyLaw{1e3 * p.thickness, 0.0};
      solver.reset();
      objective.reset();
      assembly.emplace(std::move(problem));
    } catch (const InputError& e) {
      if (geometry->mesh_from_user()) throw;  // an unreadable mesh file is the user's to fix
      result.status = SampleStatus::invalid_input;
      result.message = e.what();
      return result;
    }
    ContactOptions contact;
    contact.method = p.contact;
    // Active set: nodes within a band of an obstacle may be held on it (and lifted onto it),
    // nodes further out only when the wall pushes them in further than their gap. Under a
    // narrow probe a band of 1e-4 rho holds the nodes about to touch and saves iterations. Under
    // a probe wider than the bending length the middle of the contact patch stands off the probe
    // by 2e-5 to 6e-5 d0 (the membrane's tension tents it, src/fe/README.md section 8): a band of
    // that size held and released those nodes in turn until Newton stalled, so there the band is
    // far below any such gap. The band changes Newton's path, not the solution it converges to.
    // Penalty: nodes in the band start a step touching the obstacle; the penalty is raised until
    // the deepest node is within the stated bound on any node's penetration; a Newton step may
    // not carry a node deeper than half of it (the line search sees only the energy at the
    // step's end).
    const bool wide_probe = p.probe_radius > bending_length(p.thickness);
    contact.band = p.contact == ContactMethod::active_set && wide_probe ? wide_probe_band : 0.1 * tolerance;
    contact.reach = 0.25 * p.probe_radius;
    contact.penetration_tolerance = tolerance;
    contact.penetration_floor = 0.5 * tolerance;
    objective.emplace(*assembly, contact);
    solver = std::make_unique<NewtonSolver>(*objective);
    x = setup.mesh.positions;
    LoadSteppingOptions inflation;
    inflation.first_step = 0.25;
    inflation.max_step = 0.5;
    const EquilibriumResult inflated = solve_equilibrium(
        *objective, *solver, x, [&](double t, ShellLoads& loads) { loads.pressure = t * p.pressure; }, inflation);
    result.newton_iterations += inflated.newton_iterations;
    if (inflated.status != SampleStatus::ok) {
      add_timing(*solver, *objective, result);
      // No equilibrium beyond the pressure maximum of the wall: the load steps shrink to nothing
      // while the diameter runs away.
      result.status = inflated.reached > 0.5 ? SampleStatus::burst : inflated.status;
      result.message = "inflation: " + inflated.message;
      return result;
    }
    if (!indent) break;
    const std::optional<double> refocused = geometry->refocus(setup, x, focus_distance, 0.5 * sizing.fine_radius);
    if (!refocused) break;
    focus_distance = *refocused;
    add_timing(*solver, *objective, result);  // the discarded pass
  }
  const Eigen::Vector3d probe_axis = geometry->probe_axis(setup, x);
  measure_turgid(*geometry, setup, *assembly, x, result);
  if (!indent) {
    fill_fields(setup, *assembly, x, result);
    add_timing(*solver, *objective, result);
    return result;
  }

  // The probe just touching the highest node under it.
  const double rho = p.probe_radius;
  double touch = -std::numeric_limits<double>::infinity();
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    const double lateral2 = std::pow(x(1, v) - probe_axis.y(), 2) + std::pow(x(2, v) - probe_axis.z(), 2);
    if (lateral2 < rho * rho) touch = std::max(touch, x(0, v) + std::sqrt(rho * rho - lateral2));
  }
  if (!std::isfinite(touch)) {
    result.status = SampleStatus::probe_beyond_mesh;
    result.message = "no node of the wall under the probe";
    add_timing(*solver, *objective, result);
    return result;
  }
  const Eigen::Vector3d start(touch, probe_axis.y(), probe_axis.z());
  assembly->loads().obstacles.spheres = {RigidSphere{start, rho}};
  if (setup.substrate) {
    assembly->loads().obstacles.planes = {RigidPlane{Eigen::Vector3d(x.row(0).minCoeff(), 0, 0), Eigen::Vector3d::UnitX()}};
  }
  const double mirror_factor = setup.half ? 2.0 : 1.0;
  if (p.stabilisation.active()) objective->stabilise(p.stabilisation);
  auto record_energies = [&](const Eigen::Matrix3Xd& state) {
    const EnergyParts parts = assembly->energy(state);
    const ViscousStabilisation* stabilisation = objective->stabilisation();
    result.strain_energy.push_back(mirror_factor * (parts.membrane + parts.bending));
    result.pressure_energy.push_back(mirror_factor * parts.pressure);
    result.dissipated_energy.push_back(stabilisation ? mirror_factor * stabilisation->dissipated() : 0.0);
  };
  result.depth = {0.0};
  result.force = {0.0};
  result.contact_radius = {0.0};
  record_energies(x);
  bool lost = false;
  auto record = [&](double t, const Eigen::Matrix3Xd& state) {
    const RigidSphere& probe = assembly->loads().obstacles.spheres.front();
    const ContactState contact = objective->contact_state(state);
    double radius = 0.0;
    for (Eigen::Index v = 0; v < state.cols(); ++v) {
      // On or in the probe: exact contact holds a node on its surface (gap zero to rounding).
      if ((state.col(v) - probe.centre).norm() < probe.radius * (1 + 1e-9)) {
        radius = std::max(radius, std::hypot(state(1, v) - probe.centre.y(), state(2, v) - probe.centre.z()));
      }
    }
    result.max_penetration = std::max(result.max_penetration, contact.max_penetration);
    result.depth.push_back(t * p.max_depth);
    result.force.push_back(mirror_factor * contact.sphere_force.front().x());
    result.contact_radius.push_back(radius);
    record_energies(state);
    if (!(result.force.back() > 0)) {
      lost = true;
      return false;
    }
    if (p.on_depth) p.on_depth(t * p.max_depth);
    return !(p.long_enough && p.long_enough(result.depth, result.force));
  };
  // Steps sized from the step depth (step_share of the path): the contact forms gently, then
  // the steps grow, up to an eighth of the step depth or of the depth reached, whichever is
  // larger (the latter only on a curve that runs on past its step depth).
  const double step_share = p.step_depth > 0 ? p.step_depth / p.max_depth : 1.0;
  LoadSteppingOptions indentation;
  indentation.first_step = step_share / 48;
  indentation.max_step = step_share / 8;
  indentation.relative_max_step = 1.0 / 8;
  indentation.min_step = step_share / 4096;
  // A Newton step may not carry a node across the probe: the line search sees only the energy
  // at the step's end, where a wall that has jumped past the probe has none left in contact.
  indentation.newton.max_step = 0.25 * rho;
  indentation.newton.first_step_whole = p.contact == ContactMethod::active_set;
  // The nodal residual that is left, 1e-6 of E h0 times the shortest edge, is below 1e-5 of the
  // smallest recorded force; the contact's active set makes the last digits linear to reach.
  indentation.newton.gradient_tolerance = 1e-6;
  if (p.stabilisation.active() && p.first_increment > 0 && p.max_depth > 0) {
    // The driver's first increment (its damping factor is set from it), then the same growth.
    indentation.first_step = std::min(indentation.first_step, p.first_increment / p.max_depth);
    indentation.min_step = std::min(indentation.min_step, indentation.first_step / 16);
  }
  EquilibriumResult indented{};
  if (p.max_depth > 0) {
    indented = solve_equilibrium(
        *objective, *solver, x,
        [&](double t, ShellLoads& loads) { loads.obstacles.spheres.front().centre = start - Eigen::Vector3d(t * p.max_depth, 0, 0); },
        indentation, record);
  }
  result.newton_iterations += indented.newton_iterations;
  result.load_steps = indented.steps;
  result.indentation_iterations = indented.newton_iterations;
  if (const ViscousStabilisation* stabilisation = objective->stabilisation()) {
    result.damping_factor = stabilisation->damping_factor();
    result.damping_lowerings = stabilisation->lowerings();
  }
  add_timing(*solver, *objective, result);
  fill_fields(setup, *assembly, x, result);
  if (lost) {
    result.status = SampleStatus::contact_lost;
    result.message = "the probe lost contact with the wall at depth " + std::to_string(result.depth.back());
  } else if (indented.status != SampleStatus::ok) {
    // Where the steps stalled says why: a wall wrapped round the probe is the physical state,
    // Newton's failure only its symptom.
    const bool engulfed = result.contact_radius.back() >= engulfed_contact_fraction * rho;
    result.status = engulfed ? SampleStatus::probe_engulfed : indented.status;
    result.message = "indentation stopped at depth " + std::to_string(result.depth.back()) + " d0, contact radius " +
                     std::to_string(result.contact_radius.back() / rho) + " rho" +
                     (engulfed ? ": the wall wraps the probe" : "") + " (" + indented.message + ")";
  }
  return result;
}

}  // namespace

ForwardResult simulate_forward(const ForwardProblem& problem) { return run(problem, true); }

ForwardResult simulate_inflation(const ForwardProblem& problem) { return run(problem, false); }

}  // namespace growthuq::fe
