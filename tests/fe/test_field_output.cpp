// Field output: the HDF5 values read back with the C API, the XDMF checked as XML against the
// datasets that exist (by Python's xml.etree and h5py), the overwrite refusal, bad paths.
#include <doctest/doctest.h>

#include <hdf5.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/fe/field_output.hpp"

namespace fs = std::filesystem;
using growthuq::Overwrite;
using growthuq::ShellFeField;

namespace {

// Two triangles of a square (1 um side), the second vertex moved by (0.1, 0, -0.2) um.
ShellFeField square() {
  ShellFeField field;
  field.reference.resize(3, 4);
  field.reference << 0, 1e-6, 1e-6, 0,  //
      0, 0, 1e-6, 1e-6,                 //
      0, 0, 0, 0;
  field.deformed = field.reference;
  field.deformed(0, 1) += 0.1e-6;
  field.deformed(2, 1) -= 0.2e-6;
  field.faces = {{0, 1, 2}, {0, 2, 3}};
  field.sigma1 = {2.5e6, 1.0e6};
  field.sigma2 = {0.5e6, -0.25e6};
  field.von_mises = {2.2913e6, 1.1456e6};
  field.thickness_stretch = {0.9, 0.95};
  return field;
}

fs::path scratch() {
  const fs::path folder = fs::temp_directory_path() / ("growthuq_field_" + std::to_string(getpid()));
  fs::create_directories(folder);
  return folder;
}

std::vector<double> read_doubles(hid_t file, const char* name) {
  const hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
  REQUIRE(dataset >= 0);
  const hid_t space = H5Dget_space(dataset);
  const auto count = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
  std::vector<double> values(count);
  REQUIRE(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0);
  H5Sclose(space);
  H5Dclose(dataset);
  return values;
}

}  // namespace

TEST_CASE("field output: HDF5 values in um and MPa, read back with the C API") {
  const fs::path folder = scratch();
  const std::string xdmf = (folder / "wall.xdmf").string();
  growthuq::write_shell_field(square(), xdmf, Overwrite::refuse);
  REQUIRE(fs::exists(folder / "wall.h5"));
  CHECK(!fs::exists(folder / "wall.h5.partial"));
  CHECK(!fs::exists(folder / "wall.xdmf.partial"));

  const hid_t file = H5Fopen((folder / "wall.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const auto deformed = read_doubles(file, "/mesh/deformed");
  REQUIRE(deformed.size() == 12);
  CHECK(deformed[3] == doctest::Approx(1.1));   // vertex 1, x, um
  CHECK(deformed[5] == doctest::Approx(-0.2));  // vertex 1, z
  CHECK(deformed[7] == doctest::Approx(1.0));   // vertex 2, y
  const auto displacement = read_doubles(file, "/vertex/displacement");
  CHECK(displacement[3] == doctest::Approx(0.1));
  CHECK(displacement[5] == doctest::Approx(-0.2));
  CHECK(displacement[0] == 0.0);
  const auto sigma1 = read_doubles(file, "/face/sigma1"), sigma2 = read_doubles(file, "/face/sigma2");
  CHECK(sigma1 == std::vector<double>{2.5, 1.0});
  CHECK(sigma2 == std::vector<double>{0.5, -0.25});
  CHECK(read_doubles(file, "/face/von_mises")[0] == doctest::Approx(2.2913));
  CHECK(read_doubles(file, "/face/thickness_stretch")[1] == 0.95);
  const auto faces = read_doubles(file, "/mesh/faces");  // converted by HDF5 from int64
  CHECK(faces == std::vector<double>{0, 1, 2, 0, 2, 3});
  H5Fclose(file);

  // The XDMF: well-formed, every DataItem a dataset of the stated shape.
  if (std::system("/usr/bin/python3 -c 'import h5py' > /dev/null 2>&1") == 0) {
    const std::string report = (folder / "check.txt").string();
    const std::string command = std::string("/usr/bin/python3 '") + GROWTHUQ_SOURCE_DIR + "/tests/fe/check_shell_field.py' '" +
                                xdmf + "' > '" + report + "' 2>&1";
    const int code = std::system(command.c_str());
    std::ifstream in(report);
    std::stringstream text;
    text << in.rdbuf();
    INFO(text.str());
    CHECK(code == 0);
    CHECK(text.str() ==
          "ok 8 displacement_um reference_um sigma1_MPa sigma2_MPa thickness_stretch von_mises_MPa\n");
  } else {
    MESSAGE("XDMF check skipped: /usr/bin/python3 with h5py is not available");
  }
  fs::remove_all(folder);
}

TEST_CASE("field output: an existing file is not replaced without Overwrite::allow; bad fields are InputErrors") {
  const fs::path folder = scratch();
  const std::string xdmf = (folder / "wall.xdmf").string();
  growthuq::write_shell_field(square(), xdmf, Overwrite::refuse);
  const auto before = fs::file_size(folder / "wall.h5");
  CHECK_THROWS_WITH_AS(growthuq::write_shell_field(square(), xdmf, Overwrite::refuse), doctest::Contains("--force"),
                       growthuq::InputError);
  // Only the data file exists: refused too, and nothing written.
  fs::remove(xdmf);
  CHECK_THROWS_AS(growthuq::write_shell_field(square(), xdmf, Overwrite::refuse), growthuq::InputError);
  CHECK(!fs::exists(xdmf));
  CHECK(fs::file_size(folder / "wall.h5") == before);
  growthuq::write_shell_field(square(), xdmf, Overwrite::allow);
  CHECK(fs::exists(xdmf));

  CHECK_THROWS_WITH_AS(growthuq::write_shell_field(square(), (folder / "wall.vtk").string(), Overwrite::allow),
                       doctest::Contains("ending in .xdmf"), growthuq::InputError);
  ShellFeField bad = square();
  bad.faces[1][2] = 4;
  CHECK_THROWS_WITH_AS(growthuq::write_shell_field(bad, (folder / "bad.xdmf").string(), Overwrite::refuse),
                       doctest::Contains("names vertex 4 of 4"), growthuq::InputError);
  bad = square();
  bad.von_mises.pop_back();
  CHECK_THROWS_AS(growthuq::write_shell_field(bad, (folder / "bad.xdmf").string(), Overwrite::refuse), growthuq::InputError);
  CHECK(!fs::exists(folder / "bad.h5"));
  CHECK(!fs::exists(folder / "bad.xdmf"));
  fs::remove_all(folder);
}
