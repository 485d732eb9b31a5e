#include "campaign/raw_data_outputs.hpp"
#include "campaign/campaign_report.hpp"
#include "campaign/line_comparison_outputs.hpp"
#include "campaign/report_text.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/distributions/distribution.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/rawdata/raw_line_fit.hpp"
#include "growthuq/relaxation/analysis.hpp"

namespace growthuq {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// A numeric column of pure numbers (counts, likelihoods, test statistics).
ExtraColumn pure_number(const std::string& name) { return ExtraColumn{.name = name, .unit = "1"}; }

// The fitted laws' parameters as numbers, one row per variable, family tried and parameter
// (the `parameters` text of the fit tables rounds them to 6 digits, for reading).
void write_fit_parameters(ResultsH5Writer& h5, const std::string& group, const RawLineFit& fit) {
  ExtraColumn variable{"variable"}, unit{"unit"}, family{"family"}, chosen = pure_number("chosen"), parameter{"parameter"},
      value{"value"};
  for (const VariableFit& v : fit.variables) {
    for (const FamilyFit& candidate : v.candidates) {
      if (!candidate.result) continue;
      for (const auto& [name, number] : parameter_values(candidate.result->distribution)) {
        variable.text.push_back(v.variable);
        unit.text.emplace_back(v.unit->symbol);
        family.text.emplace_back(to_string(candidate.family));
        chosen.integer.push_back(candidate.family == v.best().family ? 1 : 0);
        parameter.text.push_back(name);
        value.real.push_back(number);
      }
    }
  }
  h5.write_table(group + "fit_parameters", {variable, unit, family, chosen, parameter, value});
}

void write_fits(ResultsH5Writer& h5, const std::string& line, const RawLineFit& fit) {
  ExtraColumn variable{"variable"}, unit{"unit"}, family{"family"}, parameters{"parameters"}, n = pure_number("n"),
      log_likelihood = pure_number("log_likelihood"), aic = pure_number("aic"), ks = pure_number("ks"),
      ad = pure_number("ad"), source{"source"};
  ExtraColumn c_variable{"variable"}, c_family{"family"}, c_status{"status"}, c_parameters{"parameters"},
      c_n = pure_number("n"), c_log_likelihood = pure_number("log_likelihood"), c_aic = pure_number("aic"),
      c_delta = pure_number("delta_aic"), c_ks = pure_number("ks"), c_ad = pure_number("ad"), c_reason{"reason"};
  for (const VariableFit& v : fit.variables) {
    const FitResult& best = v.best();
    variable.text.push_back(v.variable);
    unit.text.emplace_back(v.unit->symbol);
    family.text.emplace_back(to_string(best.family));
    parameters.text.push_back(distribution_parameters(best.distribution));
    n.integer.push_back(static_cast<std::int64_t>(best.sample_size));
    log_likelihood.real.push_back(best.log_likelihood);
    aic.real.push_back(best.aic);
    ks.real.push_back(best.ks_statistic);
    ad.real.push_back(best.ad_statistic);
    source.text.push_back(v.source);
    for (const FamilyFit& candidate : v.candidates) {
      const bool ok = candidate.result.has_value();
      c_variable.text.push_back(v.variable);
      c_family.text.emplace_back(to_string(candidate.family));
      c_status.text.emplace_back(ok ? "ok" : "failed");
      c_parameters.text.push_back(ok ? distribution_parameters(candidate.result->distribution) : std::string());
      c_n.integer.push_back(static_cast<std::int64_t>(v.values.size()));
      c_log_likelihood.real.push_back(ok ? candidate.result->log_likelihood : nan);
      c_aic.real.push_back(ok ? candidate.result->aic : nan);
      c_delta.real.push_back(ok ? candidate.result->aic - best.aic : nan);
      c_ks.real.push_back(ok ? candidate.result->ks_statistic : nan);
      c_ad.real.push_back(ok ? candidate.result->ad_statistic : nan);
      c_reason.text.push_back(candidate.failure);
    }
  }
  const std::string group = "lines/" + line + "/";
  h5.write_table(group + "fits", {variable, unit, family, parameters, n, log_likelihood, aic, ks, ad, source});
  h5.write_table(group + "fit_candidates",
                 {c_variable, c_family, c_status, c_parameters, c_n, c_log_likelihood, c_aic, c_delta, c_ks, c_ad, c_reason});
  write_fit_parameters(h5, group, fit);
  // The values each law was fitted to (one per tube, or per relaxation curve for tau and einf): what a
  // figure draws as the line's measured tubes beside its samples.
  for (const VariableFit& v : fit.variables) {
    h5.write_array(group + "fit_data/" + v.variable, v.values, std::string(v.unit->symbol), "tube");
  }
}

void write_relaxation(ResultsH5Writer& h5, const std::string& line, const RawLineFit& fit) {
  const RelaxationFits& relaxation = *fit.relaxation;
  const int terms = relaxation.options.terms;
  // rms is relative (of E_r / E_r(0), or F / F_peak), so a pure number.
  std::vector<ExtraColumn> table{
      {"curve"}, {"status"}, {"reason"}, pure_number("terms"), {.name = "tau_fast_s", .unit = "s"},
      {.name = "tau_mid_s", .unit = "s"}, {.name = "tau_slow_s", .unit = "s"}, {.name = "tau_slow_low_s", .unit = "s"},
      {.name = "tau_slow_high_s", .unit = "s"}, {.name = "einf_frac", .unit = "frac"},
      {.name = "E0_MPa", .unit = "MPa"}, {.name = "eta_MPa_s", .unit = "MPa s"}, {.name = "Er0_MPa", .unit = "MPa"},
      {.name = "tau_slow_se_pct", .unit = "%"}, pure_number("rms"), pure_number("aic"), {.name = "ramp_time_s", .unit = "s"},
      pure_number("points"), {.name = "delta_um", .unit = "um"}, {.name = "p_MPa", .unit = "MPa"},
      {.name = "d_um", .unit = "um"}, {.name = "h_nm", .unit = "nm"}, {.name = "rho_um", .unit = "um"}};
  ExtraColumn index{"curve_index"}, t{"t_s"}, force{"F_uN"}, fitted{"F_fit_uN"};
  std::vector<std::int32_t> curve_index;
  for (std::size_t c = 0; c < relaxation.curves.size(); ++c) {
    const RelaxationCurve& curve = relaxation.curves[c];
    const CurveFit& f = relaxation.fits[c];
    const bool fitted_ok = f.ok && !f.tau.empty();
    const auto value = [&](bool present, double x) { return present && std::isfinite(x) ? x : nan; };
    table[0].text.push_back(f.curve);
    table[1].text.emplace_back(fit_status(f));
    table[2].text.push_back(f.reason);
    table[3].integer.push_back(terms);
    table[4].real.push_back(value(fitted_ok && terms > 1, f.tau.empty() ? nan : f.tau.front()));
    table[5].real.push_back(value(fitted_ok && terms == 3, f.tau.size() == 3 ? f.tau[1] : nan));
    table[6].real.push_back(value(fitted_ok, f.tau.empty() ? nan : f.tau.back()));
    table[7].real.push_back(value(fitted_ok, f.tau_slow_low));
    table[8].real.push_back(value(fitted_ok, f.tau_slow_high));
    table[9].real.push_back(value(fitted_ok, f.einf));
    table[10].real.push_back(value(fitted_ok, to_MPa(f.relaxing_modulus)));
    table[11].real.push_back(value(fitted_ok, to_MPa_s(f.viscosity)));
    table[12].real.push_back(value(fitted_ok, to_MPa(f.modulus0)));
    table[13].real.push_back(value(fitted_ok, to_pct(f.tau_slow_relative_se)));
    table[14].real.push_back(value(f.points > 0, f.rms));
    table[15].real.push_back(value(f.points > 0, f.aic));
    table[16].real.push_back(f.ramp_time);
    table[17].integer.push_back(static_cast<std::int64_t>(f.points));
    table[18].real.push_back(to_um(curve.indentation));
    table[19].real.push_back(to_MPa(curve.turgor));
    table[20].real.push_back(to_um(curve.diameter));
    table[21].real.push_back(to_nm(curve.thickness));
    table[22].real.push_back(to_um(curve.probe_radius_m));
    const std::vector<double> model = fitted_force(curve, f, relaxation.options.poisson_ratio);
    for (std::size_t i = 0; i < curve.t.size(); ++i) {
      curve_index.push_back(static_cast<std::int32_t>(c));
      t.real.push_back(curve.t[i]);
      force.real.push_back(to_uN(curve.force[i]));
      fitted.real.push_back(to_uN(model[i]));
    }
  }
  const std::string group = "lines/" + line + "/relaxation";
  h5.write_table(group + "/fits", table);
  h5.write_array(group + "/points/curve_index", curve_index, "1", "point");
  h5.write_array(group + "/points/t_s", t.real, "s", "point");
  h5.write_array(group + "/points/F_uN", force.real, "uN", "point");
  h5.write_array(group + "/points/F_fit_uN", fitted.real, "uN", "point");
  h5.write_attribute(group, "fit", relaxation.options.ramp_aware ? "ramp_aware" : "step");
  h5.write_attribute(group, "terms", static_cast<double>(terms));
  h5.write_attribute(group, "curves_path", fit.raw.relaxation.curves);
}

// The force curves of [force_curves] as processed: one row per curve, one per tube, and the
// approaches' points, for the force-curve figure (tools/plotting/force_curves.py).
void write_force_curves(ResultsH5Writer& h5, const std::string& line, const RawLineFit& fit) {
  const ForceCurveFits& force_curves = *fit.force_curves;
  std::vector<ExtraColumn> table{
      {"curve"}, {"tube"}, pure_number("repetition"), {"status"}, {"reason"},
      {.name = "baseline_offset_uN", .unit = "uN"}, {.name = "baseline_tilt_N_per_m", .unit = "N/m"},
      {.name = "contact_z_um", .unit = "um"}, {.name = "window_low_uN", .unit = "uN"},
      {.name = "window_high_uN", .unit = "uN"}, {.name = "k_m_N_per_m", .unit = "N/m"},
      {.name = "fit_intercept_uN", .unit = "uN"}, {.name = "k_N_per_m", .unit = "N/m"},
      {.name = "u_N_per_m", .unit = "N/m"}};
  std::vector<std::int32_t> curve_index;
  std::vector<double> position, force;
  for (std::size_t c = 0; c < force_curves.curves.size(); ++c) {
    const CurveResult& r = force_curves.curves[c];
    const bool ok = r.status == CurveStatus::ok;
    table[0].text.push_back(r.curve);
    table[1].text.push_back(r.tube);
    table[2].integer.push_back(r.repetition);
    table[3].text.emplace_back(to_string(r.status));
    table[4].text.push_back(r.reason);
    table[5].real.push_back(to_uN(r.baseline_offset_N));
    table[6].real.push_back(r.baseline_tilt_N_per_m);
    table[7].real.push_back(ok ? to_um(r.contact_position_m) : nan);
    table[8].real.push_back(ok ? to_uN(r.window_low_N) : nan);
    table[9].real.push_back(ok ? to_uN(r.window_high_N) : nan);
    table[10].real.push_back(ok ? r.measured_stiffness : nan);
    table[11].real.push_back(ok ? to_uN(r.fit_intercept_N) : nan);
    table[12].real.push_back(ok ? r.stiffness : nan);
    table[13].real.push_back(ok ? r.uncertainty : nan);
    const ForceCurve& data = force_curves.data[c];
    for (std::size_t i = 0; i < data.approach_end; ++i) {
      curve_index.push_back(static_cast<std::int32_t>(c));
      position.push_back(to_um(data.position[i]));
      force.push_back(to_uN(data.force[i]));
    }
  }
  std::vector<ExtraColumn> tubes{{"tube"}, pure_number("curves"), pure_number("ok"), {.name = "k_N_per_m", .unit = "N/m"},
                                 {.name = "spread_N_per_m", .unit = "N/m"}, {.name = "u_N_per_m", .unit = "N/m"}};
  for (const TubeStiffness& tube : force_curves.tubes) {
    tubes[0].text.push_back(tube.tube);
    tubes[1].integer.push_back(static_cast<std::int64_t>(tube.curves));
    tubes[2].integer.push_back(static_cast<std::int64_t>(tube.ok));
    tubes[3].real.push_back(tube.ok > 0 ? tube.stiffness : nan);
    tubes[4].real.push_back(tube.ok > 0 ? tube.spread : nan);
    tubes[5].real.push_back(tube.ok > 0 ? tube.uncertainty : nan);
  }
  const std::string group = "lines/" + line + "/force_curves";
  const bool relative = fit.raw.force_curves.options.window.convention == WindowConvention::relative;
  h5.write_table(group + "/curves", table);
  h5.write_table(group + "/tubes", tubes);
  h5.write_array(group + "/points/curve_index", curve_index, "1", "point");
  h5.write_array(group + "/points/z_um", position, "um", "point");
  h5.write_array(group + "/points/F_uN", force, "uN", "point");
  h5.write_attribute(group, "curves_path", fit.raw.force_curves.curves);
  h5.write_attribute(group, "window", std::string(relative ? "relative" : "absolute"));
}

// "included" when the line's values were drawn within their measurement uncertainty, else "none".
const char* measurement_error_cell(const DataUncertainty& row) { return row.measurement_error ? "included" : "none"; }

std::vector<ExtraColumn> uncertainty_table(std::span<const DataUncertainty> rows) {
  std::vector<ExtraColumn> table{{"line"}, {"quantity"}, {"unit"}, {"median"}, {"median_ci_low"}, {"median_ci_high"},
                                 {"data_ci_low"}, {"data_ci_high"}, {"data_sd"}, pure_number("replicates"),
                                 pure_number("failed_replicates"), pure_number("samples_per_replicate"),
                                 {"measurement_error"}};
  for (const DataUncertainty& row : rows) {
    table[0].text.push_back(row.line);
    table[1].text.push_back(row.quantity);
    table[2].text.push_back(row.unit);
    table[3].real.push_back(row.median);
    table[4].real.push_back(row.median_ci_low);
    table[5].real.push_back(row.median_ci_high);
    table[6].real.push_back(row.low);
    table[7].real.push_back(row.high);
    table[8].real.push_back(row.sd);
    table[9].integer.push_back(static_cast<std::int64_t>(row.replicates));
    table[10].integer.push_back(static_cast<std::int64_t>(row.failed));
    table[11].integer.push_back(static_cast<std::int64_t>(row.samples));
    table[12].text.emplace_back(measurement_error_cell(row));
  }
  return table;
}

constexpr const char* method_text =
    "parametric bootstrap over tubes: each replicate redraws every raw-data variable (as many values as the line "
    "has) from its fitted law and refits it (least AIC), redraws every line-file law that states tubes = N (N "
    "values) and refits it within its family (maximum likelihood), keeps the other laws, reruns the campaign's "
    "models with its own seed and takes the median; data_ci_low/high are the 2.5 and 97.5 % quantiles of the replicate medians (percentile interval). It "
    "holds the uncertainty from fitting finitely many tubes; median_ci_low/high hold the Monte Carlo error only (for "
    "the v of a line other than the reference line also kappa's). measurement_error = included: the line's k of force "
    "curves was also drawn within each tube's measurement uncertainty u in each replicate, so the interval includes "
    "measurement error.";

std::string uncertainty_report(std::span<const DataUncertainty> rows, const Campaign& campaign) {
  if (rows.empty()) return {};
  std::size_t line_width = 6;
  for (const DataUncertainty& row : rows) line_width = std::max(line_width, row.line.size() + 2);
  std::string text = "\ndata uncertainty of the medians (parametric bootstrap over tubes, " +
                     std::to_string(campaign.data_uncertainty.replicates) + " replicates x " +
                     std::to_string(rows.front().samples) +
                     " samples per line; the data intervals of the summary above, with the replicates behind them):\n" +
                     padded("line", line_width) + padded("quantity", 10) + padded("unit", 8) + padded("median", 10) +
                     padded("data 95 % interval", 22) + padded("Monte Carlo 95 % CI", 22) + "replicates\n";
  for (const DataUncertainty& row : rows) {
    text += padded(row.line, line_width) + padded(row.quantity, 10) + padded(row.unit, 8) + padded(significant(row.median), 10) +
            padded(data_interval_is_fixed(row.low, row.high) ? std::string("fixed")
                                                             : "[" + significant(row.low) + ", " + significant(row.high) + "]",
                   22) +
            padded("[" + significant(row.median_ci_low) + ", " + significant(row.median_ci_high) + "]", 22) +
            std::to_string(row.replicates) +
            (row.failed > 0 ? " (" + std::to_string(row.failed) + " failed)" : std::string()) + "\n";
  }
  return text;
}

}  // namespace

