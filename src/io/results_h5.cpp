#include "growthuq/io/results_h5.hpp"

#include <H5Cpp.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "core/interrupt.hpp"
#include "growthuq/core/error.hpp"

// Why no compression: sampled doubles have random mantissas. Measured on ten columns of 1e6
// lognormal doubles (h5py 3.7 on the same HDF5 1.10, 65536-value chunks): contiguous 80.0 MB in
// 0.44 s; deflate level 1 75.7 MB (-5 %) in 6.2 s; shuffle + deflate 1 68.4 MB (-15 %) in 4.9 s.
// A 10x slower write for a few percent is not worth it; `h5repack -f SHUF -f GZIP=1` compresses
// a finished file when space matters more.

namespace growthuq {

namespace {

// HDF5's variable-length UTF-8 string, the type h5py returns as str.
H5::StrType string_type() {
  H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
  type.setCset(H5T_CSET_UTF8);
  return type;
}

void write_string_attribute(H5::H5Object& object, const std::string& name, const std::string& value) {
  const H5::StrType type = string_type();
  H5::Attribute attribute = object.createAttribute(name, type, H5::DataSpace(H5S_SCALAR));
  attribute.write(type, value);
}

void write_strings_attribute(H5::H5Object& object, const std::string& name,
                             const std::vector<std::string>& values) {
  const H5::StrType type = string_type();
  const hsize_t size = values.size();
  H5::Attribute attribute = object.createAttribute(name, type, H5::DataSpace(1, &size));
  std::vector<const char*> pointers;
  for (const std::string& value : values) pointers.push_back(value.c_str());
  if (!pointers.empty()) attribute.write(type, pointers.data());
}

void write_u64_attribute(H5::H5Object& object, const std::string& name, std::uint64_t value) {
  H5::Attribute attribute = object.createAttribute(name, H5::PredType::STD_U64LE, H5::DataSpace(H5S_SCALAR));
  attribute.write(H5::PredType::NATIVE_UINT64, &value);
}

void write_f64_attribute(H5::H5Object& object, const std::string& name, double value) {
  H5::Attribute attribute = object.createAttribute(name, H5::PredType::IEEE_F64LE, H5::DataSpace(H5S_SCALAR));
  attribute.write(H5::PredType::NATIVE_DOUBLE, &value);
}

// Objects are created without modification times (HDF5 tracks them by default), so the same
// campaign gives a byte-identical file whenever it runs, and a resumed run (checkpoint.hpp) the
// same file as an uninterrupted one. Every group and dataset of the file is made by these two
// (HDF5 makes the root group without times); attributes live in their object's header and carry
// no times of their own.
H5::DSetCreatPropList untimed_dataset() {
  H5::DSetCreatPropList properties;
  H5Pset_obj_track_times(properties.getId(), false);
  return properties;
}

H5::Group create_untimed_group(const H5::H5Location& parent, const std::string& name) {
  const hid_t properties = H5Pcreate(H5P_GROUP_CREATE);
  H5Pset_obj_track_times(properties, false);
  const hid_t id = H5Gcreate2(parent.getId(), name.c_str(), H5P_DEFAULT, properties, H5P_DEFAULT);
  H5Pclose(properties);
  if (id < 0) throw H5::GroupIException("create_untimed_group", "H5Gcreate2 failed for " + name);
  H5::Group group(id);  // takes its own reference
  H5Gclose(id);
  return group;
}

template <typename T>
H5::DataSet write_vector(H5::Group& group, const std::string& name, const H5::PredType& file_type,
                         const H5::PredType& memory_type, std::span<const T> values) {
  const hsize_t size = values.size();
  H5::DataSet dataset = group.createDataSet(name, file_type, H5::DataSpace(1, &size), untimed_dataset());
  if (!values.empty()) dataset.write(values.data(), memory_type);
  return dataset;
}

// A matrix as a 2-D row-major dataset (HDF5's and numpy's order; Eigen's default is column-major).
H5::DataSet write_matrix(H5::Group& group, const std::string& name, const Eigen::MatrixXd& matrix) {
  const hsize_t dims[2] = {static_cast<hsize_t>(matrix.rows()), static_cast<hsize_t>(matrix.cols())};
  H5::DataSet dataset = group.createDataSet(name, H5::PredType::IEEE_F64LE, H5::DataSpace(2, dims), untimed_dataset());
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> row_major = matrix;
  if (row_major.size() > 0) dataset.write(row_major.data(), H5::PredType::NATIVE_DOUBLE);
  return dataset;
}

H5::DataSet write_vector(H5::Group& group, const std::string& name, const Eigen::VectorXd& vector) {
  const hsize_t size = static_cast<hsize_t>(vector.size());
  H5::DataSet dataset = group.createDataSet(name, H5::PredType::IEEE_F64LE, H5::DataSpace(1, &size), untimed_dataset());
  if (vector.size() > 0) dataset.write(vector.data(), H5::PredType::NATIVE_DOUBLE);
  return dataset;
}

// One row of the summary table in memory; the vlen strings point into the QuantitySummary.
struct SummaryRow {
  const char* line;
  const char* quantity;
  const char* unit;
  std::uint64_t n;
  std::uint64_t n_flagged;
  double median, q1, q3, iqr, p10, p90, mean, sd, median_ci_low, median_ci_high;
};

void write_summary(H5::Group& group, const std::string& name, const std::vector<QuantitySummary>& summaries) {
  const H5::StrType text = string_type();
  H5::CompType memory(sizeof(SummaryRow));
  memory.insertMember("line", HOFFSET(SummaryRow, line), text);
  memory.insertMember("quantity", HOFFSET(SummaryRow, quantity), text);
  memory.insertMember("unit", HOFFSET(SummaryRow, unit), text);
  memory.insertMember("n", HOFFSET(SummaryRow, n), H5::PredType::NATIVE_UINT64);
  memory.insertMember("n_flagged", HOFFSET(SummaryRow, n_flagged), H5::PredType::NATIVE_UINT64);
  const std::pair<const char*, std::size_t> statistics[] = {
      {"median", HOFFSET(SummaryRow, median)}, {"q1", HOFFSET(SummaryRow, q1)},
      {"q3", HOFFSET(SummaryRow, q3)},         {"iqr", HOFFSET(SummaryRow, iqr)},
      {"p10", HOFFSET(SummaryRow, p10)},       {"p90", HOFFSET(SummaryRow, p90)},
      {"mean", HOFFSET(SummaryRow, mean)},     {"sd", HOFFSET(SummaryRow, sd)},
      {"median_ci_low", HOFFSET(SummaryRow, median_ci_low)},
      {"median_ci_high", HOFFSET(SummaryRow, median_ci_high)}};
  for (const auto& [member, offset] : statistics) memory.insertMember(member, offset, H5::PredType::NATIVE_DOUBLE);

  std::vector<SummaryRow> rows;
  for (const QuantitySummary& s : summaries) {
    rows.push_back({s.line.c_str(), s.quantity.c_str(), s.unit.c_str(), s.n, s.n_flagged, s.median, s.q1, s.q3,
                    s.iqr, s.p10, s.p90, s.mean, s.sd, s.median_ci_low, s.median_ci_high});
  }
  const hsize_t size = rows.size();
  H5::DataSet dataset = group.createDataSet(name, memory, H5::DataSpace(1, &size), untimed_dataset());
  if (!rows.empty()) dataset.write(rows.data(), memory);
}

void check_line_name(const std::string& name, const std::string& file) {
  if (name.empty() || name == "." || name.find('/') != std::string::npos) {
    throw_bad_value(file, "line", name, "a line name without '/' that is not empty or '.' (it names an HDF5 group)");
  }
}

std::vector<std::string> status_names() {
  std::vector<std::string> names;
  for (int code = 0; code <= static_cast<int>(last_sample_status); ++code) {
    names.emplace_back(to_string(static_cast<SampleStatus>(code)));
  }
  return names;
}

[[noreturn]] void rethrow_hdf5(const std::string& file, const H5::Exception& error) {
  throw WriteError(file, "HDF5 write failed in " + error.getFuncName() + ": " + error.getDetailMsg());
}

}  // namespace

struct ResultsH5Writer::File {
  std::string partial;
  H5::H5File file;
  RemovedOnSignal removed_on_signal{partial};  // a kill leaves no results.h5.partial
};

ResultsH5Writer::ResultsH5Writer(std::string path, Overwrite overwrite)
    : path_(std::move(path)), overwrite_(overwrite) {
  check_can_write(path_, overwrite_);
  // Errors reach the user as one InputError line, not as HDF5's stack dump on stderr.
  H5::Exception::dontPrint();
  const std::string partial = path_ + ".partial";
  prepare_partial_file(partial);
  try {
    file_ = std::make_unique<File>(partial, H5::H5File(partial, H5F_ACC_TRUNC));
    create_untimed_group(file_->file, "lines");
  } catch (const H5::Exception& error) {
    file_.reset();
    std::remove(partial.c_str());
    throw WriteError(partial, "cannot create the HDF5 file (" + error.getDetailMsg() + ")");
  }
}

void ResultsH5Writer::write_line(const LineResult& result, const std::vector<QuantitySummary>& summaries,
                                 const LineAnalysis& analysis) {
  if (!file_) throw std::logic_error("ResultsH5Writer::write_line after finish()");
  check_line_name(result.name, file_->partial);
  for (const std::string& written : lines_written_) {
    if (written == result.name) throw_bad_value(file_->partial, "line", result.name, "each line once");
  }
  const std::size_t samples = result.status.size();
  for (const ResultColumn& column : result.columns) {
    if (column.values.size() != samples) {
      throw std::invalid_argument("ResultsH5Writer::write_line: column " + column.column_name() + " has " +
                                  std::to_string(column.values.size()) + " values for " +
                                  std::to_string(samples) + " samples");
    }
  }
  try {
    H5::Group group = create_untimed_group(file_->file, "lines/" + result.name);
    write_u64_attribute(group, "samples", samples);
    for (const ResultColumn& column : result.columns) {
      H5::DataSet dataset = write_vector(group, column.column_name(), H5::PredType::IEEE_F64LE,
                                         H5::PredType::NATIVE_DOUBLE, std::span<const double>(column.values));
      write_string_attribute(dataset, "quantity", column.quantity);
      write_string_attribute(dataset, "unit", std::string(column.unit->symbol));
      write_string_attribute(dataset, "role", column.is_input ? "input" : "output");
    }
    std::vector<std::uint64_t> index(samples);
    std::iota(index.begin(), index.end(), std::uint64_t{0});
    write_vector(group, "sample", H5::PredType::STD_U64LE, H5::PredType::NATIVE_UINT64, std::span<const std::uint64_t>(index));
    std::vector<std::uint8_t> codes(samples);
    for (std::size_t i = 0; i < samples; ++i) codes[i] = static_cast<std::uint8_t>(result.status[i]);
    H5::DataSet status =
        write_vector(group, "status", H5::PredType::STD_U8LE, H5::PredType::NATIVE_UINT8, std::span<const std::uint8_t>(codes));
    write_strings_attribute(status, "names", status_names());

    write_summary(group, "summary", summaries);

    H5::Group correlation = create_untimed_group(group, "input_rank_correlation");
    write_strings_attribute(correlation, "names", result.correlated_inputs);
    write_matrix(correlation, "achieved", result.achieved_spearman);
    if (result.target_spearman.size() > 0) write_matrix(correlation, "target", result.target_spearman);

    H5::Group analysis_group = create_untimed_group(group, "analysis");
    write_u64_attribute(analysis_group, "samples_used", analysis.samples_used);
    write_strings_attribute(analysis_group, "notes", analysis.notes);
    H5::DataSet spearman = write_matrix(analysis_group, "input_output_spearman", analysis.input_output_spearman);
    write_strings_attribute(spearman, "rows", analysis.inputs);
    write_strings_attribute(spearman, "columns", analysis.outputs);
    write_vector(analysis_group, "explained_variance_ratio", analysis.explained_variance_ratio);
    H5::DataSet loadings = write_matrix(analysis_group, "loadings", analysis.loadings);
    write_strings_attribute(loadings, "rows", analysis.pca_names);
  } catch (const H5::Exception& error) {
    rethrow_hdf5(file_->partial, error);
  }
  lines_written_.push_back(result.name);
  summaries_.insert(summaries_.end(), summaries.begin(), summaries.end());
}

void ResultsH5Writer::finish(const CampaignMetadata& metadata) {
  if (!file_) throw std::logic_error("ResultsH5Writer::finish called twice");
  const std::string partial = file_->partial;
  try {
    H5::Group root = file_->file.openGroup("/");
    write_summary(root, "summary", summaries_);
    write_string_attribute(root, "campaign_text", metadata.campaign_text);
    write_string_attribute(root, "campaign_path", metadata.campaign_path);
    write_string_attribute(root, "command_line", metadata.command_line);
    write_string_attribute(root, "engine_version", metadata.engine_version);
    write_u64_attribute(root, "seed", metadata.seed);
    write_f64_attribute(root, "kappa", metadata.kappa);
    write_u64_attribute(root, "samples_per_line", metadata.samples_per_line);
    root.close();
    file_->file.close();
  } catch (const H5::Exception& error) {
    rethrow_hdf5(partial, error);
  }
  file_.reset();
  try {
    check_can_write(path_, overwrite_);  // a file that appeared meanwhile is not replaced silently
  } catch (const InputError&) {
    std::remove(partial.c_str());
    throw;
  }
  move_into_place(partial, path_);
}

ResultsH5Writer::~ResultsH5Writer() {
  if (!file_) return;
  const std::string partial = file_->partial;
  try {
    file_->file.close();
  } catch (...) {
    // Closing failed: the file is removed below either way.
  }
  file_.reset();
  std::remove(partial.c_str());
}

namespace {

// The group at `path` ("a/b/c"), creating missing components.
H5::Group group_at(H5::H5File& file, const std::string& path) {
  H5::Group group = file.openGroup("/");
  std::size_t start = 0;
  while (start < path.size()) {
    const std::size_t slash = std::min(path.find('/', start), path.size());
    const std::string name = path.substr(start, slash - start);
    if (!name.empty()) group = group.nameExists(name) ? group.openGroup(name) : create_untimed_group(group, name);
    start = slash + 1;
  }
  return group;
}

// (parent group path, leaf name) of "a/b/leaf".
std::pair<std::string, std::string> split_path(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return {"", path};
  return {path.substr(0, slash), path.substr(slash + 1)};
}

}  // namespace

void ResultsH5Writer::write_table(const std::string& path, const std::vector<ExtraColumn>& columns) {
  if (!file_) throw std::logic_error("ResultsH5Writer::write_table after finish()");
  // Row layout: each member 8 bytes (a char* for text, a double or an int64).
  std::size_t rows = 0;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const ExtraColumn& column = columns[c];
    const std::size_t filled = (column.text.empty() ? 0 : 1) + (column.real.empty() ? 0 : 1) + (column.integer.empty() ? 0 : 1);
    const std::size_t size = column.text.size() + column.real.size() + column.integer.size();
    if (filled > 1 || (c > 0 && size != rows)) {
      throw std::invalid_argument("ResultsH5Writer::write_table " + path + ": column " + column.name +
                                  " has another length or more than one type");
    }
    rows = size;
  }
  const std::size_t width = 8 * columns.size();
  std::vector<unsigned char> buffer(std::max<std::size_t>(1, rows * width));
  try {
    H5::CompType type(std::max<std::size_t>(width, 1));
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const ExtraColumn& column = columns[c];
      const std::size_t offset = 8 * c;
      if (!column.real.empty() || (column.text.empty() && column.integer.empty())) {
        type.insertMember(column.name, offset, H5::PredType::NATIVE_DOUBLE);
        for (std::size_t r = 0; r < column.real.size(); ++r) std::memcpy(&buffer[r * width + offset], &column.real[r], 8);
      } else if (!column.integer.empty()) {
        type.insertMember(column.name, offset, H5::PredType::NATIVE_INT64);
        for (std::size_t r = 0; r < rows; ++r) std::memcpy(&buffer[r * width + offset], &column.integer[r], 8);
      } else {
        type.insertMember(column.name, offset, string_type());
        for (std::size_t r = 0; r < rows; ++r) {
          const char* text = column.text[r].c_str();
          std::memcpy(&buffer[r * width + offset], &text, sizeof text);
        }
      }
    }
    const auto [parent, leaf] = split_path(path);
    H5::Group group = group_at(file_->file, parent);
    const hsize_t size = rows;
    H5::DataSet dataset = group.createDataSet(leaf, type, H5::DataSpace(1, &size), untimed_dataset());
    if (rows > 0) dataset.write(buffer.data(), type);
  } catch (const H5::Exception& error) {
    rethrow_hdf5(file_->partial, error);
  }
}

