// ShellFeOptions: the defaults src/fe/README.md states, and one InputError naming key, value and
// range for each bad option.
#include <doctest/doctest.h>

#include <limits>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/fe/indentation.hpp"

using growthuq::InputError;
using growthuq::ShellFeOptions;

namespace {

std::string message_of(const ShellFeOptions& options) {
  try {
    options.validate("campaign.ini [shell_fe]");
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("shell_fe options: defaults are valid and as specified") {
  const ShellFeOptions options;
  CHECK(message_of(options).empty());
  CHECK(options.tube_length == 100e-6);
  CHECK(options.probe_distance == 10e-6);
  CHECK(options.force_window[0] == 0.4e-6);
  CHECK(options.force_window[1] == 4e-6);
  CHECK(options.substrate);
  CHECK(options.bending);
  CHECK(options.half_model);
  CHECK(to_string(options.law) == "log");
  CHECK(to_string(options.mesh) == "default");
}

TEST_CASE("shell_fe options: each bad option names its key, its value and the range") {
  ShellFeOptions options;
  options.tube_length = 2e-6;
  CHECK(message_of(options) == "campaign.ini [shell_fe]: tube_length_um = '2': expected a tube length in [5, 1e6] um (default 100)");
  options = {};
  options.tube_length = growthuq::parse_shell_fe_tube_length("5", "campaign.ini [shell_fe]", "tube_length_um");  // the range's ends, as typed
  options.probe_distance = 1e-6;
  CHECK_NOTHROW(options.validate("campaign.ini [shell_fe]"));
  options.tube_length = growthuq::parse_shell_fe_tube_length("1e6", "campaign.ini [shell_fe]", "tube_length_um");
  CHECK_NOTHROW(options.validate("campaign.ini [shell_fe]"));
  options = {};
  options.probe_distance = 100e-6;
  CHECK(message_of(options).find("probe_distance_um = '100'") != std::string::npos);
  options = {};
  options.force_window = {4e-6, 0.4e-6};
  CHECK(message_of(options).find("force_window_uN = '4,0.4'") != std::string::npos);
  options = {};
  options.force_window = {0.4e-6, std::numeric_limits<double>::infinity()};
  CHECK(message_of(options).find("force_window_uN") != std::string::npos);
  options = {};
  options.geometry = growthuq::ShellFeGeometry::file;
  CHECK(message_of(options).find("mesh_file = ''") != std::string::npos);
  options = {};
  options.mesh_file = "tube.off";
  CHECK(message_of(options).find("mesh_file = 'tube.off': expected no mesh file unless geometry = file") != std::string::npos);
  options = {};
  options.inflation_tolerance = -1;
  CHECK(message_of(options).find("inflation_tolerance = '-1'") != std::string::npos);
}

TEST_CASE("shell_fe options: names parse back, and an unknown name is an InputError") {
  using namespace growthuq;
  for (ShellFeLaw law : {ShellFeLaw::hencky, ShellFeLaw::saint_venant_kirchhoff}) {
    CHECK(parse_shell_fe_law(to_string(law), "here", "law") == law);
  }
  for (ShellFeMesh mesh : {ShellFeMesh::coarse, ShellFeMesh::standard, ShellFeMesh::fine}) {
    CHECK(parse_shell_fe_mesh(to_string(mesh), "here", "mesh") == mesh);
  }
  for (ShellFeGeometry geometry : {ShellFeGeometry::tube, ShellFeGeometry::sphere, ShellFeGeometry::file}) {
    CHECK(parse_shell_fe_geometry(to_string(geometry), "here", "geometry") == geometry);
  }
  CHECK_THROWS_WITH_AS(parse_shell_fe_law("cauchy", "here", "--law"),
                       doctest::Contains("--law = 'cauchy': expected log"), InputError);
  CHECK_THROWS_AS(parse_shell_fe_mesh("medium", "here", "--mesh"), InputError);
}
