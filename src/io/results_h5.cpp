#include "growthuq/io/results_h5.hpp"

#include <H5Cpp.h>
#include <hdf5_hl.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <variant>

#include "growthuq/core/interrupt.hpp"
#include "hdf5_output_file.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/units.hpp"

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

// With `in_creation_order` the group indexes its links by creation order too, which h5py
// follows when iterating (f["lines"] lists the lines as the campaign does, not alphabetically).
H5::Group create_untimed_group(const H5::H5Location& parent, const std::string& name, bool in_creation_order = false) {
  const hid_t properties = H5Pcreate(H5P_GROUP_CREATE);
  H5Pset_obj_track_times(properties, false);
  if (in_creation_order) H5Pset_link_creation_order(properties, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
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

// A column of a line's samples: NaN where the sample lacks the quantity (its model did not
// compute it), declared as the netCDF/CF missing value, both as the dataset's fill value and as
// the `_FillValue` attribute (as netCDF-4 and h5netcdf write it), so xarray, and CF tools that
// do not treat NaN as missing by themselves, read those cells as missing.
H5::DataSet write_sample_column(H5::Group& group, const std::string& name, std::span<const double> values) {
  const double missing = std::numeric_limits<double>::quiet_NaN();
  H5::DSetCreatPropList properties = untimed_dataset();
  properties.setFillValue(H5::PredType::NATIVE_DOUBLE, &missing);
  const hsize_t size = values.size();
  H5::DataSet dataset = group.createDataSet(name, H5::PredType::IEEE_F64LE, H5::DataSpace(1, &size), properties);
  if (!values.empty()) dataset.write(values.data(), H5::PredType::NATIVE_DOUBLE);
  write_f64_attribute(dataset, "_FillValue", missing);
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

// Dimension scales (the HDF5 high-level H5DS API, as netCDF-4 writes them): xarray (engine
// h5netcdf) names each axis of a dataset after the scale attached to it, so
// xarray.open_dataset(path, group="lines/wild_type", engine="h5netcdf") has a dimension
// `sample` instead of phony_dim_0, and opens at all without phony_dims. A dimension is a 1-D
// dataset in the same group, named like it: an index (IndexValues below) or labels (strings,
// e.g. the input names of a correlation matrix).
std::size_t length_of(const H5::DataSet& dataset) {
  hsize_t length = 0;
  dataset.getSpace().getSimpleExtentDims(&length);
  return static_cast<std::size_t>(length);
}

void make_dimension(const H5::DataSet& dataset, const std::string& name) {
  if (H5DSset_scale(dataset.getId(), name.c_str()) < 0) {
    throw H5::DataSetIException("H5DSset_scale", "cannot make " + name + " a dimension scale");
  }
}

void attach_dimension(const H5::DataSet& dataset, const H5::DataSet& dimension, unsigned axis) {
  if (H5DSattach_scale(dataset.getId(), dimension.getId(), axis) < 0) {
    throw H5::DataSetIException("H5DSattach_scale", "cannot attach a dimension scale");
  }
}

// What an index dimension holds. `sample` keeps 0 .. n-1 (the samples' index, read as such).
// The others (table rows, curve points, components, replicates) are netCDF's "dimension but
// not a variable": a dataset of the dimension's length that is never written, so it takes no
// room in the file (stored, the `point` index of the relaxation curves made a raw-data
// results.h5 30 % larger at 50 samples per line, measured); xarray shows it as a dimension
// without coordinate and h5py reads zeros.
enum class IndexValues { stored, none };

constexpr const char* not_a_variable = "This is a netCDF dimension but not a netCDF variable.";

// The index dimension `name` of `group` (created on first use), or, when `group` already has a
// dataset of that name with another length, the index dimension "<name>_<length>".
H5::DataSet index_dimension(H5::Group& group, const std::string& name, std::size_t length,
                            IndexValues values = IndexValues::none) {
  if (group.nameExists(name)) {
    H5::DataSet existing = group.openDataSet(name);
    if (length_of(existing) == length) return existing;
    return index_dimension(group, name + "_" + std::to_string(length), length, values);
  }
  if (values == IndexValues::none) {
    H5::DSetCreatPropList properties = untimed_dataset();
    properties.setFillTime(H5D_FILL_TIME_NEVER);  // with late allocation (contiguous): no storage at all
    const hsize_t size = length;
    H5::DataSet dimension = group.createDataSet(name, H5::PredType::STD_U64LE, H5::DataSpace(1, &size), properties);
    char scale_name[80];
    std::snprintf(scale_name, sizeof scale_name, "%s%10zu", not_a_variable, length);  // as netCDF-4 names it
    make_dimension(dimension, scale_name);
    return dimension;
  }
  std::vector<std::uint64_t> index(length);
  std::iota(index.begin(), index.end(), std::uint64_t{0});
  H5::DataSet dimension = write_vector(group, name, H5::PredType::STD_U64LE, H5::PredType::NATIVE_UINT64,
                                       std::span<const std::uint64_t>(index));
  make_dimension(dimension, name);
  write_string_attribute(dimension, "units", "1");
  return dimension;
}

// The label dimension `name` holding `labels` for an axis of `length` (created on first use).
// Labels that do not fit the axis (an empty matrix of a line without analysis) or a dimension
// of that name holding other labels give the index dimension "<name>_<length>" instead.
H5::DataSet label_dimension(H5::Group& group, const std::string& name, const std::vector<std::string>& labels,
                            std::size_t length) {
  if (labels.size() != length) return index_dimension(group, name + "_" + std::to_string(length), length);
  const H5::StrType type = string_type();
  if (group.nameExists(name)) {
    H5::DataSet existing = group.openDataSet(name);
    bool same = length_of(existing) == length;
    if (same && length > 0) {
      std::vector<char*> stored(length);
      existing.read(stored.data(), type);
      for (std::size_t i = 0; i < length; ++i) same = same && labels[i] == stored[i];
      H5Dvlen_reclaim(type.getId(), existing.getSpace().getId(), H5P_DEFAULT, stored.data());
    }
    return same ? existing : index_dimension(group, name + "_" + std::to_string(length), length);
  }
  const hsize_t size = length;
  H5::DataSet dimension = group.createDataSet(name, type, H5::DataSpace(1, &size), untimed_dataset());
  std::vector<const char*> pointers;
  for (const std::string& label : labels) pointers.push_back(label.c_str());
  if (!pointers.empty()) dimension.write(pointers.data(), type);
  make_dimension(dimension, name);
  return dimension;
}

// A matrix whose rows and columns are named: dimensions `row_dimension` and `column_dimension`
// holding the names (units "1": the matrices are rank correlations).
H5::DataSet write_named_matrix(H5::Group& group, const std::string& name, const Eigen::MatrixXd& matrix,
                               const std::string& row_dimension, const std::vector<std::string>& rows,
                               const std::string& column_dimension, const std::vector<std::string>& columns) {
  H5::DataSet dataset = write_matrix(group, name, matrix);
  write_string_attribute(dataset, "units", "1");
  attach_dimension(dataset, label_dimension(group, row_dimension, rows, static_cast<std::size_t>(matrix.rows())), 0);
  attach_dimension(dataset, label_dimension(group, column_dimension, columns, static_cast<std::size_t>(matrix.cols())), 1);
  return dataset;
}

// One row of the summary table in memory; the vlen strings point into the QuantitySummary.
struct SummaryRow {
  const char* line;
  const char* quantity;
  const char* unit;
  std::uint64_t n;
  std::uint64_t n_flagged;
  double median, q1, q3, iqr, p10, p90, mean, sd, median_ci_low, median_ci_high, data_ci_low, data_ci_high;
};

H5::CompType summary_type() {
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
      {"median_ci_high", HOFFSET(SummaryRow, median_ci_high)},
      {"data_ci_low", HOFFSET(SummaryRow, data_ci_low)},
      {"data_ci_high", HOFFSET(SummaryRow, data_ci_high)}};
  for (const auto& [member, offset] : statistics) memory.insertMember(member, offset, H5::PredType::NATIVE_DOUBLE);
  return memory;
}

std::vector<SummaryRow> summary_rows(const std::vector<QuantitySummary>& summaries) {
  std::vector<SummaryRow> rows;
  for (const QuantitySummary& s : summaries) {
    rows.push_back({s.line.c_str(), s.quantity.c_str(), s.unit.c_str(), s.n, s.n_flagged, s.median, s.q1, s.q3, s.iqr,
                    s.p10, s.p90, s.mean, s.sd, s.median_ci_low, s.median_ci_high, s.data_ci_low, s.data_ci_high});
  }
  return rows;
}

void write_summary(H5::Group& group, const std::string& name, const std::vector<QuantitySummary>& summaries) {
  const H5::CompType memory = summary_type();
  const std::vector<SummaryRow> rows = summary_rows(summaries);
  const hsize_t size = rows.size();
  H5::DataSet dataset = group.createDataSet(name, memory, H5::DataSpace(1, &size), untimed_dataset());
  if (!rows.empty()) dataset.write(rows.data(), memory);
  attach_dimension(dataset, index_dimension(group, name + "_row", rows.size()), 0);
}

// A result column as results.h5 stores it: in its quantity's default unit whatever unit the line
// file used, so a quantity has one dataset name in every line (einf_frac whether a line file
// gives einf in % or as a fraction; samples.csv keeps the line file's unit). Converted through
// SI (x * from.to_si / to.to_si), as exact as any decimal rescaling. A quantity the engine does
// not know keeps its unit.
struct StoredColumn {
  std::string name;
  const Unit* unit;
  std::string long_name;     // the quantity's description, for plot labels
  std::vector<double> converted;  // empty when the column is stored as it is
};

StoredColumn stored_column(const ResultColumn& column) {
  const Quantity* quantity = find_quantity(column.quantity);
  StoredColumn stored{column.column_name(), column.unit, column.quantity, {}};
  if (quantity == nullptr) return stored;
  stored.long_name = std::string(quantity->description);
  if (column.unit->symbol == quantity->default_unit) return stored;
  stored.unit = &find_unit(quantity->default_unit, "results.h5", column.quantity);
  stored.name = column_name(column.quantity, *stored.unit);
  stored.converted.reserve(column.values.size());
  for (const double value : column.values) stored.converted.push_back(value * column.unit->to_si / stored.unit->to_si);
  return stored;
}

// Column names of the line file (as the analysis names its rows) renamed as stored.
std::vector<std::string> stored_names(const std::vector<std::string>& names, const std::vector<StoredColumn>& stored,
                                      const std::vector<ResultColumn>& columns) {
  std::vector<std::string> renamed = names;
  for (std::string& name : renamed) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (columns[c].column_name() == name) name = stored[c].name;
    }
  }
  return renamed;
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

}  // namespace

