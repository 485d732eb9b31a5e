// read_force_curves and the writers of force_curve.hpp; the format is documented in
// distributions/README.md, "Force curves".
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <system_error>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/forcecurves/force_curve.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/mechanics/instrument.hpp"

namespace growthuq {
namespace {

// A column of one of several units: the names it may have and each one's factor to SI.
struct UnitColumn {
  const char* name;
  double to_si;
};
constexpr UnitColumn position_columns[] = {{"z_um", unit_factor::um}, {"z_nm", unit_factor::nm}};
// V_V: sensor voltage, converted with the sheet's gain (factor applied later).
constexpr UnitColumn force_columns[] = {{"F_uN", unit_factor::uN}, {"F_nN", 1e-9}, {"V_V", 1.0}};

struct FoundColumn {
  std::size_t index = 0;
  std::string name;
  double to_si = 1.0;
};

template <std::size_t N>
FoundColumn one_of(const CsvTable& table, const UnitColumn (&columns)[N], std::string_view what) {
  std::optional<FoundColumn> found;
  std::string names;
  for (const UnitColumn& column : columns) {
    names += (names.empty() ? "" : ", ") + std::string(column.name);
    if (!table.has_column(column.name)) continue;
    if (found) {
      throw InputError(file_location(table.path, 1), "columns " + found->name + " and " + column.name +
                                                         ": expected one " + std::string(what) + " column");
    }
    found = FoundColumn{table.column_index(column.name), column.name, column.to_si};
  }
  if (!found) throw InputError(file_location(table.path, 1), "no " + std::string(what) + " column: expected one of " + names);
  return *found;
}

// A column that may be absent: its index, or `absent`. (A sentinel rather than
// std::optional<std::size_t>, which GCC 12 warns about as maybe uninitialized when inlined.)
constexpr std::size_t absent = static_cast<std::size_t>(-1);
std::size_t optional_column(const CsvTable& table, std::string_view name) {
  return table.has_column(name) ? table.column_index(name) : absent;
}

struct SheetRow {
  std::string tube;
  int repetition = 0;
  double probe_radius = 0.0;
  double sensor_stiffness = 0.0;
  double gain_N_per_V = std::numeric_limits<double>::quiet_NaN();  // NaN: not given
  std::string location;
};

std::map<std::string, SheetRow, std::less<>> read_sheet(const std::string& path) {
  const CsvTable table = read_csv(path);
  const std::size_t name = table.column_index("curve");
  const std::size_t tube = table.column_index("tube");
  const std::size_t repetition = table.column_index("repetition");
  const std::size_t rho = table.column_index("rho_um");
  const std::size_t k_sys = table.column_index("k_sys_N_per_m");
  const std::size_t gain = optional_column(table, "gain_uN_per_V");
  std::map<std::string, SheetRow, std::less<>> sheet;
  std::map<std::pair<std::string, int>, std::string> tube_repetitions;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    const auto& cells = table.rows[row];
    const std::string location = table.row_location(row);
    SheetRow entry;
    entry.location = location;
    if (cells[name].empty()) throw_bad_value(location, "curve", cells[name], "a curve name");
    entry.tube = cells[tube];
    if (entry.tube.empty()) throw_bad_value(location, "tube", cells[tube], "the name of the curve's tube");
    entry.repetition = static_cast<int>(parse_count(cells[repetition], location, "repetition", 1, 1000000));
    const std::optional<double> rho_um = try_parse_double(cells[rho]);
    entry.probe_radius = rho_um ? *rho_um * unit_factor::um : std::numeric_limits<double>::quiet_NaN();
    check_instrument_value(InstrumentField::probe_radius, entry.probe_radius, location, "rho_um", cells[rho]);
    const std::optional<double> stiffness = try_parse_double(cells[k_sys]);
    entry.sensor_stiffness = cells[k_sys] == "inf" ? std::numeric_limits<double>::infinity()
                                                   : stiffness.value_or(std::numeric_limits<double>::quiet_NaN());
    check_instrument_value(InstrumentField::sensor_stiffness, entry.sensor_stiffness, location, "k_sys_N_per_m",
                           cells[k_sys]);
    if (gain != absent && !cells[gain].empty()) {
      const double value = parse_double(cells[gain], location, "gain_uN_per_V");
      if (!(value > 0.0)) throw_bad_value(location, "gain_uN_per_V", cells[gain], "a positive gain (uN per V)");
      entry.gain_N_per_V = value * unit_factor::uN;
    }
    auto [repeated, first] = tube_repetitions.try_emplace({entry.tube, entry.repetition}, location);
    if (!first) {
      throw_bad_value(location, "repetition", cells[repetition],
                      "one curve per repetition of tube '" + entry.tube + "' (this one is given at " + repeated->second + ")");
    }
    auto [known, inserted] = sheet.try_emplace(cells[name], entry);
    if (!inserted) {
      throw_bad_value(location, "curve", cells[name], "one row per curve (first given at " + known->second.location + ")");
    }
  }
  return sheet;
}

// A curve while its rows are read: the file line of each sample, for messages about it.
struct PartialCurve {
  ForceCurve curve;
  std::vector<long> lines;
  std::string path;
  std::string position_column, force_column;
  bool voltage = false;
  bool segmented = false;
  bool retracting = false;  // a retract row has been read
  // The first sample whose position is not beyond the previous one, with both cells as written:
  // an error if it falls in the approach (known once the curve is read).
  std::optional<std::size_t> first_back;
  std::string back_text, before_back_text, previous_text;
};

void read_curve_file(const std::string& path, const std::string& stem, std::vector<PartialCurve>& curves,
                     std::map<std::string, std::size_t, std::less<>>& index) {
  const CsvTable table = read_csv(path);
  const FoundColumn position = one_of(table, position_columns, "position");
  const FoundColumn force = one_of(table, force_columns, "force (or sensor voltage)");
  const std::size_t name = optional_column(table, "curve");
  const std::size_t time = optional_column(table, "t_s");
  const std::size_t segment = optional_column(table, "segment");
  std::set<std::size_t> of_this_file;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    const auto& cells = table.rows[row];
    const std::string location = table.row_location(row);
    const std::string curve_name = name != absent ? cells[name] : stem;
    if (curve_name.empty()) throw_bad_value(location, "curve", curve_name, "a curve name");
    auto [it, inserted] = index.try_emplace(curve_name, curves.size());
    if (inserted) {
      curves.push_back({});
      PartialCurve& partial = curves.back();
      partial.curve.name = curve_name;
      partial.curve.location = location;
      partial.path = table.path;
      partial.position_column = position.name;
      partial.force_column = force.name;
      partial.voltage = force.name == "V_V";
      partial.segmented = segment != absent;
    } else if (!of_this_file.contains(it->second)) {
      throw_bad_value(location, "curve", curve_name, "a curve of one file (it is also in " + curves[it->second].path + ")");
    }
    of_this_file.insert(it->second);
    PartialCurve& partial = curves[it->second];
    ForceCurve& curve = partial.curve;
    const double z = parse_double(cells[position.index], location, "column " + position.name) * position.to_si;
    if (!partial.first_back && !curve.position.empty() && !(z > curve.position.back())) {
      partial.first_back = curve.position.size();
      partial.back_text = cells[position.index];
      partial.before_back_text = partial.previous_text;
    }
    partial.previous_text = cells[position.index];
    const double f = parse_double(cells[force.index], location, "column " + force.name) * force.to_si;
    if (time != absent) {
      const double t = parse_double(cells[time], location, "column t_s");
      if (!curve.time.empty() && !(t > curve.time.back())) {
        throw_bad_value(location, "column t_s", cells[time],
                        "a time after the previous sample of curve '" + curve_name + "' (" + format_double(curve.time.back()) + " s)");
      }
      curve.time.push_back(t);
    }
    if (segment != absent) {
      const std::string& text = cells[segment];
      if (text != "approach" && text != "retract") throw_bad_value(location, "column segment", text, "approach or retract");
      if (text == "approach" && partial.retracting) {
        throw_bad_value(location, "column segment", text,
                        "retract: curve '" + curve_name + "' is retracting since an earlier row (approach rows come first)");
      }
      partial.retracting = text == "retract";
      if (!partial.retracting) curve.approach_end = curve.position.size() + 1;
    }
    curve.position.push_back(z);
    curve.force.push_back(f);
    partial.lines.push_back(table.line_numbers[row]);
  }
  if (table.rows.empty()) throw InputError(file_location(table.path, 0), "no samples: expected rows of position and force");
}

