// The capped tube (mesh.hpp) in the forward protocol (geometry.hpp): the distal ring z = 0
// pinned; the nodes of the plane y = 0 keep y = 0 (half model: the mirror plane; full model: on
// the symmetric branch, see setup()); the probe on the meridian x > 0, a behind the turgid apex;
// the substrate, if on, under it; the turgid state read from the far field.
#include <algorithm>
#include <cmath>

#include "fe/assembly.hpp"
#include "fe/far_field.hpp"
#include "fe/geometry.hpp"

namespace growthuq::fe {
namespace {

class TubeGeometry final : public WallGeometry {
 public:
  using WallGeometry::WallGeometry;
  std::optional<std::string> check(SampleStatus& status) const override;
  std::optional<double> first_focus(ForwardResult& result) const override;
  WallSetup setup(double focus) const override;
  std::optional<double> refocus(const WallSetup& setup, const Eigen::Matrix3Xd& x, double focus,
                                double allowed) const override;
  Eigen::Vector3d probe_axis(const WallSetup& setup, const Eigen::Matrix3Xd& x) const override;
  void measure_turgid(const WallSetup& setup, const Eigen::Matrix3Xd& x, ForwardResult& result) const override;
  bool has_far_field() const override { return true; }

 private:
  double reference_distance(const TriangleMesh& mesh, const Eigen::Matrix3Xd& x, double distance) const;
};

std::optional<std::string> TubeGeometry::check(SampleStatus& status) const {
  const ForwardProblem& p = problem_;
  status = SampleStatus::invalid_input;
  if (!std::isfinite(p.tube_length) || !std::isfinite(p.probe_distance) || !(p.tube_length >= 1.0)) {
    return "tube length L/d0 = " + std::to_string(p.tube_length) + ": expected >= 1";
  }
  if (!(p.probe_distance > 0 && p.probe_distance <= p.tube_length - 0.5)) {
    status = SampleStatus::probe_beyond_mesh;
    return "probe distance a/d0 = " + std::to_string(p.probe_distance) +
           ": expected in (0, L/d0 - 1/2] (on the cap or the cylinder, away from the pinned end)";
  }
  status = SampleStatus::ok;
  return std::nullopt;
}

std::optional<double> TubeGeometry::first_focus(ForwardResult& result) const {
  const ForwardProblem& p = problem_;
  const FarFieldInflation far = far_field_inflation(far_field_law(p.law), p.pressure, p.thickness, p.poisson);
  if (far.burst) {
    result.status = SampleStatus::burst;
    result.message = "p/E = " + std::to_string(p.pressure) + " is beyond the pressure maximum of the closed-end tube "
                     "(far field, hoop stretch " + std::to_string(far.hoop_stretch) + " there)";
    return std::nullopt;
  }
  // The cylinder between cap and probe stretches axially; the cap, under half the cylinder's hoop
  // tension, stretches about as a sphere, whose small-strain stretch is (1 - nu)/(2 - nu) of the
  // cylinder's hoop strain (Timoshenko and Woinowsky-Krieger 1959, membrane theory; measured
  // within 0.02 d0 of the inflated state's own point at p/E = 0.005, h0/d0 = 0.02).
  const double cap = 0.5 * std::exp(std::log(far.hoop_stretch) * (1 - p.poisson) / (2 - p.poisson));
  return p.probe_distance >= cap ? 0.5 + (p.probe_distance - cap) / far.axial_stretch
                                 : p.probe_distance / far.hoop_stretch;
}

WallSetup TubeGeometry::setup(double focus) const {
  const ForwardProblem& p = problem_;
  WallSetup s;
  s.half = p.half_model;
  s.mesh = make_tube_mesh(p.tube_length, focus, s.half, mesh_sizing(p.mesh, p.probe_radius, p.thickness));
  s.fixed = mirror_and_end_ring_fixed(s.mesh, s.half, true);
  const Eigen::Index nodes = s.mesh.positions.cols();
  if (!s.half) {
    // The full model on the symmetric branch: a tube pressed between a sphere and a frictionless
    // plane has a sideways mode of almost no stiffness (it would slide out from under the probe,
    // held only by the pinned end 90 um away), on which Newton stalls. Holding the nodes of the
    // plane y = 0 in y leaves the symmetric solution unchanged (they have y = 0 there), and the
    // bending across the plane is computed from real neighbours, which is what the comparison
    // with the half model (whose mirror edges stand in for them) tests.
    for (Eigen::Index v = 0; v < nodes; ++v) {
      if (std::fabs(s.mesh.positions(1, v)) <= 1e-12) s.fixed[static_cast<std::size_t>(3 * v + 1)] = 1;
    }
  }
  s.substrate = p.substrate;
  // The far field: a band of the cylinder one diameter long, midway between end and cap.
  const double middle = 0.5 * (p.tube_length - 0.5);
  for (Eigen::Index v = 0; v < nodes; ++v) {
    if (std::fabs(s.mesh.positions(2, v) - middle) <= 0.5) s.measured_nodes.push_back(static_cast<int>(v));
  }
  for (std::size_t f = 0; f < s.mesh.faces.size(); ++f) {
    double z = 0;
    for (int v : s.mesh.faces[f]) z += s.mesh.positions(2, v) / 3;
    if (std::fabs(z - middle) <= 0.5) s.measured_faces.push_back(static_cast<int>(f));
  }
  return s;
}

// The reference distance behind the apex of the material point that inflation brings to
// `distance` behind the turgid apex, on the probe's meridian (y = 0, x > 0): the deformed z
// along the meridian is interpolated linearly between its nodes (sorted by reference arc).
double TubeGeometry::reference_distance(const TriangleMesh& mesh, const Eigen::Matrix3Xd& x, double distance) const {
  const double length = problem_.tube_length;
  const double cap_base = length - 0.5;
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
      return length - z;
    }
  }
  return distance;
}

std::optional<double> TubeGeometry::refocus(const WallSetup& setup, const Eigen::Matrix3Xd& x, double focus,
                                            double allowed) const {
  const double actual = reference_distance(setup.mesh, x, problem_.probe_distance);
  if (std::fabs(actual - focus) <= allowed) return std::nullopt;
  return actual;
}

Eigen::Vector3d TubeGeometry::probe_axis(const WallSetup&, const Eigen::Matrix3Xd& x) const {
  return {0, 0, x.row(2).maxCoeff() - problem_.probe_distance};
}

// Mean diameter, and the axial stretch as the least-squares slope of deformed against reference z.
void TubeGeometry::measure_turgid(const WallSetup& setup, const Eigen::Matrix3Xd& x, ForwardResult& result) const {
  const Eigen::Matrix3Xd& X = setup.mesh.positions;
  double radius = 0, zr = 0, zd = 0, zrr = 0, zrd = 0;
  for (int v : setup.measured_nodes) {
    radius += std::hypot(x(0, v), x(1, v));
    zr += X(2, v), zd += x(2, v), zrr += X(2, v) * X(2, v), zrd += X(2, v) * x(2, v);
  }
  const double n = static_cast<double>(setup.measured_nodes.size());
  result.turgid_diameter = 2 * radius / n;
  result.axial_stretch = (n * zrd - zr * zd) / (n * zrr - zr * zr);
}

}  // namespace

std::unique_ptr<WallGeometry> make_tube_geometry(const ForwardProblem& problem) {
  return std::make_unique<TubeGeometry>(problem);
}

}  // namespace growthuq::fe