// The partial file: written through hdf5::OutputFile (no crash, no diagnostics on a full disk:
// io/hdf5_output_file.hpp), removed by a signal that ends the process.
struct ResultsH5Writer::File {
  std::string partial;
  hdf5::OutputFile out{partial};
  RemovedOnSignal removed_on_signal{partial};  // a kill leaves no results.h5.partial
  H5::H5File& file = out.file();
};

ResultsH5Writer::ResultsH5Writer(std::string path, Overwrite overwrite)
    : path_(std::move(path)), overwrite_(overwrite) {
  check_can_write(path_, overwrite_);
  // Errors reach the user as one InputError line, not as HDF5's stack dump on stderr.
  hdf5::use_error_handler();
  const std::string partial = path_ + ".partial";
  prepare_partial_file(partial);
  try {
    file_ = std::make_unique<File>(partial);
    try {
      create_untimed_group(file_->file, "lines", /*in_creation_order=*/true);
    } catch (const H5::Exception& error) {
      file_->out.rethrow(error);
    }
  } catch (const InputError&) {
    file_.reset();
    std::remove(partial.c_str());
    throw;
  }
}

void ResultsH5Writer::declare_lines(const std::vector<std::string>& names) {
  if (!file_) throw std::logic_error("ResultsH5Writer::declare_lines after finish()");
  hdf5::use_error_handler();  // per thread: results.h5 is written on a thread of its own
  if (!lines_written_.empty() || !lines_declared_.empty()) throw std::logic_error("ResultsH5Writer::declare_lines: too late");
  try {
    for (const std::string& name : names) {
      check_line_name(name, file_->partial);
      create_untimed_group(file_->file, "lines/" + name);
    }
  } catch (const H5::Exception& error) {
    file_->out.rethrow(error);
  }
  file_->out.throw_if_failed();
  lines_declared_ = names;
}