void add_data_intervals(std::span<QuantitySummary> summaries, std::span<const DataUncertainty> rows) {
  for (QuantitySummary& summary : summaries) {
    for (const DataUncertainty& row : rows) {
      if (row.line != summary.line || row.quantity != summary.quantity) continue;
      summary.data_ci_low = row.low;
      summary.data_ci_high = row.high;
    }
  }
}

std::string data_uncertainty_csv_text(std::span<const DataUncertainty> rows) {
  CsvWriter writer({"line", "quantity", "unit", "median", "median_ci_low", "median_ci_high", "data_ci_low",
                    "data_ci_high", "data_sd", "replicates", "failed_replicates", "samples_per_replicate",
                    "measurement_error"});
  for (const DataUncertainty& row : rows) {
    writer.add_row({row.line, row.quantity, row.unit, number_cell(row.median), number_cell(row.median_ci_low),
                    number_cell(row.median_ci_high), number_cell(row.low), number_cell(row.high), number_cell(row.sd),
                    std::to_string(row.replicates), std::to_string(row.failed), std::to_string(row.samples),
                    measurement_error_cell(row)});
  }
  return writer.text();
}

std::string write_raw_data_outputs(const PreparedCampaign& campaign, std::span<const QuantitySummary> summaries,
                                   DataUncertaintyResult uncertainty, ResultsH5Writer* h5, const std::string& directory) {
  const Campaign& c = campaign.campaign();
  std::string report;
  for (const PreparedLine& line : campaign.lines()) {
    if (!line.raw_fit) continue;
    report += "\n" + format_raw_fit_report(*line.raw_fit);
    if (h5 != nullptr) {
      write_fits(*h5, line.campaign_line.name, *line.raw_fit);
      if (line.raw_fit->relaxation) write_relaxation(*h5, line.campaign_line.name, *line.raw_fit);
      if (line.raw_fit->force_curves) write_force_curves(*h5, line.campaign_line.name, *line.raw_fit);
    }
  }

  const std::string csv_path = (std::filesystem::path(directory) / data_uncertainty_csv_name).string();
  if (uncertainty.rows.empty()) {  // (the commit removes a stale one of a --force rerun)
    if (c.lines.size() >= 2) report += comparisons_need_data_interval();
    return report;
  }
  for (DataUncertainty& row : uncertainty.rows) {
    for (const QuantitySummary& summary : summaries) {
      if (summary.line == row.line && summary.quantity == row.quantity) {
        row.median = summary.median;
        row.median_ci_low = summary.median_ci_low;
        row.median_ci_high = summary.median_ci_high;
      }
    }
  }
  write_file_atomically(csv_path, data_uncertainty_csv_text(uncertainty.rows), Overwrite::allow);
  if (h5 != nullptr) {
    const std::vector<ExtraColumn> all = uncertainty_table(uncertainty.rows);
    h5->write_table("data_uncertainty", all);
    h5->write_attribute("data_uncertainty", "method", std::string(method_text));
    std::string sources;
    for (const std::string& source : data_uncertainty_sources(campaign)) sources += source + "\n";
    h5->write_attribute("data_uncertainty", "resampled", sources);
    for (const PreparedLine& line : campaign.lines()) {
      std::vector<DataUncertainty> rows;
      for (const DataUncertainty& row : uncertainty.rows) {
        if (row.line == line.campaign_line.name) rows.push_back(row);
      }
      if (rows.empty()) continue;
      const std::string group = "lines/" + line.campaign_line.name;
      h5->write_table(group + "/data_uncertainty", uncertainty_table(rows));
      for (const DataUncertainty& row : rows) {
        const std::string path = group + "/data_uncertainty_replicates/" + row.quantity;
        h5->write_array(path, row.replicate_medians, row.unit, "replicate");
        h5->write_attribute(path, "unit", row.unit);
      }
    }
  }
  report += uncertainty_report(uncertainty.rows, c);
  report += "  redrawn in each replicate (the rest fixed: Monte Carlo error only):\n";
  for (const std::string& source : data_uncertainty_sources(campaign)) report += "    " + source + "\n";
  for (const std::string& failure : uncertainty.failures) report += "  failed " + failure + "\n";
  std::vector<std::string> line_order;
  for (const CampaignLine& line : c.lines) line_order.push_back(line.name);
  report += write_line_comparisons(compare_campaign_lines(uncertainty.rows, line_order), c.lines.size(), h5, directory);
  return report;
}

}  // namespace growthuq
