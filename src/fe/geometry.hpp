// The wall geometries of the forward protocol (forward.hpp): each owns its mesh, its supports
// (fixed dofs), its symmetry plane, where the probe presses and how its turgid state is read, so
// forward.cpp runs the same protocol on any of them. A new geometry is one implementation of
// WallGeometry in its own file plus its line in make_wall_geometry (geometry.cpp).
#pragma once

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fe/forward.hpp"
#include "fe/mesh.hpp"
#include "growthuq/evaluation/sample_status.hpp"

namespace growthuq::fe {

// A geometry's reference wall for one pass of the protocol.
struct WallSetup {
  TriangleMesh mesh;
  std::vector<char> fixed;          // per dof, node-major (x, y, z)
  bool half = false;                // the mesh ends at the mirror plane y = 0 (forces doubled)
  bool substrate = false;           // the plane x = min x of the inflated wall under it
  std::vector<int> measured_nodes;  // the part of the wall the turgid state is read from
  std::vector<int> measured_faces;
};

// One geometry for one ForwardProblem (it keeps its own copy of the problem).
class WallGeometry {
 public:
  explicit WallGeometry(const ForwardProblem& problem) : problem_(problem) {}
  virtual ~WallGeometry() = default;

  // What is wrong with the geometry's own input (one line), or nothing; `status` says which
  // kind of failure it is.
  virtual std::optional<std::string> check(SampleStatus& status) const = 0;

  // Where (a reference distance behind the apex) the first mesh is finest. Nothing, with the
  // status and message in `result`, where no inflated state exists at all.
  virtual std::optional<double> first_focus(ForwardResult& result) const = 0;

  // The reference wall, graded around `focus` where the geometry has one. Throws InputError for
  // a mesh beyond its size bound, or an unreadable or unsuitable mesh file.
  virtual WallSetup setup(double focus) const = 0;

  // Whether an InputError of setup() is the user's to fix (a mesh file), rather than a status.
  virtual bool mesh_from_user() const { return false; }

  // After inflation to the state x: the focus of a better mesh where the probe's target moved by
  // more than `allowed` from `focus`; nothing when this mesh is kept.
  virtual std::optional<double> refocus(const WallSetup& setup, const Eigen::Matrix3Xd& x, double focus,
                                        double allowed) const = 0;

  // A point of the probe's line at the inflated state x (the probe presses in -x; y, z used).
  virtual Eigen::Vector3d probe_axis(const WallSetup& setup, const Eigen::Matrix3Xd& x) const = 0;

  // The turgid diameter and, where the geometry has an axis, the axial stretch, into `result`.
  virtual void measure_turgid(const WallSetup& setup, const Eigen::Matrix3Xd& x, ForwardResult& result) const = 0;

  // Whether the wall far from tip and ends is the closed-form far-field cylinder (far_field.hpp),
  // so that its turgid thickness maps to h0 in closed form rather than by inflating the mesh.
  virtual bool has_far_field() const { return false; }

 protected:
  ForwardProblem problem_;
};

// The geometry the problem names (ForwardProblem::geometry).
std::unique_ptr<WallGeometry> make_wall_geometry(const ForwardProblem& problem);

// Every face of the mesh, and every node: the part of a wall without far field to measure.
std::vector<int> all_indices(std::size_t count);

}  // namespace growthuq::fe
