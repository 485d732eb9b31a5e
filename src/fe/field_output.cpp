// HDF5 + XDMF output of a deformed wall. XDMF 3 (xdmf.org, "XDMF Model and Format"): a Uniform
// Grid with Triangle topology and XYZ geometry, whose DataItems point into the HDF5 file as
// "<file>:<dataset>"; attributes are Vector on Node (displacement) or Scalar on Cell (stresses).
#include "growthuq/fe/field_output.hpp"

#include <H5Cpp.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <vector>

#include "growthuq/core/interrupt.hpp"
#include "growthuq/core/error.hpp"
#include "io/hdf5_output_file.hpp"
#include "growthuq/core/numbers.hpp"

namespace growthuq {
namespace {

constexpr double um = 1e6;   // m -> um
constexpr double MPa = 1e-6;  // Pa -> MPa

// Datasets are created without modification times, as the engine's results files are, so the
// same simulation gives a byte-identical file.
H5::DSetCreatPropList untimed_dataset() {
  H5::DSetCreatPropList properties;
  H5Pset_obj_track_times(properties.getId(), false);
  return properties;
}

void write_rows(H5::Group& group, const std::string& name, const std::vector<double>& values, hsize_t columns) {
  const hsize_t dims[2] = {values.size() / columns, columns};
  H5::DataSet dataset = group.createDataSet(name, H5::PredType::IEEE_F64LE, H5::DataSpace(columns == 1 ? 1 : 2, dims),
                                            untimed_dataset());
  if (!values.empty()) dataset.write(values.data(), H5::PredType::NATIVE_DOUBLE);
}

void write_indices(H5::Group& group, const std::string& name, const std::vector<std::int64_t>& values) {
  const hsize_t dims[2] = {values.size() / 3, 3};
  H5::DataSet dataset = group.createDataSet(name, H5::PredType::STD_I64LE, H5::DataSpace(2, dims), untimed_dataset());
  if (!values.empty()) dataset.write(values.data(), H5::PredType::NATIVE_INT64);
}

// Positions as [n, 3] row-major, in um.
std::vector<double> rows_of(const Eigen::Matrix3Xd& positions) {
  std::vector<double> rows;
  rows.reserve(static_cast<std::size_t>(positions.size()));
  for (Eigen::Index v = 0; v < positions.cols(); ++v) {
    for (int c = 0; c < 3; ++c) rows.push_back(positions(c, v) * um);
  }
  return rows;
}

std::vector<double> scaled(const std::vector<double>& values, double factor) {
  std::vector<double> out;
  out.reserve(values.size());
  for (double value : values) out.push_back(value * factor);
  return out;
}

void check_field(const ShellFeField& field, const std::string& path) {
  const auto vertices = field.reference.cols();
  const std::size_t faces = field.faces.size();
  if (vertices == 0 || faces == 0 || field.deformed.cols() != vertices) {
    throw InputError(path, "the field has no mesh or its deformed and reference vertices differ in number");
  }
  for (const auto* values : {&field.sigma1, &field.sigma2, &field.von_mises, &field.thickness_stretch}) {
    if (values->size() != faces) throw InputError(path, "a per-face stress does not have one value per face");
    for (double value : *values) {
      if (!std::isfinite(value)) throw InputError(path, "a per-face stress is not finite");
    }
  }
  if (!field.reference.allFinite() || !field.deformed.allFinite()) throw InputError(path, "a vertex position is not finite");
  for (const auto& face : field.faces) {
    for (int index : face) {
      if (index < 0 || index >= vertices) throw InputError(path, "a face names vertex " + std::to_string(index) + " of " + std::to_string(vertices));
    }
  }
}

void write_data(const ShellFeField& field, const std::string& partial) {
  // Through hdf5::OutputFile: one line naming the file, never HDF5's diagnostics or a crash,
  // also on a full disk (io/hdf5_output_file.hpp).
  try {
    hdf5::OutputFile out(partial);
    try {
      H5::H5File& file = out.file();
      H5::Group mesh = file.createGroup("mesh"), vertex = file.createGroup("vertex"), face = file.createGroup("face");
      const std::vector<double> reference = rows_of(field.reference), deformed = rows_of(field.deformed);
      write_rows(mesh, "reference", reference, 3);
      write_rows(mesh, "deformed", deformed, 3);
      std::vector<std::int64_t> faces;
      for (const auto& f : field.faces) faces.insert(faces.end(), f.begin(), f.end());
      write_indices(mesh, "faces", faces);
      std::vector<double> displacement(deformed.size());
      for (std::size_t i = 0; i < deformed.size(); ++i) displacement[i] = deformed[i] - reference[i];
      write_rows(vertex, "displacement", displacement, 3);
      write_rows(face, "sigma1", scaled(field.sigma1, MPa), 1);
      write_rows(face, "sigma2", scaled(field.sigma2, MPa), 1);
      write_rows(face, "von_mises", scaled(field.von_mises, MPa), 1);
      write_rows(face, "thickness_stretch", field.thickness_stretch, 1);
    } catch (const H5::Exception& error) {
      out.rethrow(error);
    }
    out.close();
  } catch (const InputError&) {
    std::remove(partial.c_str());
    throw;
  }
}

std::string data_item(const std::string& h5_name, const std::string& dataset, std::size_t rows, int columns,
                      const char* number_type, int precision) {
  std::ostringstream item;
  item << "        <DataItem Dimensions=\"" << rows;
  if (columns > 1) item << " " << columns;
  item << "\" NumberType=\"" << number_type << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << h5_name << ":"
       << dataset << "</DataItem>\n";
  return item.str();
}

std::string xdmf_text(const ShellFeField& field, const std::string& h5_name) {
  const std::size_t vertices = static_cast<std::size_t>(field.reference.cols()), faces = field.faces.size();
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" ?>\n"
         "<Xdmf Version=\"3.0\">\n"
         "  <Domain>\n"
         "    <Grid Name=\"wall\" GridType=\"Uniform\">\n"
      << "      <Topology TopologyType=\"Triangle\" NumberOfElements=\"" << faces << "\">\n"
      << data_item(h5_name, "/mesh/faces", faces, 3, "Int", 8) << "      </Topology>\n"
      << "      <Geometry GeometryType=\"XYZ\">\n"
      << data_item(h5_name, "/mesh/deformed", vertices, 3, "Float", 8) << "      </Geometry>\n";
  const auto attribute = [&](const char* name, const char* type, const char* center, const std::string& dataset,
                             std::size_t rows, int columns) {
    xml << "      <Attribute Name=\"" << name << "\" AttributeType=\"" << type << "\" Center=\"" << center << "\">\n"
        << data_item(h5_name, dataset, rows, columns, "Float", 8) << "      </Attribute>\n";
  };
  attribute("displacement_um", "Vector", "Node", "/vertex/displacement", vertices, 3);
  attribute("reference_um", "Vector", "Node", "/mesh/reference", vertices, 3);
  attribute("sigma1_MPa", "Scalar", "Cell", "/face/sigma1", faces, 1);
  attribute("sigma2_MPa", "Scalar", "Cell", "/face/sigma2", faces, 1);
  attribute("von_mises_MPa", "Scalar", "Cell", "/face/von_mises", faces, 1);
  attribute("thickness_stretch", "Scalar", "Cell", "/face/thickness_stretch", faces, 1);
  xml << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return xml.str();
}

}  // namespace

std::string shell_field_data_path(const std::string& xdmf_path) {
  return std::filesystem::path(xdmf_path).replace_extension(".h5").string();
}

void write_shell_field(const ShellFeField& field, const std::string& xdmf_path, Overwrite overwrite) {
  if (std::filesystem::path(xdmf_path).extension() != ".xdmf") {
    throw_bad_value("field output", "path", xdmf_path, "a file name ending in .xdmf (the data goes beside it, .h5)");
  }
  const std::string h5_path = shell_field_data_path(xdmf_path);
  check_can_write(xdmf_path, overwrite);
  check_can_write(h5_path, overwrite);
  check_field(field, xdmf_path);

  // Through the steps every writer shares (io/output_file.hpp): never written through a stale
  // link or into a special file, never renamed over one.
  const std::string partial = h5_path + ".partial";
  prepare_partial_file(partial);
  const RemovedOnSignal removed_on_signal(partial);
  write_data(field, partial);
  move_into_place(partial, h5_path);
  // The XDMF names the data file relative to itself, so the pair can be moved together.
  try {
    write_file_atomically(xdmf_path, xdmf_text(field, std::filesystem::path(h5_path).filename().string()), overwrite);
  } catch (...) {
    std::remove(h5_path.c_str());  // no data file without its description
    throw;
  }
}

}  // namespace growthuq
