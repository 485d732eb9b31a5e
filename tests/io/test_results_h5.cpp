// results.h5: every dataset and attribute read back with the HDF5 C++ API and compared exactly,
// the same file checked from Python with h5py (the users' reader), and the file's life cycle
// (.partial while writing, removed when abandoned, existing results never overwritten silently,
// no times recorded, so the bytes depend on the results only).
#include <doctest/doctest.h>

#include <H5Cpp.h>
#include <hdf5_hl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <thread>

#include "growthuq/core/error.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/io/results_h5.hpp"
#include "growthuq/stats/quantity_summary.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

constexpr double missing = std::numeric_limits<double>::quiet_NaN();

// A scratch folder that names its files as the writer takes them.
struct Scratch : ScratchDirectory {
  explicit Scratch(const std::string& name) : ScratchDirectory("results_h5_" + name) {}
  std::string path(const std::string& file) const { return (root / file).string(); }
};

ResultColumn column_of(const char* quantity, const char* unit, bool is_input, std::vector<double> values) {
  ResultColumn column;
  column.quantity = quantity;
  column.unit = &find_unit(unit, "test", "unit");
  column.is_input = is_input;
  column.values.assign(values.begin(), values.end());
  return column;
}

// The data the Python check (check_results_h5.py) expects too: keep them in step.
LineResult wild_type() {
  LineResult line;
  line.name = "wild_type";
  line.columns = {column_of("k", "N/m", true, {2.87, 3.1, 2.2, 4.05, 1.9, 2.5}),
                  column_of("d0", "um", true, {5.35, 5.9, 4.8, 6.2, 5.0, 5.1}),
                  column_of("einf", "%", true, {65, 70, 55, 80, 60, 72}),  // stored as einf_frac
                  column_of("p", "MPa", false, {0.31, missing, 0.22, 0.45, 0.18, 0.27}),
                  column_of("v", "um/s", false, {0.028, missing, 0.0, 0.041, 0.012, 0.02})};
  line.status = {SampleStatus::ok, SampleStatus::burst, SampleStatus::no_growth,
                 SampleStatus::ok, SampleStatus::ok,    SampleStatus::ok};
  line.correlated_inputs = {"k", "d0"};
  line.target_spearman.resize(2, 2);
  line.target_spearman << 1, 0.3, 0.3, 1;
  line.achieved_spearman.resize(2, 2);
  line.achieved_spearman << 1, 0.2857142857142857, 0.2857142857142857, 1;
  return line;
}

LineResult xxt1_xxt2() {
  LineResult line;
  line.name = "xxt1 xxt2";
  line.columns = {column_of("k", "N/m", true, {1.5, 2.5}), column_of("p", "MPa", false, {missing, missing})};
  line.status = {SampleStatus::lambda_not_above_one, SampleStatus::invalid_input};
  line.correlated_inputs = {"k"};
  line.achieved_spearman = Eigen::MatrixXd::Identity(1, 1);
  return line;
}

std::vector<QuantitySummary> summaries_of(const LineResult& line) {
  std::vector<QuantitySummary> summaries;
  for (const ResultColumn& column : line.columns) summaries.push_back(summarize_quantity(line.name, column));
  return summaries;
}

CampaignMetadata metadata() {
  CampaignMetadata m;
  m.campaign_text = "[campaign]\nsamples = 6\nseed = 42\n# \xc2\xb5m and a newline\n";
  m.campaign_path = "campaigns/test.ini";
  m.command_line = "growthuq run campaigns/test.ini --out results";
  m.engine_version = "0.1.0";
  m.seed = 18446744073709551557ULL;  // the largest 64-bit prime: every bit of the seed survives
  m.kappa = 0.8125;
  m.samples_per_line = 6;
  return m;
}

// The campaign's order is not alphabetical: the file records it (attribute line_order, and /lines
// lists its groups in it).
void write_campaign(const std::string& path, Overwrite overwrite = Overwrite::refuse) {
  ResultsH5Writer writer(path, overwrite);
  for (const LineResult& line : {xxt1_xxt2(), wild_type()}) writer.write_line(line, summaries_of(line), analyze_line(line));
  writer.finish(metadata());
}

