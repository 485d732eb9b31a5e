#include "growthuq/relaxation/curves.hpp"

#include <cmath>
#include <limits>
#include <map>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/mechanics/instrument.hpp"

namespace growthuq {
namespace {

// A metadata column: its name in the file and the factor to SI.
struct MetaColumn {
  const char* name;
  double to_si;
};
constexpr MetaColumn indentation_column{"delta_um", unit_factor::um};
constexpr MetaColumn turgor_column{"p_MPa", unit_factor::MPa};
constexpr MetaColumn diameter_column{"d_um", unit_factor::um};
constexpr MetaColumn thickness_column{"h_nm", unit_factor::nm};
constexpr MetaColumn radius_column{"rho_um", unit_factor::um};

struct Metadata {
  double indentation = 0.0, turgor = 0.0, diameter = 0.0, thickness = 0.0, probe_radius = 0.0;
  std::string location;
};

double positive_cell(const CsvTable& table, std::size_t row, const MetaColumn& column) {
  const std::string& text = table.rows[row][table.column_index(column.name)];
  const double value = parse_double(text, table.row_location(row), column.name);
  if (!(value > 0.0)) throw_bad_value(table.row_location(row), column.name, text, "a positive number");
  return value * column.to_si;
}

// A tube sheet's rho_um, in the instrument's range and with its message (as --rho-um and the
// campaign file's probe_radius_um).
double probe_radius_cell(const CsvTable& table, std::size_t row) {
  const std::string& text = table.rows[row][table.column_index(radius_column.name)];
  const std::optional<double> rho_um = try_parse_double(text);
  const double rho = rho_um ? *rho_um * radius_column.to_si : std::numeric_limits<double>::quiet_NaN();
  check_instrument_value(InstrumentField::probe_radius, rho, table.row_location(row), radius_column.name, text);
  return rho;
}

Metadata metadata_of_row(const CsvTable& table, std::size_t row, std::optional<double> probe_radius) {
  Metadata meta;
  meta.location = table.row_location(row);
  meta.indentation = positive_cell(table, row, indentation_column);
  meta.turgor = positive_cell(table, row, turgor_column);
  meta.diameter = positive_cell(table, row, diameter_column);
  meta.thickness = positive_cell(table, row, thickness_column);
  meta.probe_radius = table.has_column(radius_column.name) ? probe_radius_cell(table, row) : *probe_radius;
  // A radius given for every curve (--rho-um, a campaign's probe_radius_um) and another in the
  // sheet: which one the user meant cannot be told, and using either silently changes E.
  if (probe_radius && std::abs(meta.probe_radius - *probe_radius) > 1e-12 * *probe_radius) {
    throw_bad_value(meta.location, radius_column.name, table.rows[row][table.column_index(radius_column.name)],
                    "the probe radius given for every curve, " + format_double(*probe_radius / radius_column.to_si) +
                        " um (--rho-um, or the campaign's probe_radius_um): give the radius in one place, or the same "
                        "in both");
  }
  return meta;
}

bool same(const Metadata& a, const Metadata& b) {
  return a.indentation == b.indentation && a.turgor == b.turgor && a.diameter == b.diameter &&
         a.thickness == b.thickness && a.probe_radius == b.probe_radius;
}

void require_probe_radius(const CsvTable& table, std::optional<double> probe_radius) {
  if (!table.has_column(radius_column.name) && !probe_radius) {
    throw InputError(file_location(table.path, 0),
                     "no rho_um column and no --rho-um: the probe radius is a measured, required input");
  }
}

}  // namespace

std::vector<RelaxationCurve> read_relaxation_curves(const std::string& curves_path, const std::string& meta_path,
                                                    std::optional<double> probe_radius) {
  const CsvTable table = read_csv(curves_path);
  const std::size_t name_column = table.column_index("curve");
  const std::vector<double> times = table.numeric_column("t_s");
  const std::vector<double> forces = table.numeric_column("F_uN");

  std::vector<RelaxationCurve> curves;
  std::map<std::string, std::size_t, std::less<>> index;
  std::map<std::string, Metadata, std::less<>> inline_metadata;
  if (meta_path.empty()) require_probe_radius(table, probe_radius);

  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    const std::string& name = table.rows[row][name_column];
    if (name.empty()) throw_bad_value(table.row_location(row), "curve", name, "a curve name");
    if (forces[row] < 0.0) {
      throw_bad_value(table.row_location(row), "F_uN", table.rows[row][table.column_index("F_uN")],
                      "a force >= 0 (a negative force means the probe lost contact or the baseline is off)");
    }
    auto [it, inserted] = index.try_emplace(name, curves.size());
    if (inserted) {
      curves.push_back({});
      curves.back().name = name;
      curves.back().location = table.row_location(row);
    }
    RelaxationCurve& curve = curves[it->second];
    if (!curve.t.empty() && !(times[row] > curve.t.back())) {
      throw_bad_value(table.row_location(row), "t_s", table.rows[row][table.column_index("t_s")],
                      "a time after the previous sample of curve '" + name + "' (" + format_double(curve.t.back()) + " s)");
    }
    curve.t.push_back(times[row]);
    curve.force.push_back(from_uN(forces[row]));
    if (meta_path.empty()) {
      const Metadata meta = metadata_of_row(table, row, probe_radius);
      auto [known, first] = inline_metadata.try_emplace(name, meta);
      if (!first && !same(known->second, meta)) {
        throw InputError(meta.location, "metadata of curve '" + name + "' differ from its first row (" +
                                            known->second.location + "): expected the same values on every row of a curve");
      }
    }
  }
  if (curves.empty()) throw InputError(file_location(curves_path, 0), "no samples: expected rows curve,t_s,F_uN");

  std::map<std::string, Metadata, std::less<>> metadata = inline_metadata;
  if (!meta_path.empty()) {
    const CsvTable meta_table = read_csv(meta_path);
    require_probe_radius(meta_table, probe_radius);
    const std::size_t meta_name = meta_table.column_index("curve");
    for (std::size_t row = 0; row < meta_table.rows.size(); ++row) {
      const std::string& name = meta_table.rows[row][meta_name];
      if (!index.contains(name)) {
        throw_bad_value(meta_table.row_location(row), "curve", name, "a curve of " + curves_path);
      }
      const Metadata meta = metadata_of_row(meta_table, row, probe_radius);
      auto [known, first] = metadata.try_emplace(name, meta);
      if (!first) {
        throw_bad_value(meta_table.row_location(row), "curve", name,
                        "one row per curve (first given at " + known->second.location + ")");
      }
    }
  }

  for (RelaxationCurve& curve : curves) {
    const auto meta = metadata.find(curve.name);
    if (meta == metadata.end()) {
      throw InputError(curve.location, "curve '" + curve.name + "' has no row in " + meta_path +
                                           ": expected delta_um, p_MPa, d_um, h_nm for every curve");
    }
    if (curve.t.size() < minimum_curve_samples) {
      throw InputError(curve.location, "curve '" + curve.name + "' has " + std::to_string(curve.t.size()) +
                                           " samples: expected at least " + std::to_string(minimum_curve_samples));
    }
    curve.indentation = meta->second.indentation;
    curve.turgor = meta->second.turgor;
    curve.diameter = meta->second.diameter;
    curve.thickness = meta->second.thickness;
    curve.probe_radius_m = meta->second.probe_radius;
  }
  return curves;
}

}  // namespace growthuq