// The approach ends at the first sample of largest position unless a segment column says.
void check_approach(PartialCurve& partial) {
  ForceCurve& curve = partial.curve;
  if (!partial.segmented) {
    curve.approach_end =
        static_cast<std::size_t>(std::max_element(curve.position.begin(), curve.position.end()) - curve.position.begin()) + 1;
  }
  if (curve.approach_end < minimum_approach_samples) {
    throw InputError(curve.location, "curve '" + curve.name + "' has " + std::to_string(curve.approach_end) +
                                         " approach samples: expected at least " + std::to_string(minimum_approach_samples));
  }
  if (partial.first_back && *partial.first_back < curve.approach_end) {
    throw_bad_value(file_location(partial.path, partial.lines[*partial.first_back]), "column " + partial.position_column,
                    partial.back_text,
                    "a position beyond the previous sample's (" + partial.before_back_text +
                        ") during the approach of curve '" + curve.name + "'");
  }
}

std::vector<std::string> curve_files(const std::string& folder, const std::string& sheet_path) {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".csv") continue;
    if (fs::exists(sheet_path) && fs::equivalent(entry.path(), sheet_path)) continue;
    files.push_back(entry.path().string());
  }
  if (error) throw InputError(folder, "cannot list the folder: " + error.message());
  std::sort(files.begin(), files.end());
  if (files.empty()) throw InputError(folder, "no curve files: expected *.csv files of position and force");
  return files;
}

}  // namespace