// Reading back through the C++ API.
std::string read_string(const H5::H5Object& object, const std::string& name) {
  const H5::Attribute attribute = object.openAttribute(name);
  std::string value;
  attribute.read(attribute.getStrType(), value);
  return value;
}

std::vector<std::string> read_strings(const H5::H5Object& object, const std::string& name) {
  const H5::Attribute attribute = object.openAttribute(name);
  const H5::DataSpace space = attribute.getSpace();
  std::vector<char*> pointers(static_cast<std::size_t>(space.getSimpleExtentNpoints()));
  const H5::StrType type = attribute.getStrType();
  CHECK(type.isVariableStr());
  CHECK(type.getCset() == H5T_CSET_UTF8);
  if (pointers.empty()) return {};
  attribute.read(type, pointers.data());
  std::vector<std::string> values(pointers.begin(), pointers.end());
  H5Dvlen_reclaim(type.getId(), space.getId(), H5P_DEFAULT, pointers.data());
  return values;
}

template <typename T>
T read_scalar(const H5::H5Object& object, const std::string& name, const H5::PredType& type) {
  T value{};
  object.openAttribute(name).read(type, &value);
  return value;
}

std::vector<double> read_doubles(const H5::DataSet& dataset, std::vector<hsize_t>* dims = nullptr) {
  const H5::DataSpace space = dataset.getSpace();
  std::vector<hsize_t> shape(static_cast<std::size_t>(space.getSimpleExtentNdims()));
  space.getSimpleExtentDims(shape.data());
  if (dims != nullptr) *dims = shape;
  CHECK(dataset.getDataType() == H5::PredType::IEEE_F64LE);
  std::vector<double> values(static_cast<std::size_t>(space.getSimpleExtentNpoints()));
  if (!values.empty()) dataset.read(values.data(), H5::PredType::NATIVE_DOUBLE);
  return values;
}

// Bitwise equality, so NaN cells compare equal to NaN cells.
bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

void check_same(const std::vector<double>& actual, const std::vector<double>& expected) {
  REQUIRE(actual.size() == expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    CAPTURE(i);
    CHECK(same(actual[i], expected[i]));
  }
}

// Row-major values of an Eigen matrix, as the file stores them.
std::vector<double> row_major(const Eigen::MatrixXd& matrix) {
  std::vector<double> values;
  for (Eigen::Index r = 0; r < matrix.rows(); ++r)
    for (Eigen::Index c = 0; c < matrix.cols(); ++c) values.push_back(matrix(r, c));
  return values;
}

struct SummaryRow {
  char* line;
  char* quantity;
  char* unit;
  std::uint64_t n, n_flagged;
  double median, q1, q3, iqr, p10, p90, mean, sd, median_ci_low, median_ci_high;
};

std::vector<QuantitySummary> read_summary(const H5::DataSet& dataset) {
  const H5::StrType text(H5::PredType::C_S1, H5T_VARIABLE);
  H5::CompType type(sizeof(SummaryRow));
  type.insertMember("line", HOFFSET(SummaryRow, line), text);
  type.insertMember("quantity", HOFFSET(SummaryRow, quantity), text);
  type.insertMember("unit", HOFFSET(SummaryRow, unit), text);
  type.insertMember("n", HOFFSET(SummaryRow, n), H5::PredType::NATIVE_UINT64);
  type.insertMember("n_flagged", HOFFSET(SummaryRow, n_flagged), H5::PredType::NATIVE_UINT64);
  const char* names[] = {"median", "q1", "q3", "iqr", "p10", "p90", "mean", "sd", "median_ci_low", "median_ci_high"};
  for (std::size_t i = 0; i < 10; ++i) type.insertMember(names[i], HOFFSET(SummaryRow, median) + i * sizeof(double), H5::PredType::NATIVE_DOUBLE);
  const H5::DataSpace space = dataset.getSpace();
  std::vector<SummaryRow> rows(static_cast<std::size_t>(space.getSimpleExtentNpoints()));
  if (!rows.empty()) dataset.read(rows.data(), type);
  std::vector<QuantitySummary> result;
  for (const SummaryRow& row : rows) {
    result.push_back({row.line, row.quantity, row.unit, row.n, row.n_flagged, row.median, row.q1, row.q3, row.iqr,
                      row.p10, row.p90, row.mean, row.sd, row.median_ci_low, row.median_ci_high});
  }
  if (!rows.empty()) H5Dvlen_reclaim(type.getId(), space.getId(), H5P_DEFAULT, rows.data());
  return result;
}

