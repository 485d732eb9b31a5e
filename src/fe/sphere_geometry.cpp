// The sphere of the forward protocol (geometry.hpp), a validation case: the probe presses at the
// pole +x; the great circle x = 0 is held in x (the symmetry plane of a sphere squeezed between
// two equal probes, so the depth is the pole's own deflection), the rigid motions left by it at
// single nodes on the axes; no substrate; the turgid state read from the whole wall.
#include <cmath>

#include "fe/assembly.hpp"
#include "fe/geometry.hpp"

namespace growthuq::fe {
namespace {

class SphereGeometry final : public WallGeometry {
 public:
  using WallGeometry::WallGeometry;

  std::optional<std::string> check(SampleStatus& status) const override {
    status = SampleStatus::ok;
    return std::nullopt;
  }

  std::optional<double> first_focus(ForwardResult&) const override { return problem_.probe_distance; }

  WallSetup setup(double) const override {
    const ForwardProblem& p = problem_;
    WallSetup s;
    s.half = p.half_model;
    s.mesh = make_sphere_mesh(s.half, mesh_sizing(p.mesh, p.probe_radius, p.thickness));
    s.fixed = mirror_and_end_ring_fixed(s.mesh, s.half, false);
    for (Eigen::Index v = 0; v < s.mesh.positions.cols(); ++v) {
      const Eigen::Vector3d q = s.mesh.positions.col(v);
      const auto base = static_cast<std::size_t>(3 * v);
      if (std::fabs(q.x()) <= 1e-12) s.fixed[base] = 1;  // the great circle x = 0 held in x
      if ((q - Eigen::Vector3d(0.5, 0, 0)).norm() <= 1e-12) {
        s.fixed[base + 2] = 1;               // z translation
        if (!s.half) s.fixed[base + 1] = 1;  // y translation (full model)
      }
      if (!s.half && (q - Eigen::Vector3d(0, 0, 0.5)).norm() <= 1e-12) s.fixed[base + 1] = 1;  // rotation about x
    }
    s.measured_nodes = all_indices(static_cast<std::size_t>(s.mesh.positions.cols()));
    s.measured_faces = all_indices(s.mesh.faces.size());
    return s;
  }

  std::optional<double> refocus(const WallSetup&, const Eigen::Matrix3Xd&, double, double) const override {
    return std::nullopt;  // the mesh is graded around the pole, where the probe presses
  }

  Eigen::Vector3d probe_axis(const WallSetup&, const Eigen::Matrix3Xd&) const override {
    return Eigen::Vector3d::Zero();
  }

  void measure_turgid(const WallSetup& setup, const Eigen::Matrix3Xd& x, ForwardResult& result) const override {
    double radius = 0;
    for (int v : setup.measured_nodes) radius += x.col(v).norm();
    result.turgid_diameter = 2 * radius / static_cast<double>(setup.measured_nodes.size());
  }
};

}  // namespace

std::unique_ptr<WallGeometry> make_sphere_geometry(const ForwardProblem& problem) {
  return std::make_unique<SphereGeometry>(problem);
}

}  // namespace growthuq::fe
