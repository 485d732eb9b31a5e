#include "growthuq/campaign/prepared_campaign.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <stdexcept>

#include "campaign/campaign_models.hpp"
#include "campaign/chunk_values.hpp"
#include "campaign/line_source.hpp"
#include "campaign/parametric_resample.hpp"
#include "campaign/shared_raw_fits.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/growth/kappa.hpp"
#include "growthuq/mechanics/mechanical_correlation.hpp"
#include "growthuq/mechanics/thin_shell_evaluators.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/stats/rank_correlation.hpp"

namespace growthuq {
namespace {

bool contains(const std::vector<std::string>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

bool wants(const Campaign& campaign, std::string_view quantity) { return contains(campaign.outputs, quantity); }

std::vector<std::string> variable_names(const LineDistributions& line) {
  std::vector<std::string> names;
  for (const LineVariable& variable : line.variables) names.push_back(variable.name);
  return names;
}

// The rows and columns of `matrix` named in `keep` (in `names` order); nullopt when fewer than
// two remain. A principal submatrix of a correlation matrix is a correlation matrix.
std::optional<RankCorrelationFile> restricted(const std::string& path, const std::vector<std::string>& names,
                                              const Eigen::MatrixXd& matrix, const std::vector<std::string>& keep) {
  std::vector<Eigen::Index> rows;
  RankCorrelationFile result;
  result.path = path;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (!contains(keep, names[i])) continue;
    rows.push_back(static_cast<Eigen::Index>(i));
    result.names.push_back(names[i]);
  }
  if (rows.size() < 2) return std::nullopt;
  const auto m = static_cast<Eigen::Index>(rows.size());
  result.spearman.resize(m, m);
  for (Eigen::Index a = 0; a < m; ++a) {
    for (Eigen::Index b = 0; b < m; ++b) result.spearman(a, b) = matrix(rows[static_cast<std::size_t>(a)], rows[static_cast<std::size_t>(b)]);
  }
  return result;
}

// The measured k is the tube and the sensor in series, so it stays below the sensor's k_sys
// (instrument.hpp). A line whose median k is not below it has at least half its draws flagged
// and its statistics (and kappa, a nan) from the rest: refused, naming both figures.
void require_sensor_stiffer_than_line(const LineDistributions& line, const Instrument& instrument, const std::string& location) {
  const LineVariable* k = line.find("k");
  const double k_sys = instrument.sensor_stiffness_N_per_m;
  if (k == nullptr || std::isinf(k_sys)) return;
  const double median = quantile(k->distribution, 0.5) * k->unit->to_si;
  if (median < k_sys) return;
  throw InputError(location, "line '" + line.name + "' (" + line.path + "): median measured stiffness k = " +
                                 format_double(median) + " N/m is not below [instrument] sensor_stiffness_N_per_m = " +
                                 format_double(k_sys) +
                                 ": expected a sensor stiffer than the tubes it measures (k_sys in N/m, or the line's k unit?)");
}

}  // namespace

std::uint64_t physics_correlation_seed(std::uint64_t campaign_seed, std::string_view line) {
  return derive_key(derive_key(mix64(campaign_seed), line), "physics_correlation");
}

PreparedCampaign::PreparedCampaign(Campaign campaign) : PreparedCampaign(std::move(campaign), nullptr, ProgressMode::none, nullptr) {}

PreparedCampaign::PreparedCampaign(Campaign campaign, Pool& pool, ProgressMode progress, std::ostream& log)
    : PreparedCampaign(std::move(campaign), &pool, progress, &log) {}

PreparedCampaign::PreparedCampaign(Campaign campaign, Pool* pool, ProgressMode progress, std::ostream* log)
    : campaign_(std::move(campaign)),
      experimental_median_(std::numeric_limits<double>::quiet_NaN()) {
  calibrates_kappa_ = wants(campaign_, KappaCalibration::quantity);
  for (const CampaignLine& campaign_line : campaign_.lines) {
    const Fidelity fidelity = campaign_.fidelity_of(campaign_line);
    if (!models_.contains(fidelity)) models_.emplace(fidelity, campaign_models(campaign_, fidelity));
    std::vector<const Evaluator*> available;
    for (const std::unique_ptr<const Evaluator>& model : models_.at(fidelity)) available.push_back(model.get());
    PreparedLine line;
    line.campaign_line = campaign_line;
    const CurveFitter fit_curves = pool != nullptr ? shared_curve_fitter(*pool, campaign_line.name, progress, *log) : CurveFitter();
    line.distributions = load_line_distributions(campaign_line, campaign_.instrument, line.raw_fit, fit_curves);
    // A law of the probe radius ([probe_radius]) is one more input of every line.
    if (campaign_.probe_radius_law) line.distributions.variables.push_back(*campaign_.probe_radius_law);
    require_sensor_stiffer_than_line(line.distributions, campaign_.instrument, file_location(campaign_.path, campaign_line.line));
    if (line.raw_fit) require_force_curves_match(*line.raw_fit, campaign_, fidelity, file_location(campaign_.path, campaign_line.line));
    const std::vector<std::string> inputs = variable_names(line.distributions);
    try {
      line.plan = plan_evaluation(available, inputs, campaign_.outputs);
    } catch (const InputError& error) {
      throw InputError(file_location(campaign_.path, campaign_line.line),
                       "line '" + campaign_line.name + "' (" + line.distributions.path + "): " + error.problem());
    }
    // Sample what the chosen models read and the outputs that are measurements, nothing else.
    std::vector<std::string> needed(campaign_.outputs);
    for (const Evaluator* evaluator : line.plan) {
      for (const std::string& read : evaluator->reads()) needed.push_back(read);
    }
    line.design_variables.name = line.distributions.name;
    line.design_variables.description = line.distributions.description;
    line.design_variables.path = line.distributions.path;
    for (const LineVariable& variable : line.distributions.variables) {
      if (contains(needed, variable.name)) line.design_variables.variables.push_back(variable);
    }
    const std::vector<std::string> sampled = variable_names(line.design_variables);

    const std::string location = file_location(campaign_.path, campaign_line.line);
    if (campaign_line.correlation == CorrelationSource::file) {
      const RankCorrelationFile file = read_rank_correlation_csv(campaign_line.correlation_path);
      for (const std::string& name : file.names) {
        if (!contains(inputs, name)) {
          throw InputError(file.path, "variable '" + name + "' of the matrix is not in line file " +
                                          line.distributions.path + " (line '" + campaign_line.name + "')");
        }
      }
      line.correlation = restricted(file.path, file.names, file.spearman, sampled);
    } else if (campaign_line.correlation == CorrelationSource::physics) {
      MechanicalDrawOptions draw = campaign_.physics_correlation;
      draw.seed = physics_correlation_seed(campaign_.seed, campaign_line.name);
      const MechanicalCorrelation physics = mechanical_rank_correlation(draw, campaign_.instrument, location);
      const std::vector<std::string> names(physics.names.begin(), physics.names.end());
      line.correlation = restricted(location + " (physics)", names, physics.spearman, sampled);
    }
    lines_.push_back(std::move(line));
  }

  for (const std::string& output : campaign_.outputs) {
    bool is_input = false;
    for (const PreparedLine& line : lines_) is_input = is_input || line.design_variables.find(output) != nullptr;
    if (!is_input && !contains(computed_outputs_, output)) computed_outputs_.push_back(output);
  }

  // What a replicate can move: a raw line's fits, the sampled laws stating tubes, and the
  // reference line's v_exp, whose median calibrates kappa.
  const auto resampled = [&](const PreparedLine& line) {
    const LineVariable* v_exp = line.distributions.find("v_exp");
    const bool calibrating = calibrates_kappa_ && line.campaign_line.name == campaign_.reference_line;
    return line.raw_fit != nullptr || states_tubes(line.design_variables) || (calibrating && v_exp != nullptr && v_exp->tubes > 0);
  };
  if (campaign_.data_uncertainty.replicates > 0 && std::none_of(lines_.begin(), lines_.end(), resampled)) {
    throw InputError(campaign_.path, "[data_uncertainty] resamples the tubes of lines given by raw = FILE and of line-file "
                                     "laws that state tubes = N, and no line has either among the variables sampled: remove "
                                     "the section, give a line's raw data, or state tubes in a line file");
  }

  if (calibrates_kappa_) {
    const auto reference = std::find_if(lines_.begin(), lines_.end(), [&](const PreparedLine& line) {
      return line.campaign_line.name == campaign_.reference_line;
    });
    if (reference == lines_.end()) {
      throw_bad_value(campaign_.path, "[growth] reference_line", campaign_.reference_line, "one of the campaign's lines");
    }
    const LineVariable* v_exp = reference->distributions.find("v_exp");
    if (v_exp == nullptr) {
      throw_bad_value(campaign_.path, "[growth] reference_line", campaign_.reference_line,
                      "a line whose distribution file (" + reference->distributions.path +
                          ") has a [v_exp] section: its median calibrates kappa");
    }
    experimental_median_ = quantile(v_exp->distribution, 0.5) * v_exp->unit->to_si;
    std::rotate(lines_.begin(), reference, reference + 1);
  }
}

bool PreparedCampaign::has_slow_samples(const PreparedLine& line) const {
  return seconds_per_sample(line.plan) >= slow_sample_seconds;
}

std::size_t PreparedCampaign::chunk_size_of(const PreparedLine& line) const {
  return has_slow_samples(line) ? campaign_.shell_fe_chunk_size : campaign_.chunk_size;
}

LineDesign PreparedCampaign::design(const PreparedLine& line) const {
  SamplingOptions options;
  options.samples = campaign_.samples;
  options.seed = campaign_.seed;
  options.position = campaign_.stratum_position;
  return sample_line(line.design_variables, options, line.correlation ? &*line.correlation : nullptr);
}

std::vector<double> PreparedCampaign::evaluate_chunk(const PreparedLine& line, const LineDesign& design,
                                                     ChunkRange range) const {
  const std::size_t n = range.end - range.begin;
  SampleBlock block(n);
  const auto& variables = line.design_variables.variables;
  for (std::size_t j = 0; j < variables.size(); ++j) {
    std::span<double> column = block.add_column(variables[j].name);
    const double to_si = variables[j].unit->to_si;
    for (std::size_t i = 0; i < n; ++i) column[i] = design.values[j][range.begin + i] * to_si;
  }
  // The stretch from d and d0 as drawn, in the line file's units, before the conversion above
  // rounds them (thin_shell.hpp, TubeDiameters).
  const LineVariable* d = line.design_variables.find("d");
  const LineVariable* d0 = line.design_variables.find("d0");
  if (d != nullptr && d0 != nullptr) {
    const auto drawn = [&](const LineVariable* variable) {
      const auto j = static_cast<std::size_t>(variable - variables.data());
      return std::span<const double>(design.values[j].data() + range.begin, n);
    };
    add_hoop_strain(block, drawn(d), d->unit->to_si, drawn(d0), d0->unit->to_si);
  }
  run_plan(line.plan, block);
  return ChunkValues::pack(block, computed_outputs_);
}

}  // namespace growthuq