void check_summaries(const std::vector<QuantitySummary>& actual, const std::vector<QuantitySummary>& expected) {
  REQUIRE(actual.size() == expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    const QuantitySummary &a = actual[i], &e = expected[i];
    CAPTURE(e.quantity);
    CHECK(a.line == e.line);
    CHECK(a.quantity == e.quantity);
    CHECK(a.unit == e.unit);
    CHECK(a.n == e.n);
    CHECK(a.n_flagged == e.n_flagged);
    check_same({a.median, a.q1, a.q3, a.iqr, a.p10, a.p90, a.mean, a.sd, a.median_ci_low, a.median_ci_high},
               {e.median, e.q1, e.q3, e.iqr, e.p10, e.p90, e.mean, e.sd, e.median_ci_low, e.median_ci_high});
  }
}

void check_line(const H5::H5File& file, const LineResult& line) {
  CAPTURE(line.name);
  const H5::Group group = file.openGroup("lines/" + line.name);
  CHECK(read_scalar<std::uint64_t>(group, "samples", H5::PredType::NATIVE_UINT64) == line.samples());
  const H5::DataSet sample = group.openDataSet("sample");
  CHECK(H5DSis_scale(sample.getId()) > 0);
  std::vector<std::string> column_order;  // as written, einf in % named as stored
  for (const ResultColumn& column : line.columns) {
    column_order.push_back(column.unit->symbol == "%" ? "einf_frac" : column.column_name());
  }
  CHECK(read_strings(group, "columns") == column_order);
  for (const ResultColumn& column : line.columns) {
    CAPTURE(column.quantity);
    const bool in_percent = column.unit->symbol == "%";  // einf: stored as a fraction, named einf_frac
    const H5::DataSet dataset = group.openDataSet(in_percent ? "einf_frac" : column.column_name());
    const std::vector<double> stored = read_doubles(dataset);
    if (in_percent) {
      const std::vector<double> fractions = {0.65, 0.70, 0.55, 0.80, 0.60, 0.72};  // by hand
      REQUIRE(stored.size() == fractions.size());
      for (std::size_t i = 0; i < stored.size(); ++i) CHECK(stored[i] == doctest::Approx(fractions[i]).epsilon(1e-15));
      CHECK_FALSE(group.nameExists("einf_pct"));
    } else {
      check_same(stored, {column.values.begin(), column.values.end()});
    }
    CHECK(read_string(dataset, "quantity") == column.quantity);
    CHECK(read_string(dataset, "unit") == (in_percent ? "frac" : column.unit->symbol));
    CHECK(read_string(dataset, "units") == (in_percent ? "frac" : column.unit->symbol));
    CHECK(read_string(dataset, "long_name") == find_quantity(column.quantity)->description);
    CHECK(read_string(dataset, "role") == (column.is_input ? "input" : "output"));
    CHECK(H5DSis_attached(dataset.getId(), sample.getId(), 0) > 0);
  }
  const H5::DataSet status = group.openDataSet("status");
  CHECK(status.getDataType() == H5::PredType::STD_U8LE);
  std::vector<std::uint8_t> codes(line.samples());
  status.read(codes.data(), H5::PredType::NATIVE_UINT8);
  for (std::size_t i = 0; i < codes.size(); ++i) CHECK(codes[i] == static_cast<std::uint8_t>(line.status[i]));
  const std::vector<std::string> names = read_strings(status, "names");
  REQUIRE(names.size() == 18);
  CHECK(names.back() == "probe_engulfed");
  for (std::size_t code = 0; code < names.size(); ++code) CHECK(names[code] == to_string(static_cast<SampleStatus>(code)));
  std::vector<std::uint64_t> index(line.samples());
  group.openDataSet("sample").read(index.data(), H5::PredType::NATIVE_UINT64);
  CHECK(read_string(group.openDataSet("sample"), "units") == "1");
  for (std::size_t i = 0; i < index.size(); ++i) CHECK(index[i] == i);

  check_summaries(read_summary(group.openDataSet("summary")), summaries_of(line));

  const H5::Group correlation = group.openGroup("input_rank_correlation");
  CHECK(read_strings(correlation, "names") == line.correlated_inputs);
  std::vector<hsize_t> dims;
  check_same(read_doubles(correlation.openDataSet("achieved"), &dims), row_major(line.achieved_spearman));
  CHECK(dims == std::vector<hsize_t>{static_cast<hsize_t>(line.achieved_spearman.rows()), static_cast<hsize_t>(line.achieved_spearman.cols())});
  CHECK(correlation.nameExists("target") == (line.target_spearman.size() > 0));
  if (line.target_spearman.size() > 0) check_same(read_doubles(correlation.openDataSet("target")), row_major(line.target_spearman));

  const LineAnalysis analysis = analyze_line(line);
  const H5::Group analysis_group = group.openGroup("analysis");
  CHECK(read_scalar<std::uint64_t>(analysis_group, "samples_used", H5::PredType::NATIVE_UINT64) == analysis.samples_used);
  CHECK(read_strings(analysis_group, "notes") == analysis.notes);
  const H5::DataSet spearman = analysis_group.openDataSet("input_output_spearman");
  check_same(read_doubles(spearman, &dims), row_major(analysis.input_output_spearman));
  CHECK(dims == std::vector<hsize_t>{analysis.inputs.size(), analysis.outputs.size()});
  // The analysis names its rows by the line file's columns; the file by the stored ones.
  std::vector<std::string> stored_inputs = analysis.inputs, stored_variables = analysis.pca_names;
  for (std::vector<std::string>* renamed : {&stored_inputs, &stored_variables}) {
    std::replace(renamed->begin(), renamed->end(), std::string("einf_pct"), std::string("einf_frac"));
  }
  CHECK(read_strings(spearman, "rows") == stored_inputs);
  CHECK(read_strings(spearman, "columns") == analysis.outputs);
  check_same(read_doubles(analysis_group.openDataSet("explained_variance_ratio")),
             std::vector<double>(analysis.explained_variance_ratio.begin(), analysis.explained_variance_ratio.end()));
  const H5::DataSet loadings = analysis_group.openDataSet("loadings");
  check_same(read_doubles(loadings), row_major(analysis.loadings));
  CHECK(read_strings(loadings, "rows") == stored_variables);
}

}  // namespace

