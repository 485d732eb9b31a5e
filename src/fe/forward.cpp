#include "fe/forward.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "fe/assembly.hpp"
#include "fe/equilibrium.hpp"
#include "fe/far_field.hpp"
#include "fe/newton.hpp"
#include "growthuq/core/error.hpp"

namespace growthuq::fe {
namespace {

// Where the probe presses, the supports, and the part of the wall the turgid state is read from.
struct Setup {
  TriangleMesh mesh;
  std::vector<char> fixed;
  bool half = false;
  Eigen::Vector3d probe_axis = Eigen::Vector3d::Zero();  // a point of the probe's line (y, z used)
  std::vector<int> measured_nodes;  // the far field (tube) or the whole wall
  std::vector<int> measured_faces;
  bool substrate = false;
};

bool finite_all(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

// An empty string when the problem is admissible, else what is wrong (one line).
std::string check(const ForwardProblem& p, FeStatus& status) {
  status = FeStatus::invalid_input;
  if (!finite_all({p.pressure, p.thickness, p.poisson, p.probe_radius, p.max_depth})) {
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
  if (!(p.max_depth >= 0 && p.max_depth < 0.5)) {
    return "max depth / d0 = " + std::to_string(p.max_depth) + ": expected in [0, 0.5)";
  }
  if (p.geometry == Geometry::tube) {
    if (!finite_all({p.tube_length, p.probe_distance}) || !(p.tube_length >= 1.0)) {
      return "tube length L/d0 = " + std::to_string(p.tube_length) + ": expected >= 1";
    }
    if (!(p.probe_distance > 0 && p.probe_distance <= p.tube_length - 0.5)) {
      status = FeStatus::probe_beyond_mesh;
      return "probe distance a/d0 = " + std::to_string(p.probe_distance) +
             ": expected in (0, L/d0 - 1/2] (on the cap or the cylinder, away from the pinned end)";
    }
  }
  if (p.geometry == Geometry::file && p.mesh_file.empty()) return "mesh file: expected a path";
  status = FeStatus::ok;
  return {};
}

// `focus_distance`: where (behind the apex, in the reference configuration) the tube mesh is
// finest; the probe itself is placed a behind the turgid apex after inflation.
Setup make_setup(const ForwardProblem& p, double focus_distance) {
  Setup s;
  const MeshSizing sizing = mesh_sizing(p.mesh, p.probe_radius, p.thickness);
  const auto nodes = [&] { return s.mesh.positions.cols(); };
  if (p.geometry == Geometry::tube) {
    s.half = p.half_model;
    s.mesh = make_tube_mesh(p.tube_length, focus_distance, s.half, sizing);
    s.fixed = mirror_and_end_ring_fixed(s.mesh, s.half, true);
    if (!s.half) {
      // The full model on the symmetric branch: a tube pressed between a sphere and a frictionless
      // plane has a sideways mode of almost no stiffness (it would slide out from under the probe,
      // held only by the pinned end 90 um away), on which Newton stalls. Holding the nodes of the
      // plane y = 0 in y leaves the symmetric solution unchanged (they have y = 0 there), and the
      // bending across the plane is computed from real neighbours, which is what the comparison
      // with the half model (whose mirror edges stand in for them) tests.
      for (Eigen::Index v = 0; v < nodes(); ++v) {
        if (std::fabs(s.mesh.positions(1, v)) <= 1e-12) s.fixed[static_cast<std::size_t>(3 * v + 1)] = 1;
      }
    }
    s.substrate = p.substrate;
    // The far field: a band of the cylinder one diameter long, midway between end and cap.
    const double middle = 0.5 * (p.tube_length - 0.5);
    for (Eigen::Index v = 0; v < nodes(); ++v) {
      if (std::fabs(s.mesh.positions(2, v) - middle) <= 0.5) s.measured_nodes.push_back(static_cast<int>(v));
    }
    for (std::size_t f = 0; f < s.mesh.faces.size(); ++f) {
      double z = 0;
      for (int v : s.mesh.faces[f]) z += s.mesh.positions(2, v) / 3;
      if (std::fabs(z - middle) <= 0.5) s.measured_faces.push_back(static_cast<int>(f));
    }
    return s;
  }
  if (p.geometry == Geometry::sphere) {
    s.half = p.half_model;
    s.mesh = make_sphere_mesh(s.half, sizing);
    s.fixed = mirror_and_end_ring_fixed(s.mesh, s.half, false);
    for (Eigen::Index v = 0; v < nodes(); ++v) {
      const Eigen::Vector3d q = s.mesh.positions.col(v);
      const auto base = static_cast<std::size_t>(3 * v);
      if (std::fabs(q.x()) <= 1e-12) s.fixed[base] = 1;  // the great circle x = 0 held in x
      if ((q - Eigen::Vector3d(0.5, 0, 0)).norm() <= 1e-12) {
        s.fixed[base + 2] = 1;                       // z translation
        if (!s.half) s.fixed[base + 1] = 1;          // y translation (full model)
      }
      if (!s.half && (q - Eigen::Vector3d(0, 0, 0.5)).norm() <= 1e-12) s.fixed[base + 1] = 1;  // rotation about x
    }
  } else {
    s.half = false;
    s.mesh = read_mesh_file(p.mesh_file);
    require_bending_stencils(s.mesh, p.mesh_file);  // named with its file, before the simulation
    s.fixed.assign(static_cast<std::size_t>(3 * nodes()), 0);
    Eigen::Index low = 0, high = 0, top = 0;
    s.mesh.positions.row(0).minCoeff(&low);
    s.mesh.positions.row(0).maxCoeff(&high);
    s.mesh.positions.row(2).maxCoeff(&top);
    for (int k = 0; k < 3; ++k) s.fixed[static_cast<std::size_t>(3 * low + k)] = 1;
    s.fixed[static_cast<std::size_t>(3 * high + 1)] = s.fixed[static_cast<std::size_t>(3 * high + 2)] = 1;
    s.fixed[static_cast<std::size_t>(3 * top + 1)] = 1;
    s.probe_axis = s.mesh.positions.col(high);
    s.substrate = p.substrate;
  }
  for (Eigen::Index v = 0; v < nodes(); ++v) s.measured_nodes.push_back(static_cast<int>(v));
  for (std::size_t f = 0; f < s.mesh.faces.size(); ++f) s.measured_faces.push_back(static_cast<int>(f));
  return s;
}

// The turgid state: mean diameter, axial stretch (least-squares slope of deformed against
// reference z), mean thickness stretch, over the measured part of the wall.
void measure_turgid(const ForwardProblem& p, const Setup& s, const ShellAssembly& assembly,
                    const Eigen::Matrix3Xd& x, ForwardResult& result) {
  const Eigen::Matrix3Xd& X = s.mesh.positions;
  if (p.geometry == Geometry::tube) {
    double radius = 0, zr = 0, zd = 0, zrr = 0, zrd = 0;
    for (int v : s.measured_nodes) {
      radius += std::hypot(x(0, v), x(1, v));
      zr += X(2, v), zd += x(2, v), zrr += X(2, v) * X(2, v), zrd += X(2, v) * x(2, v);
    }
    const double n = static_cast<double>(s.measured_nodes.size());
    result.turgid_diameter = 2 * radius / n;
    result.axial_stretch = (n * zrd - zr * zd) / (n * zrr - zr * zr);
  } else if (p.geometry == Geometry::sphere) {
    double radius = 0;
    for (int v : s.measured_nodes) radius += x.col(v).norm();
    result.turgid_diameter = 2 * radius / static_cast<double>(s.measured_nodes.size());
  } else {
    result.turgid_diameter = x.row(0).maxCoeff() - x.row(0).minCoeff();
  }
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

// The reference distance behind the apex of the material point that inflation brings to
// `distance` behind the turgid apex, on the probe's meridian (y = 0, x > 0): the deformed z
// along the meridian is interpolated linearly between its nodes (sorted by reference arc).
double reference_distance(const ForwardProblem& p, const TriangleMesh& mesh, const Eigen::Matrix3Xd& x,
                          double distance) {
  const double cap_base = p.tube_length - 0.5;
  struct Point { double arc, reference_z, deformed_z; };
  std::vector<Point> meridian;
  for (Eigen::Index v = 0; v < mesh.positions.cols(); ++v) {
    const Eigen::Vector3d q = mesh.positions.col(v);
    if (std::fabs(q.y()) > 1e-12 || q.x() < 0) continue;
    const double arc = q.z() <= cap_base ? q.z() : cap_base + 0.5 * std::atan2(q.z() - cap_base, q.x());
    meridian.push_back({arc, q.z(), x(2, v)});
  }
  std::sort(meridian.begin(), meridian.end(), [](const Point& a, const Point& b) { return a.arc < b.arc; });
  const double target = x.row(2).maxCoeff() - distance;
  for (std::size_t k = 1; k < meridian.size(); ++k) {
    const Point& a = meridian[k - 1];
    const Point& b = meridian[k];
    if ((a.deformed_z - target) * (b.deformed_z - target) <= 0 && a.deformed_z != b.deformed_z) {
      const double w = (target - a.deformed_z) / (b.deformed_z - a.deformed_z);
      const double arc = a.arc + w * (b.arc - a.arc);
      const double z = arc <= cap_base ? arc : cap_base + 0.5 * std::sin((arc - cap_base) / 0.5);
      return p.tube_length - z;
    }
  }
  return distance;
}

void fill_fields(const Setup& s, const ShellAssembly& assembly, const Eigen::Matrix3Xd& x, ForwardResult& result) {
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
  FeStatus status = FeStatus::ok;
  if (std::string why = check(p, status); !why.empty()) {
    result.status = status;
    result.message = why;
    return result;
  }
  // The mesh is finest where the probe will press: at first where the reference point a behind
  // the apex lies, then (one remeshing, if inflation moved the turgid target by more than half
  // the fine region's radius) where inflation actually brings it.
  const double tolerance = 1e-3 * p.probe_radius;  // the stated bound on any node's penetration
  const MeshSizing sizing = mesh_sizing(p.mesh, p.probe_radius, p.thickness);
  double focus_distance = p.probe_distance;
  if (p.geometry == Geometry::tube) {
    const FarFieldInflation far = far_field_inflation(far_field_law(p.law), p.pressure, p.thickness, p.poisson);
    if (far.burst) {
      result.status = FeStatus::burst;
      result.message = "p/E = " + std::to_string(p.pressure) + " is beyond the pressure maximum of the closed-end tube "
                       "(far field, hoop stretch " + std::to_string(far.hoop_stretch) + " there)";
      return result;
    }
    // First guess of the reference distance the probe will press at: the cylinder between cap
    // and probe stretches axially; the cap, under half the cylinder's hoop tension, stretches
    // about as a sphere, whose small-strain stretch is (1 - nu)/(2 - nu) of the cylinder's hoop
    // strain (Timoshenko and Woinowsky-Krieger 1959, membrane theory; measured within 0.02 d0
    // of the inflated state's own point at p/E = 0.005, h0/d0 = 0.02).
    const double cap = 0.5 * std::exp(std::log(far.hoop_stretch) * (1 - p.poisson) / (2 - p.poisson));
    focus_distance = p.probe_distance >= cap ? 0.5 + (p.probe_distance - cap) / far.axial_stretch
                                             : p.probe_distance / far.hoop_stretch;
  }
  Setup setup;
  std::optional<ShellAssembly> assembly;
  std::optional<ShellObjective> objective;
  std::unique_ptr<NewtonSolver> solver;
  Eigen::Matrix3Xd x;
  for (int pass = 0; pass < 2; ++pass) {
    try {
      setup = make_setup(p, focus_distance);
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
      if (p.geometry == Geometry::file) throw;  // an unreadable mesh file is the user's to fix
      result.status = FeStatus::invalid_input;
      result.message = e.what();
      return result;
    }
    ContactOptions contact;
    contact.method = p.contact;
    // Active set: nodes within a thin band of an obstacle may be held on it. Penalty: nodes
    // there start a step touching it; the penalty is raised until the deepest node is within
    // the stated bound on any node's penetration; a Newton step may not carry a node deeper than
    // half of it (the line search sees only the energy at the step's end).
    contact.band = 0.1 * tolerance;
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
    if (inflated.status != FeStatus::ok) {
      add_timing(*solver, *objective, result);
      // No equilibrium beyond the pressure maximum of the wall: the load steps shrink to nothing
      // while the diameter runs away.
      result.status = inflated.reached > 0.5 ? FeStatus::burst : inflated.status;
      result.message = "inflation: " + inflated.message;
      return result;
    }
    if (p.geometry != Geometry::tube || !indent) break;
    const double actual = reference_distance(p, setup.mesh, x, p.probe_distance);
    if (std::fabs(actual - focus_distance) <= 0.5 * sizing.fine_radius) break;
    focus_distance = actual;
    add_timing(*solver, *objective, result);  // the discarded pass
  }
  if (p.geometry == Geometry::tube) {
    setup.probe_axis = Eigen::Vector3d(0, 0, x.row(2).maxCoeff() - p.probe_distance);
  }
  measure_turgid(p, setup, *assembly, x, result);
  if (!indent) {
    fill_fields(setup, *assembly, x, result);
    add_timing(*solver, *objective, result);
    return result;
  }

  // The probe just touching the highest node under it.
  const double rho = p.probe_radius;
  double touch = -std::numeric_limits<double>::infinity();
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    const double lateral2 = std::pow(x(1, v) - setup.probe_axis.y(), 2) + std::pow(x(2, v) - setup.probe_axis.z(), 2);
    if (lateral2 < rho * rho) touch = std::max(touch, x(0, v) + std::sqrt(rho * rho - lateral2));
  }
  if (!std::isfinite(touch)) {
    result.status = FeStatus::probe_beyond_mesh;
    result.message = "no node of the wall under the probe";
    add_timing(*solver, *objective, result);
    return result;
  }
  const Eigen::Vector3d start(touch, setup.probe_axis.y(), setup.probe_axis.z());
  assembly->loads().obstacles.spheres = {RigidSphere{start, rho}};
  if (setup.substrate) {
    assembly->loads().obstacles.planes = {RigidPlane{Eigen::Vector3d(x.row(0).minCoeff(), 0, 0), Eigen::Vector3d::UnitX()}};
  }
  const double mirror_factor = setup.half ? 2.0 : 1.0;
  result.depth = {0.0};
  result.force = {0.0};
  result.contact_radius = {0.0};
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
    if (!(result.force.back() > 0)) {
      lost = true;
      return false;
    }
    if (p.on_depth) p.on_depth(t * p.max_depth);
    return true;
  };
  LoadSteppingOptions indentation;
  indentation.first_step = 1.0 / 48;  // the contact forms gently, then the steps grow
  indentation.max_step = 1.0 / 8;
  // A Newton step may not carry a node across the probe: the line search sees only the energy
  // at the step's end, where a wall that has jumped past the probe has none left in contact.
  indentation.newton.max_step = 0.25 * rho;
  indentation.newton.first_step_whole = p.contact == ContactMethod::active_set;
  // The nodal residual that is left, 1e-6 of E h0 times the shortest edge, is below 1e-5 of the
  // smallest recorded force; the contact's active set makes the last digits linear to reach.
  indentation.newton.gradient_tolerance = 1e-6;
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
  add_timing(*solver, *objective, result);
  fill_fields(setup, *assembly, x, result);
  if (lost) {
    result.status = FeStatus::contact_lost;
    result.message = "the probe lost contact with the wall at depth " + std::to_string(result.depth.back());
  } else if (indented.status != FeStatus::ok) {
    result.status = indented.status;
    result.message = "indentation: " + indented.message;
  }
  return result;
}

}  // namespace

ForwardResult simulate_forward(const ForwardProblem& problem) { return run(problem, true); }

ForwardResult simulate_inflation(const ForwardProblem& problem) { return run(problem, false); }

}  // namespace growthuq::fe