void ResultsH5Writer::write_line(const LineResult& result, const std::vector<QuantitySummary>& summaries,
                                 const LineAnalysis& analysis) {
  if (!file_) throw std::logic_error("ResultsH5Writer::write_line after finish()");
  hdf5::use_error_handler();  // per thread: results.h5 is written on a thread of its own
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
    const bool declared = std::find(lines_declared_.begin(), lines_declared_.end(), result.name) != lines_declared_.end();
    H5::Group group = declared ? file_->file.openGroup("lines/" + result.name)
                               : create_untimed_group(file_->file, "lines/" + result.name);
    write_u64_attribute(group, "samples", samples);
    // `sample` (0-based index of the sample in its line) is the dimension of every column.
    const H5::DataSet sample = index_dimension(group, "sample", samples, IndexValues::stored);
    std::vector<StoredColumn> stored;
    for (const ResultColumn& column : result.columns) {
      stored.push_back(stored_column(column));
      const StoredColumn& as_stored = stored.back();
      const std::span<const double> values =
          as_stored.converted.empty() ? std::span<const double>(column.values) : std::span<const double>(as_stored.converted);
      H5::DataSet dataset = write_sample_column(group, as_stored.name, values);
      attach_dimension(dataset, sample, 0);
      write_string_attribute(dataset, "quantity", column.quantity);
      write_string_attribute(dataset, "unit", std::string(as_stored.unit->symbol));
      write_string_attribute(dataset, "units", std::string(as_stored.unit->symbol));
      write_string_attribute(dataset, "long_name", as_stored.long_name);
      write_string_attribute(dataset, "role", column.is_input ? "input" : "output");
    }
    std::vector<std::string> column_order;  // HDF5 lists datasets alphabetically; samples.csv's order
    for (const StoredColumn& column : stored) column_order.push_back(column.name);
    write_strings_attribute(group, "columns", column_order);
    std::vector<std::uint8_t> codes(samples);
    for (std::size_t i = 0; i < samples; ++i) codes[i] = static_cast<std::uint8_t>(result.status[i]);
    H5::DataSet status =
        write_vector(group, "status", H5::PredType::STD_U8LE, H5::PredType::NATIVE_UINT8, std::span<const std::uint8_t>(codes));
    attach_dimension(status, sample, 0);
    write_strings_attribute(status, "names", status_names());
    write_string_attribute(status, "units", "1");

    write_summary(group, "summary", summaries);

    H5::Group correlation = create_untimed_group(group, "input_rank_correlation");
    write_strings_attribute(correlation, "names", result.correlated_inputs);
    write_named_matrix(correlation, "achieved", result.achieved_spearman, "row", result.correlated_inputs, "column",
                       result.correlated_inputs);
    if (result.target_spearman.size() > 0) {
      write_named_matrix(correlation, "target", result.target_spearman, "row", result.correlated_inputs, "column",
                         result.correlated_inputs);
    }

    H5::Group analysis_group = create_untimed_group(group, "analysis");
    write_u64_attribute(analysis_group, "samples_used", analysis.samples_used);
    write_strings_attribute(analysis_group, "notes", analysis.notes);
    const std::vector<std::string> inputs = stored_names(analysis.inputs, stored, result.columns);
    const std::vector<std::string> outputs = stored_names(analysis.outputs, stored, result.columns);
    const std::vector<std::string> variables = stored_names(analysis.pca_names, stored, result.columns);
    H5::DataSet spearman =
        write_named_matrix(analysis_group, "input_output_spearman", analysis.input_output_spearman, "input", inputs, "output", outputs);
    write_strings_attribute(spearman, "rows", inputs);
    write_strings_attribute(spearman, "columns", outputs);
    const std::size_t components = static_cast<std::size_t>(analysis.explained_variance_ratio.size());
    H5::DataSet ratio = write_vector(analysis_group, "explained_variance_ratio", analysis.explained_variance_ratio);
    write_string_attribute(ratio, "units", "1");
    attach_dimension(ratio, index_dimension(analysis_group, "component", components), 0);
    H5::DataSet loadings = write_matrix(analysis_group, "loadings", analysis.loadings);
    write_string_attribute(loadings, "units", "1");
    write_strings_attribute(loadings, "rows", variables);
    attach_dimension(loadings, label_dimension(analysis_group, "variable", variables, static_cast<std::size_t>(analysis.loadings.rows())), 0);
    attach_dimension(loadings, index_dimension(analysis_group, "component", static_cast<std::size_t>(analysis.loadings.cols())), 1);
  } catch (const H5::Exception& error) {
    file_->out.rethrow(error);
  }
  file_->out.throw_if_failed();
  lines_written_.push_back(result.name);
  summaries_.insert(summaries_.end(), summaries.begin(), summaries.end());
}

