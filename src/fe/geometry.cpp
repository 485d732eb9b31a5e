// The registration of the wall geometries (geometry.hpp): each lives in its own file.
#include "fe/geometry.hpp"

#include <numeric>

namespace growthuq::fe {

std::unique_ptr<WallGeometry> make_tube_geometry(const ForwardProblem& problem);    // tube_geometry.cpp
std::unique_ptr<WallGeometry> make_sphere_geometry(const ForwardProblem& problem);  // sphere_geometry.cpp
std::unique_ptr<WallGeometry> make_file_geometry(const ForwardProblem& problem);    // file_geometry.cpp

std::unique_ptr<WallGeometry> make_wall_geometry(const ForwardProblem& problem) {
  switch (problem.geometry) {
    case ShellFeGeometry::tube: return make_tube_geometry(problem);
    case ShellFeGeometry::sphere: return make_sphere_geometry(problem);
    case ShellFeGeometry::file: return make_file_geometry(problem);
  }
  return make_tube_geometry(problem);
}

std::vector<int> all_indices(std::size_t count) {
  std::vector<int> indices(count);
  std::iota(indices.begin(), indices.end(), 0);
  return indices;
}

}  // namespace growthuq::fe
