// A closed surface from a mesh file (mesh.hpp) in the forward protocol (geometry.hpp): the node
// of least x is pinned, the node of largest x (where the probe presses) held in y and z, the node
// of largest z held in y; the substrate as for the tube; the diameter read as the extent in x.
#include "fe/geometry.hpp"

namespace growthuq::fe {
namespace {

class FileGeometry final : public WallGeometry {
 public:
  using WallGeometry::WallGeometry;

  std::optional<std::string> check(SampleStatus& status) const override {
    if (problem_.mesh_file.empty()) {
      status = SampleStatus::invalid_input;
      return "mesh file: expected a path";
    }
    status = SampleStatus::ok;
    return std::nullopt;
  }

  std::optional<double> first_focus(ForwardResult&) const override { return problem_.probe_distance; }

  WallSetup setup(double) const override {
    WallSetup s;
    s.mesh = read_mesh_file(problem_.mesh_file);
    require_bending_stencils(s.mesh, problem_.mesh_file);  // named with its file, before the simulation
    s.fixed.assign(static_cast<std::size_t>(3 * s.mesh.positions.cols()), 0);
    const Eigen::Index low = extreme(s.mesh, 0, false), high = extreme(s.mesh, 0, true), top = extreme(s.mesh, 2, true);
    for (int k = 0; k < 3; ++k) s.fixed[static_cast<std::size_t>(3 * low + k)] = 1;
    s.fixed[static_cast<std::size_t>(3 * high + 1)] = s.fixed[static_cast<std::size_t>(3 * high + 2)] = 1;
    s.fixed[static_cast<std::size_t>(3 * top + 1)] = 1;
    s.substrate = problem_.substrate;
    s.measured_nodes = all_indices(static_cast<std::size_t>(s.mesh.positions.cols()));
    s.measured_faces = all_indices(s.mesh.faces.size());
    return s;
  }

  bool mesh_from_user() const override { return true; }

  std::optional<double> refocus(const WallSetup&, const Eigen::Matrix3Xd&, double, double) const override {
    return std::nullopt;  // the user's mesh is kept as it is
  }

  // The reference position of the node of largest x (held in y and z).
  Eigen::Vector3d probe_axis(const WallSetup& setup, const Eigen::Matrix3Xd&) const override {
    return setup.mesh.positions.col(extreme(setup.mesh, 0, true));
  }

  void measure_turgid(const WallSetup&, const Eigen::Matrix3Xd& x, ForwardResult& result) const override {
    result.turgid_diameter = x.row(0).maxCoeff() - x.row(0).minCoeff();
  }

 private:
  // The node of least (or largest) reference coordinate `axis` (the first of equals).
  static Eigen::Index extreme(const TriangleMesh& mesh, int axis, bool largest) {
    Eigen::Index node = 0;
    if (largest) {
      mesh.positions.row(axis).maxCoeff(&node);
    } else {
      mesh.positions.row(axis).minCoeff(&node);
    }
    return node;
  }
};

}  // namespace

std::unique_ptr<WallGeometry> make_file_geometry(const ForwardProblem& problem) {
  return std::make_unique<FileGeometry>(problem);
}

}  // namespace growthuq::fe
