// The correction's data: the training CSV it is fitted from, the C++ text `growthuq
// fit-correction` writes, and the shipped correction compiled from that text.
#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <span>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "correction/correction_training.hpp"
#include "growthuq/correction/corrected_closed_form.hpp"
#include "fe/force_window.hpp"
#include "growthuq/io/csv.hpp"

namespace growthuq {
namespace {

std::string number(double value) {
  std::array<char, 40> text{};
  std::snprintf(text.data(), text.size(), "%.17g", value);
  return text.data();
}

std::string list(std::span<const double> values) {
  std::string text = "{";
  for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + number(values[i]);
  return text + "}";
}

// A long list one row of `width` numbers per line (the kriging's centres: one per line).
std::string rows_of(std::span<const double> values, std::size_t width) {
  std::string text = "{\n";
  for (std::size_t i = 0; i < values.size(); i += width) {
    for (std::size_t j = i; j < std::min(i + width, values.size()); ++j) text += number(values[j]) + ", ";
    text += "\n";
  }
  return text + "}";
}

}  // namespace

const Correction& shipped_correction() {
  static const Correction correction = [] {
    Correction c;
#include "shipped_correction.inc"
    return c;
  }();
  return correction;
}

std::vector<TrainingPoint> read_training_csv(const std::string& path) {
  const CsvTable table = read_csv(path);
  const std::size_t index = table.column_index("index"), status = table.column_index("status");
  const std::array<std::size_t, 7> columns{table.column_index("p_MPa"), table.column_index("E_MPa"), table.column_index("h_nm"),
                                           table.column_index("d0_um"), table.column_index("rho_um"),
                                           table.column_index("k_N_per_m"), table.column_index("d_um")};
  const std::array<double, 7> to_si{1e6, 1e6, 1e-9, 1e-6, 1e-6, 1.0, 1e-6};
  // What a simulation that stopped may leave empty: the turgid h, k and d.
  constexpr std::array<bool, 7> measured{false, false, true, false, false, true, true};
  std::vector<TrainingPoint> points;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const std::vector<std::string>& row = table.rows[r];
    TrainingPoint point;
    point.index = static_cast<int>(parse_count(row[index], table.row_location(r), "index", 0, 1000000));
    point.ok = row[status] == "ok";
    std::array<double, 7> values{};
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::string& cell = row[columns[c]];
      if (cell.empty() && measured[c] && !point.ok) continue;
      values[c] = parse_double(cell, table.row_location(r), table.header[columns[c]]);
      if (!(values[c] > 0)) throw_bad_value(table.row_location(r), table.header[columns[c]], cell, "a positive number");
      values[c] *= to_si[c];
    }
    point.p = values[0];
    point.E = values[1];
    point.h = values[2];
    point.d0 = values[3];
    point.rho = values[4];
    point.k = values[5];
    point.d = values[6];
    points.push_back(point);
  }
  return points;
}

std::vector<std::array<double, 2>> training_windows() {
  std::vector<std::array<double, 2>> windows;
  for (const double top : {2e-6, 3e-6, 4e-6}) {
    for (const double ratio : {0.05, 0.1, 0.25, 0.5}) windows.push_back({ratio * top, top});
  }
  return windows;
}

std::vector<TrainingPoint> under_training_windows(const std::vector<TrainingPoint>& rows, const std::string& curves_path) {
  struct Curve {
    std::vector<double> depth, force;  // um, uN
  };
  const CsvTable table = read_csv(curves_path);
  const std::size_t index = table.column_index("index"), depth = table.column_index("delta_um"),
                    force = table.column_index("F_uN");
  std::map<int, std::size_t> row_of;
  for (std::size_t r = 0; r < rows.size(); ++r) row_of[rows[r].index] = r;
  std::map<int, Curve> curves;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const std::vector<std::string>& row = table.rows[r];
    const int i = static_cast<int>(parse_count(row[index], table.row_location(r), "index", 0, 1000000));
    if (!row_of.contains(i)) throw_bad_value(table.row_location(r), "index", row[index], "the index of a training row");
    Curve& curve = curves[i];
    curve.depth.push_back(parse_double(row[depth], table.row_location(r), "delta_um"));
    curve.force.push_back(parse_double(row[force], table.row_location(r), "F_uN"));
    if (curve.depth.size() > 1 && !(curve.depth.back() > curve.depth[curve.depth.size() - 2])) {
      throw_bad_value(table.row_location(r), "delta_um", row[depth], "a depth beyond the curve's previous one");
    }
  }
  std::vector<TrainingPoint> points;
  for (const auto& [i, curve] : curves) {
    const TrainingPoint& tube = rows[row_of[i]];
    if (!(tube.d > 0 && tube.h > 0)) continue;  // no turgid state: no tube to measure
    for (const std::array<double, 2>& window : training_windows()) {
      const fe::WindowFit fit = fe::fit_force_window(curve.depth, curve.force, window[0] * 1e6, window[1] * 1e6);
      if (fit.status != fe::WindowFitStatus::ok) continue;
      TrainingPoint point = tube;
      point.window = window;
      point.k = fit.slope;  // uN/um = N/m
      point.ok = true;
      points.push_back(point);
    }
  }
  return points;
}

std::string correction_source(const Correction& c) {
  std::string text =
      "// Written by `growthuq fit-correction` from src/correction/training.csv: do not edit by hand\n"
      "// (src/correction/README.md says how to regenerate it). The body of shipped_correction().\n";
  text += "c.law = ShellFeLaw::" + std::string(c.law == ShellFeLaw::hencky ? "hencky" : "saint_venant_kirchhoff") + ";\n";
  text += "c.substrate = " + std::string(c.substrate ? "true" : "false") + ";\n";
  text += "c.bending = " + std::string(c.bending ? "true" : "false") + ";\n";
  text += "c.tube_length = " + number(c.tube_length) + ";\n";
  text += "c.probe_distance = " + number(c.probe_distance) + ";\n";
  text += "c.poisson_ratio = " + number(c.poisson_ratio) + ";\n";
  text += "c.low = " + list(c.low) + ";\n";
  text += "c.high = " + list(c.high) + ";\n";
  text += "c.max_stiffness = " + number(c.max_stiffness) + ";\n";
  text += "c.max_probe_over_bending_length = " + number(c.max_probe_over_bending_length) + ";\n";
  text += "c.modulus = " + list(c.modulus) + ";\n";
  text += "c.pressure_ratio = " + list(c.pressure_ratio) + ";\n";
  const ResidualKriging& g = c.modulus_residual;
  text += "c.modulus_residual.length_scales = " + list(g.length_scales) + ";\n";
  text += "c.modulus_residual.signal_sd = " + number(g.signal_sd) + ";\n";
  text += "c.modulus_residual.noise_sd = " + number(g.noise_sd) + ";\n";
  text += "c.modulus_residual.centres = " + rows_of(g.centres, std::max<std::size_t>(1, g.length_scales.size())) + ";\n";
  text += "c.modulus_residual.weights = " + rows_of(g.weights, 4) + ";\n";
  text += "c.training_points = " + std::to_string(c.training_points) + ";\n";
  return text;
}

}  // namespace growthuq