TEST_CASE("results.h5 reads back exactly with the HDF5 C++ API") {
  const Scratch scratch("readback");
  const std::string path = scratch.path("results.h5");
  write_campaign(path);
  CHECK(fs::exists(path));
  CHECK_FALSE(fs::exists(path + ".partial"));

  const H5::H5File file(path, H5F_ACC_RDONLY);
  const CampaignMetadata expected = metadata();
  const H5::Group root = file.openGroup("/");
  CHECK(read_string(root, "campaign_text") == expected.campaign_text);
  CHECK(read_string(root, "campaign_path") == expected.campaign_path);
  CHECK(read_string(root, "command_line") == expected.command_line);
  CHECK(read_string(root, "engine_version") == expected.engine_version);
  CHECK(read_scalar<std::uint64_t>(root, "seed", H5::PredType::NATIVE_UINT64) == expected.seed);
  CHECK(read_scalar<double>(root, "kappa", H5::PredType::NATIVE_DOUBLE) == expected.kappa);
  CHECK(read_scalar<std::uint64_t>(root, "samples_per_line", H5::PredType::NATIVE_UINT64) == 6);
  CHECK(read_strings(root, "line_order") == std::vector<std::string>{"xxt1 xxt2", "wild_type"});
  CHECK(file.openGroup("lines").getNumObjs() == 2);

  check_line(file, wild_type());
  check_line(file, xxt1_xxt2());

  std::vector<QuantitySummary> all = summaries_of(xxt1_xxt2());
  for (const QuantitySummary& s : summaries_of(wild_type())) all.push_back(s);
  check_summaries(read_summary(file.openDataSet("summary")), all);
}