std::vector<ForceCurve> read_force_curves(const std::string& curves_path, const std::string& sheet_path) {
  namespace fs = std::filesystem;
  const bool folder = fs::is_directory(curves_path);
  std::string sheet = sheet_path;
  if (sheet.empty()) {
    if (!folder) throw InputError(curves_path, "no curve sheet: expected --sheet naming tube, repetition, rho_um, k_sys_N_per_m per curve");
    sheet = (fs::path(curves_path) / "sheet.csv").string();
  }
  std::vector<PartialCurve> partials;
  std::map<std::string, std::size_t, std::less<>> index;
  if (folder) {
    for (const std::string& file : curve_files(curves_path, sheet)) {
      read_curve_file(file, fs::path(file).stem().string(), partials, index);
    }
  } else {
    read_curve_file(curves_path, fs::path(curves_path).stem().string(), partials, index);
  }
  const auto rows = read_sheet(sheet);
  for (const auto& [name, row] : rows) {
    if (!index.contains(name)) throw_bad_value(row.location, "curve", name, "a curve of " + curves_path);
  }
  std::vector<ForceCurve> curves;
  curves.reserve(partials.size());
  for (PartialCurve& partial : partials) {
    check_approach(partial);
    ForceCurve& curve = partial.curve;
    const auto row = rows.find(curve.name);
    if (row == rows.end()) {
      throw InputError(curve.location, "curve '" + curve.name + "' has no row in " + sheet +
                                           ": expected curve, tube, repetition, rho_um, k_sys_N_per_m for every curve");
    }
    if (partial.voltage) {
      if (std::isnan(row->second.gain_N_per_V)) {
        throw InputError(row->second.location, "curve '" + curve.name +
                                                   "' is recorded as V_V: expected a positive gain_uN_per_V in its sheet row");
      }
      for (double& f : curve.force) f *= row->second.gain_N_per_V;
    }
    curve.tube = row->second.tube;
    curve.repetition = row->second.repetition;
    curve.probe_radius_m = row->second.probe_radius;
    curve.sensor_stiffness_N_per_m = row->second.sensor_stiffness;
    curves.push_back(std::move(curve));
  }
  return curves;
}

namespace {

// `value` with at most `decimals` decimals, trailing zeros dropped ("0.297", "12", "-0.0031");
// exact (format_double) for decimals < 0.
std::string rounded_cell(double value, int decimals) {
  if (decimals < 0) return format_double(value);
  std::array<char, 64> text{};
  const auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), value, std::chars_format::fixed, decimals);
  if (error != std::errc()) return format_double(value);
  std::string cell(text.data(), end);
  if (cell.find('.') != std::string::npos) {
    cell.erase(cell.find_last_not_of('0') + 1);
    if (cell.back() == '.') cell.pop_back();
  }
  return cell == "-0" ? "0" : cell;
}

}  // namespace

std::string force_curves_csv(const std::vector<ForceCurve>& curves, int decimals) {
  const bool timed = std::all_of(curves.begin(), curves.end(), [](const ForceCurve& c) { return !c.time.empty(); });
  std::vector<std::string> header{"curve", "z_um", "F_uN", "segment"};
  if (timed) header.insert(header.begin() + 1, "t_s");
  CsvWriter writer(header);
  for (const ForceCurve& curve : curves) {
    for (std::size_t i = 0; i < curve.position.size(); ++i) {
      std::vector<std::string> row{curve.name, rounded_cell(to_um(curve.position[i]), decimals),
                                   rounded_cell(to_uN(curve.force[i]), decimals), i < curve.approach_end ? "approach" : "retract"};
      if (timed) row.insert(row.begin() + 1, rounded_cell(curve.time[i], decimals));
      writer.add_row(row);
    }
  }
  return writer.text();
}

std::string curve_sheet_csv(const std::vector<ForceCurve>& curves) {
  CsvWriter writer({"curve", "tube", "repetition", "rho_um", "k_sys_N_per_m"});
  for (const ForceCurve& curve : curves) {
    const double k_sys = curve.sensor_stiffness_N_per_m;
    writer.add_row({curve.name, curve.tube, std::to_string(curve.repetition), format_double(to_um(curve.probe_radius_m)),
                    std::isinf(k_sys) ? "inf" : format_double(k_sys)});
  }
  return writer.text();
}

}  // namespace growthuq