void ResultsH5Writer::replace_summaries(const std::vector<QuantitySummary>& summaries) {
  if (!file_) throw std::logic_error("ResultsH5Writer::replace_summaries called after finish");
  hdf5::use_error_handler();  // per thread: results.h5 is written on a thread of its own
  if (summaries.size() != summaries_.size()) throw std::invalid_argument("replace_summaries: not the rows written");
  try {
    for (const std::string& line : lines_written_) {
      std::vector<QuantitySummary> rows;
      for (const QuantitySummary& summary : summaries) {
        if (summary.line == line) rows.push_back(summary);
      }
      H5::DataSet dataset = file_->file.openDataSet("lines/" + line + "/summary");
      if (dataset.getSpace().getSimpleExtentNpoints() != static_cast<hssize_t>(rows.size())) {
        throw std::invalid_argument("replace_summaries: line " + line + " has another number of rows");
      }
      if (!rows.empty()) dataset.write(summary_rows(rows).data(), summary_type());
    }
  } catch (const H5::Exception& error) {
    file_->out.rethrow(error);
  }
  file_->out.throw_if_failed();
  summaries_ = summaries;
}

void ResultsH5Writer::finish(const CampaignMetadata& metadata) {
  if (!file_) throw std::logic_error("ResultsH5Writer::finish called twice");
  hdf5::use_error_handler();  // per thread: results.h5 is written on a thread of its own
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
    write_strings_attribute(root, "line_order", lines_declared_.empty() ? lines_written_ : lines_declared_);
    root.close();
  } catch (const H5::Exception& error) {
    file_->out.rethrow(error);
  }
  // The room checked, everything flushed, the file closed; the file's last metadata reach the
  // disk here, so a full disk may show only now.
  try {
    file_->out.close();
  } catch (const InputError&) {
    file_.reset();
    std::remove(partial.c_str());
    throw;
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
  file_.reset();  // hdf5::OutputFile closes it into memory, never throwing
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
  hdf5::use_error_handler();  // per thread: results.h5 is written on a thread of its own
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
    std::vector<std::string> units;
    for (const ExtraColumn& column : columns) units.push_back(column.unit);
    write_strings_attribute(dataset, "column_units", units);
    attach_dimension(dataset, index_dimension(group, leaf + "_row", rows), 0);
  } catch (const H5::Exception& error) {
    file_->out.rethrow(error);
  }
  file_->out.throw_if_failed();
}