TEST_CASE("h5py and xarray read the file with its values, units and named dimensions") {
  const char* python = "/usr/bin/python3";
  if (!fs::exists(python) || std::system("/usr/bin/python3 -c 'import h5py, numpy, xarray, h5netcdf' > /dev/null 2>&1") != 0) {
    MESSAGE("skipped: /usr/bin/python3 with h5py, numpy, xarray and h5netcdf is not available (tools/install-deps)");
    return;
  }
  const Scratch scratch("h5py");
  const std::string path = scratch.path("results.h5");
  write_campaign(path);
  const std::string script = std::string(GROWTHUQ_SOURCE_DIR) + "/tests/io/check_results_h5.py";
  const std::string output = scratch.path("h5py.txt");
  const int code = std::system((std::string(python) + " '" + script + "' '" + path + "' > '" + output + "' 2>&1").c_str());
  std::ifstream in(output);
  const std::string report((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  INFO(report);
  CHECK(code == 0);
  CHECK(report.find("results.h5 checked with h5py and xarray") != std::string::npos);
}

TEST_CASE("the .partial file is removed when the writer is abandoned") {
  const Scratch scratch("abandon");
  const std::string path = scratch.path("results.h5");
  {
    ResultsH5Writer writer(path, Overwrite::refuse);
    const LineResult line = wild_type();
    writer.write_line(line, summaries_of(line), analyze_line(line));
    CHECK(fs::exists(path + ".partial"));
    CHECK_FALSE(fs::exists(path));
  }
  CHECK_FALSE(fs::exists(path + ".partial"));
  CHECK_FALSE(fs::exists(path));
}

TEST_CASE("an existing results file is refused unless overwriting is allowed") {
  const Scratch scratch("overwrite");
  const std::string path = scratch.path("results.h5");
  std::ofstream(path) << "an earlier result";
  CHECK_THROWS_WITH_AS(ResultsH5Writer(path, Overwrite::refuse),
                       (path + ": already exists; choose another output or pass --force to overwrite").c_str(), InputError);
  CHECK_FALSE(fs::exists(path + ".partial"));
  write_campaign(path, Overwrite::allow);
  const H5::H5File file(path, H5F_ACC_RDONLY);
  CHECK(read_string(file.openGroup("/"), "engine_version") == "0.1.0");
}

TEST_CASE("bad line names and repeated lines are input errors; a bad directory too") {
  const Scratch scratch("names");
  ResultsH5Writer writer(scratch.path("results.h5"), Overwrite::refuse);
  LineResult line = wild_type();
  const std::vector<QuantitySummary> summaries = summaries_of(line);
  const LineAnalysis analysis = analyze_line(line);
  line.name = "wild/type";
  CHECK_THROWS_WITH_AS(writer.write_line(line, summaries, analysis),
                       (scratch.path("results.h5.partial") +
                        ": line = 'wild/type': expected a line name without '/' that is not empty or '.' (it names an HDF5 group)")
                           .c_str(),
                       InputError);
  line.name = "wild_type";
  writer.write_line(line, summaries, analysis);
  CHECK_THROWS_AS(writer.write_line(line, summaries, analysis), InputError);
  line.columns[0].values.pop_back();
  line.name = "other";
  CHECK_THROWS_AS(writer.write_line(line, summaries, analysis), std::invalid_argument);

  CHECK_THROWS_AS(ResultsH5Writer(scratch.path("no/such/dir/results.h5"), Overwrite::refuse), InputError);
}

TEST_CASE("additional tables, arrays and attributes read back exactly") {
  const Scratch scratch("extra");
  const std::string path = scratch.path("results.h5");
  {
    ResultsH5Writer writer(path, Overwrite::refuse);
    writer.write_table("lines/extra/fits", {ExtraColumn{"variable", {"k", "d0", "einf"}},
                                            ExtraColumn{"aic", {}, {12.5, missing, -3.25}, {}, "1"},
                                            ExtraColumn{"n", {}, {}, {57, 46, -1}, "1"}});
    writer.write_array("lines/extra/points/t_s", std::vector<double>{0.0, 0.02, missing}, "s", "point");
    writer.write_array("lines/extra/points/curve_index", std::vector<std::int32_t>{0, 0, 7}, "1", "point");
    writer.write_array("lines/extra/points/other", std::vector<double>{1.5, 2.5}, "uN", "point");  // another length
    writer.write_attribute("lines/extra/points", "fit", "step");
    writer.write_attribute("lines/extra/points/t_s", "scale", 2.5);
    CHECK_THROWS_AS(writer.write_table("lines/extra/fits", {ExtraColumn{"n", {}, {1.0}}}), InputError);  // written twice
    CHECK_THROWS_AS(writer.write_table("bad", {ExtraColumn{"a", {}, {1.0}}, ExtraColumn{"b", {}, {1.0, 2.0}}}),
                    std::invalid_argument);
    writer.finish(CampaignMetadata{});
  }
  const H5::H5File file(path, H5F_ACC_RDONLY);
  const H5::DataSet fits = file.openDataSet("lines/extra/fits");
  const H5::CompType stored = fits.getCompType();
  REQUIRE(stored.getNmembers() == 3);
  CHECK(stored.getMemberName(0) == "variable");
  CHECK(stored.getMemberName(1) == "aic");
  CHECK(stored.getMemberName(2) == "n");
  struct Row {
    char* variable;
    double aic;
    std::int64_t n;
  };
  H5::StrType text(H5::PredType::C_S1, H5T_VARIABLE);
  text.setCset(H5T_CSET_UTF8);  // as written: HDF5 does not convert between character sets
  H5::CompType memory(sizeof(Row));
  memory.insertMember("variable", HOFFSET(Row, variable), text);
  memory.insertMember("aic", HOFFSET(Row, aic), H5::PredType::NATIVE_DOUBLE);
  memory.insertMember("n", HOFFSET(Row, n), H5::PredType::NATIVE_INT64);
  std::vector<Row> rows(3);
  fits.read(rows.data(), memory);
  CHECK(std::string(rows[0].variable) == "k");
  CHECK(std::string(rows[2].variable) == "einf");
  CHECK(rows[0].aic == 12.5);
  CHECK(std::isnan(rows[1].aic));
  CHECK(rows[2].aic == -3.25);
  CHECK(rows[1].n == 46);
  CHECK(rows[2].n == -1);
  H5Dvlen_reclaim(memory.getId(), fits.getSpace().getId(), H5P_DEFAULT, rows.data());

  const std::vector<double> t = read_doubles(file.openDataSet("lines/extra/points/t_s"));
  check_same(t, {0.0, 0.02, missing});
  const H5::DataSet index = file.openDataSet("lines/extra/points/curve_index");
  CHECK(index.getDataType() == H5::PredType::STD_I32LE);
  std::vector<std::int32_t> indices(3);
  index.read(indices.data(), H5::PredType::NATIVE_INT32);
  CHECK(indices == std::vector<std::int32_t>{0, 0, 7});
  CHECK(read_string(file.openGroup("lines/extra/points"), "fit") == "step");
  CHECK(read_strings(fits, "column_units") == std::vector<std::string>{"", "1", "1"});
  const H5::DataSet fits_row = file.openDataSet("lines/extra/fits_row");
  CHECK(H5DSis_scale(fits_row.getId()) > 0);
  CHECK(H5DSis_attached(fits.getId(), fits_row.getId(), 0) > 0);
  // A row index is a netCDF "dimension but not a variable": a scale of the right length that
  // holds no values and takes no room (sample, the samples' index, is stored: check_line).
  const H5::DataSet point = file.openDataSet("lines/extra/points/point");
  CHECK(H5DSis_scale(point.getId()) > 0);
  CHECK(point.getSpace().getSimpleExtentNpoints() == 3);
  CHECK(point.getStorageSize() == 0);
  char scale_name[80] = {};
  H5DSget_scale_name(point.getId(), scale_name, sizeof scale_name);
  CHECK(std::string(scale_name) == "This is a netCDF dimension but not a netCDF variable.         3");
  CHECK(read_string(file.openDataSet("lines/extra/points/t_s"), "units") == "s");
  CHECK(read_string(index, "units") == "1");
  CHECK(H5DSis_attached(file.openDataSet("lines/extra/points/t_s").getId(), point.getId(), 0) > 0);
  CHECK(H5DSis_attached(index.getId(), point.getId(), 0) > 0);
  const H5::DataSet other = file.openDataSet("lines/extra/points/other");
  const H5::DataSet point_2 = file.openDataSet("lines/extra/points/point_2");  // its own dimension
  CHECK(H5DSis_attached(other.getId(), point_2.getId(), 0) > 0);
  CHECK(H5DSis_attached(other.getId(), point.getId(), 0) == 0);
  CHECK(read_scalar<double>(file.openDataSet("lines/extra/points/t_s"), "scale", H5::PredType::NATIVE_DOUBLE) == 2.5);
}

namespace {

// Every kind of object the writer makes: line groups and their datasets, the summary, the
// additional tables, arrays and attributes of raw-data campaigns (a group made for an
// attribute, as the data-uncertainty method is written) and the root's attributes.
void write_every_kind_of_object(const std::string& path) {
  ResultsH5Writer writer(path, Overwrite::refuse);
  for (const LineResult& line : {wild_type(), xxt1_xxt2()}) writer.write_line(line, summaries_of(line), analyze_line(line));
  writer.write_table("fits", {ExtraColumn{"variable", {"k", "d0"}}, ExtraColumn{"aic", {}, {12.5, -3.25}}});
  writer.write_table("lines/wild_type/fits", {ExtraColumn{"n", {}, {}, {57, 46}}});
  writer.write_array("lines/wild_type/curves/t_s", std::vector<double>{0.0, 0.02}, "s", "point");
  writer.write_array("lines/wild_type/curves/curve_index", std::vector<std::int32_t>{0, 7}, "1", "point");
  writer.write_attribute("data_uncertainty", "method", "bootstrap");
  writer.write_attribute("lines/wild_type/curves/t_s", "scale", 2.5);
  writer.finish(metadata());
}

// The times HDF5 recorded in the object headers of `path`, as "<object>: <time>" per object
// that has any (HDF5 records them unless told not to).
std::vector<std::string> recorded_times(const std::string& path) {
  const H5::H5File file(path, H5F_ACC_RDONLY);
  std::vector<std::string> found;
  const auto visit = [](hid_t, const char* name, const H5O_info_t* info, void* data) -> herr_t {
    for (const time_t time : {info->atime, info->mtime, info->ctime, info->btime}) {
      if (time != 0) {
        static_cast<std::vector<std::string>*>(data)->push_back(std::string(name) + ": " + std::to_string(time));
        break;
      }
    }
    return 0;
  };
  REQUIRE(H5Ovisit2(file.getId(), H5_INDEX_NAME, H5_ITER_NATIVE, visit, &found, H5O_INFO_TIME) >= 0);
  return found;
}

}  // namespace

TEST_CASE("results.h5 records no times: the same results give the same bytes whenever they are written") {
  const Scratch scratch("untimed");
  const std::string first = scratch.path("first.h5");
  const std::string second = scratch.path("second.h5");
  write_every_kind_of_object(first);
  CHECK(recorded_times(first) == std::vector<std::string>{});
  // Times have a resolution of one second: a second file written more than a second later.
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  write_every_kind_of_object(second);
  const std::string a = slurp(first);
  const std::string b = slurp(second);
  REQUIRE(a.size() > 0);
  CHECK(a.size() == b.size());
  CHECK(a == b);
}

TEST_CASE("declared lines keep the campaign's order whatever order they are written in") {
  const Scratch scratch("declared");
  const std::string path = scratch.path("results.h5");
  {
    ResultsH5Writer writer(path, Overwrite::refuse);
    writer.declare_lines({"xxt1 xxt2", "wild_type"});
    for (const LineResult& line : {wild_type(), xxt1_xxt2()}) writer.write_line(line, summaries_of(line), analyze_line(line));
    CHECK_THROWS_AS(writer.declare_lines({"other"}), std::logic_error);
    writer.finish(metadata());
  }
  const H5::H5File file(path, H5F_ACC_RDONLY);
  CHECK(read_strings(file.openGroup("/"), "line_order") == std::vector<std::string>{"xxt1 xxt2", "wild_type"});
  std::vector<std::string> created;  // /lines by creation order, as h5py lists it
  for (hsize_t i = 0; i < 2; ++i) {
    char name[64] = {};
    H5Lget_name_by_idx(file.getId(), "lines", H5_INDEX_CRT_ORDER, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT);
    created.emplace_back(name);
  }
  CHECK(created == std::vector<std::string>{"xxt1 xxt2", "wild_type"});
  check_line(file, wild_type());  // written into its declared group
  check_line(file, xxt1_xxt2());
  // The root summary keeps the written order (as summary.csv does).
  std::vector<QuantitySummary> all = summaries_of(wild_type());
  for (const QuantitySummary& s : summaries_of(xxt1_xxt2())) all.push_back(s);
  check_summaries(read_summary(file.openDataSet("summary")), all);
}