void ResultsH5Writer::write_array(const std::string& path, const std::vector<double>& values) {
  if (!file_) throw std::logic_error("ResultsH5Writer::write_array after finish()");
  try {
    const auto [parent, leaf] = split_path(path);
    H5::Group group = group_at(file_->file, parent);
    write_vector(group, leaf, H5::PredType::IEEE_F64LE, H5::PredType::NATIVE_DOUBLE, std::span<const double>(values));
  } catch (const H5::Exception& error) {
    rethrow_hdf5(file_->partial, error);
  }
}

void ResultsH5Writer::write_array(const std::string& path, const std::vector<std::int32_t>& values) {
  if (!file_) throw std::logic_error("ResultsH5Writer::write_array after finish()");
  try {
    const auto [parent, leaf] = split_path(path);
    H5::Group group = group_at(file_->file, parent);
    write_vector(group, leaf, H5::PredType::STD_I32LE, H5::PredType::NATIVE_INT32, std::span<const std::int32_t>(values));
  } catch (const H5::Exception& error) {
    rethrow_hdf5(file_->partial, error);
  }
}

namespace {

// Calls write(object) on the dataset at `path` when there is one, else on the group at `path`
// (created when missing).
template <typename Write>
void write_on_object(H5::H5File& file, const std::string& path, Write write) {
  const auto [parent, leaf] = split_path(path);
  H5::Group group = group_at(file, parent);
  if (!leaf.empty() && group.nameExists(leaf) && group.childObjType(leaf) == H5O_TYPE_DATASET) {
    H5::DataSet dataset = group.openDataSet(leaf);
    write(dataset);
  } else {
    H5::Group target = group_at(file, path);
    write(target);
  }
}

}  // namespace

void ResultsH5Writer::write_attribute(const std::string& path, const std::string& name, const std::string& value) {
  if (!file_) throw std::logic_error("ResultsH5Writer::write_attribute after finish()");
  try {
    write_on_object(file_->file, path, [&](H5::H5Object& object) { write_string_attribute(object, name, value); });
  } catch (const H5::Exception& error) {
    rethrow_hdf5(file_->partial, error);
  }
}

void ResultsH5Writer::write_attribute(const std::string& path, const std::string& name, double value) {
  if (!file_) throw std::logic_error("ResultsH5Writer::write_attribute after finish()");
  try {
    write_on_object(file_->file, path, [&](H5::H5Object& object) { write_f64_attribute(object, name, value); });
  } catch (const H5::Exception& error) {
    rethrow_hdf5(file_->partial, error);
  }
}

}  // namespace growthuq
