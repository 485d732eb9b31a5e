#include "growthuq/campaign/campaign_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "growthuq/core/error.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/growth/kappa.hpp"
#include "growthuq/mechanics/mechanical_correlation.hpp"
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

}  // namespace

std::uint64_t physics_correlation_seed(std::uint64_t campaign_seed, std::string_view line) {
  return derive_key(derive_key(mix64(campaign_seed), line), "physics_correlation");
}

PreparedCampaign::PreparedCampaign(Campaign campaign)
    : campaign_(std::move(campaign)),
      turgor_(campaign_.instrument, campaign_.path),
      growth_(GrowthParameters{campaign_.yield_pressure, 1.0}),
      experimental_median_(std::numeric_limits<double>::quiet_NaN()) {
  calibrates_kappa_ = wants(campaign_, "v");
  const std::vector<const Evaluator*> available{&turgor_, &modulus_, &viscosity_, &growth_};

  for (const CampaignLine& campaign_line : campaign_.lines) {
    PreparedLine line;
    line.campaign_line = campaign_line;
    line.distributions = read_line_file(campaign_line.distributions_path);
    const std::vector<std::string> inputs = variable_names(line.distributions);
    try {
      line.plan = plan_evaluation(available, inputs, campaign_.outputs);
    } catch (const InputError& error) {
      throw InputError(file_location(campaign_.path, campaign_line.line),
                       "line '" + campaign_line.name + "' (" + campaign_line.distributions_path + "): " + error.problem());
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
  run_plan(line.plan, block);
  std::vector<double> values;
  values.reserve((computed_outputs_.size() + 1) * n);
  for (const std::string& output : computed_outputs_) {
    const std::span<const double> column = block.column(output);
    values.insert(values.end(), column.begin(), column.end());
  }
  for (const SampleStatus status : block.status()) values.push_back(static_cast<double>(status));
  return values;
}

void on_coordinator(Pool& pool, const std::function<void()>& action) {
  // Message layout: kind ('I' InputError, 'E' other), location, NUL, problem.
  std::string message;
  std::exception_ptr failure;
  if (pool.is_coordinator()) {
    try {
      action();
    } catch (const InputError& error) {
      message = "I" + error.location() + '\0' + error.problem();
      failure = std::current_exception();
    } catch (const std::exception& error) {
      message = std::string("E") + '\0' + error.what();
      failure = std::current_exception();
    }
  }
  message = pool.broadcast(message);
  if (failure) std::rethrow_exception(failure);
  if (message.empty()) return;
  const std::size_t separator = message.find('\0');
  if (message[0] == 'I') throw InputError(message.substr(1, separator - 1), message.substr(separator + 1));
  throw std::runtime_error(message.substr(separator + 1));
}

namespace {

// The coordinator's LineResult for `line`: inputs copied from the design in their line-file
// unit, outputs allocated as NaN in their default unit, waiting for the chunks.
LineResult start_result(const PreparedCampaign& campaign, const PreparedLine& line, const LineDesign& design) {
  LineResult result;
  result.name = line.campaign_line.name;
  const std::size_t n = campaign.campaign().samples;
  const auto& variables = line.design_variables.variables;
  for (std::size_t j = 0; j < variables.size(); ++j) {
    result.columns.push_back(
        ResultColumn{variables[j].name, variables[j].unit, true, {design.values[j].begin(), design.values[j].end()}});
  }
  for (const std::string& output : campaign.computed_outputs()) {
    const Quantity* quantity = find_quantity(output);
    const Unit& unit = find_unit(quantity->default_unit, "quantity table", output);
    result.columns.push_back(ResultColumn{output, &unit, false, std::vector<double>(n, std::numeric_limits<double>::quiet_NaN())});
  }
  result.status.assign(n, SampleStatus::ok);
  result.correlated_inputs = design.names;
  if (design.target) result.target_spearman = design.target->target_spearman;
  if (n >= 2 && !design.ranks.empty()) {
    const std::vector<std::span<const std::uint32_t>> ranks(design.ranks.begin(), design.ranks.end());
    result.achieved_spearman = spearman_matrix_of_ranks(ranks);
  }
  return result;
}

ResultColumn* find_column(LineResult& result, std::string_view quantity) {
  for (ResultColumn& column : result.columns) {
    if (column.quantity == quantity) return &column;
  }
  return nullptr;
}

// v *= kappa. v is linear in kappa (growth_rate.hpp), so this equals evaluating with kappa;
// a product that leaves the normal range is flagged like the growth evaluator would.
void apply_kappa(LineResult& result, double kappa) {
  ResultColumn* v = find_column(result, "v");
  if (v == nullptr) return;
  for (std::size_t i = 0; i < v->values.size(); ++i) {
    if (result.status[i] != SampleStatus::ok) continue;
    v->values[i] *= kappa;
    if (!std::isnormal(v->values[i])) {
      v->values[i] = std::numeric_limits<double>::quiet_NaN();
      result.status[i] = SampleStatus::out_of_range;
    }
  }
}

}  // namespace

RunOutcome run_campaign_lines(const PreparedCampaign& campaign, Pool& pool, RunObserver& observer) {
  RunOutcome outcome;
  const std::size_t n = campaign.campaign().samples;
  const std::size_t outputs = campaign.computed_outputs().size();
  for (const PreparedLine& line : campaign.lines()) {
    if (pool.is_coordinator()) observer.line_started(line, n);
    const LineDesign design = campaign.design(line);
    std::optional<LineResult> result;
    if (pool.is_coordinator()) result = start_result(campaign, line, design);
    std::vector<ResultColumn*> output_columns;
    if (result) {
      for (const std::string& output : campaign.computed_outputs()) output_columns.push_back(find_column(*result, output));
    }
    const ChunkWork work = [&](ChunkRange range) { return campaign.evaluate_chunk(line, design, range); };
    const ChunkSink sink = [&](ChunkRange range, std::span<const double> values) {
      const std::size_t size = range.end - range.begin;
      if (values.size() != (outputs + 1) * size) throw std::logic_error("chunk of unexpected size");
      for (std::size_t o = 0; o < outputs; ++o) {
        const double to_si = output_columns[o]->unit->to_si;
        for (std::size_t i = 0; i < size; ++i) output_columns[o]->values[range.begin + i] = values[o * size + i] / to_si;
      }
      for (std::size_t i = 0; i < size; ++i) {
        result->status[range.begin + i] = static_cast<SampleStatus>(static_cast<int>(values[outputs * size + i]));
      }
      observer.chunk_done(range);
    };
    pool.run(n, campaign.campaign().chunk_size, work, sink);

    const bool is_reference = campaign.calibrates_kappa() && line.campaign_line.name == campaign.campaign().reference_line;
    if (is_reference) {
      on_coordinator(pool, [&] {
        const ResultColumn* v = find_column(*result, "v");
        std::vector<double> v_si(v->values);
        for (double& value : v_si) value *= v->unit->to_si;
        outcome.kappa = calibrate_kappa(line.campaign_line.name, campaign.experimental_median_growth_rate(),
                                        median_growth_rate(v_si, result->status));
      });
      outcome.calibrated = true;
    }
    // Writing happens on the coordinator; a failure there must stop every process, not leave
    // the others waiting in the next line's pool run.
    on_coordinator(pool, [&] {
      if (campaign.calibrates_kappa()) apply_kappa(*result, outcome.kappa);
      observer.line_done(*result, design.warnings);
    });
  }
  return outcome;
}

}  // namespace growthuq