namespace {

template <typename T>
void write_array_at(H5::H5File& file, const std::string& path, const H5::PredType& file_type, const H5::PredType& memory_type,
                    std::span<const T> values, const std::string& unit, const std::string& dimension) {
  const auto [parent, leaf] = split_path(path);
  H5::Group group = group_at(file, parent);
  H5::DataSet dataset = write_vector(group, leaf, file_type, memory_type, values);
  write_string_attribute(dataset, "units", unit);
  attach_dimension(dataset, index_dimension(group, dimension, values.size()), 0);
}

}  // namespace

void ResultsH5Writer::write_array(const std::string& path, const std::vector<double>& values, const std::string& unit,
                                  const std::string& dimension) {
  if (!file_) throw std::logic_error("ResultsH5Writer::write_array after finish()");
  hdf5::use_error_handler();  // per thread: results.h5 is written on a thread of its own
  try {
    write_array_at(file_->file, path, H5::PredType::IEEE_F64LE, H5::PredType::NATIVE_DOUBLE, std::span<const double>(values),
                   unit, dimension);
  } catch (const H5::Exception& error) {
    file_->out.rethrow(error);
  }
  file_->out.throw_if_failed();
}

void ResultsH5Writer::write_array(const std::string& path, const std::vector<std::int32_t>& values, const std::string& unit,
                                  const std::string& dimension) {
  if (!file_) throw std::logic_error("ResultsH5Writer::write_array after finish()");
  hdf5::use_error_handler();  // per thread: results.h5 is written on a thread of its own
  try {
    write_array_at(file_->file, path, H5::PredType::STD_I32LE, H5::PredType::NATIVE_INT32,
                   std::span<const std::int32_t>(values), unit, dimension);
  } catch (const H5::Exception& error) {
    file_->out.rethrow(error);
  }
  file_->out.throw_if_failed();
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
  write_attribute_value(path, name, value);
}

void ResultsH5Writer::write_attribute(const std::string& path, const std::string& name, double value) {
  write_attribute_value(path, name, value);
}

void ResultsH5Writer::write_attribute(const std::string& path, const std::string& name, std::uint64_t value) {
  write_attribute_value(path, name, value);
}

void ResultsH5Writer::write_attribute_value(const std::string& path, const std::string& name,
                                            const std::variant<std::string, double, std::uint64_t>& value) {
  if (!file_) throw std::logic_error("ResultsH5Writer::write_attribute after finish()");
  hdf5::use_error_handler();  // per thread: results.h5 is written on a thread of its own
  try {
    write_on_object(file_->file, path, [&](H5::H5Object& object) {
      if (const auto* text = std::get_if<std::string>(&value)) write_string_attribute(object, name, *text);
      if (const auto* real = std::get_if<double>(&value)) write_f64_attribute(object, name, *real);
      if (const auto* count = std::get_if<std::uint64_t>(&value)) write_u64_attribute(object, name, *count);
    });
  } catch (const H5::Exception& error) {
    file_->out.rethrow(error);
  }
  file_->out.throw_if_failed();
}

}  // namespace growthuq
