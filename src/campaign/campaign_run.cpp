#include "growthuq/campaign/campaign_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>

#include "campaign/line_source.hpp"
#include "campaign/shared_raw_fits.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/growth/kappa.hpp"
#include "growthuq/mechanics/mechanical_correlation.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/stats/quantity_summary.hpp"
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

// Which process does each of `costs.size()` pieces of work: the next piece (in the order given)
// goes to the process with the least work so far, the coordinator starting with
// `coordinator_load` for what it alone does; ties go to the highest rank. Process `left_out`
// (if > 0) gets none.
std::vector<int> share_out(const std::vector<double>& costs, int processes, double coordinator_load, int left_out = -1) {
  std::vector<double> load(static_cast<std::size_t>(processes), 0.0);
  load[0] = coordinator_load;
  if (left_out > 0) load[static_cast<std::size_t>(left_out)] = std::numeric_limits<double>::infinity();
  std::vector<int> owner;
  for (const double cost : costs) {
    int best = processes - 1;
    for (int p = processes - 1; p >= 0; --p) {
      if (load[static_cast<std::size_t>(p)] < load[static_cast<std::size_t>(best)]) best = p;
    }
    owner.push_back(best);
    load[static_cast<std::size_t>(best)] += cost;
  }
  return owner;
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
      turgor_(campaign_.instrument, campaign_.path),
      growth_(GrowthParameters{campaign_.yield_pressure, 1.0}),
      experimental_median_(std::numeric_limits<double>::quiet_NaN()) {
  calibrates_kappa_ = wants(campaign_, "v");
  const std::vector<const Evaluator*> available{&turgor_, &modulus_, &viscosity_, &growth_};

  for (const CampaignLine& campaign_line : campaign_.lines) {
    PreparedLine line;
    line.campaign_line = campaign_line;
    const CurveFitter fit_curves = pool != nullptr ? shared_curve_fitter(*pool, campaign_line.name, progress, *log) : CurveFitter();
    line.distributions = load_line_distributions(campaign_line, campaign_.instrument, line.raw_fit, fit_curves);
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

namespace {

// Bytes of a trivially copyable value, appended to and read from a message.
template <class T>
void append_bytes(std::string& message, const T& value) {
  message.append(reinterpret_cast<const char*>(&value), sizeof value);
}
template <class T>
T read_bytes(const std::string& message, std::size_t& at) {
  T value;
  std::memcpy(&value, message.data() + at, sizeof value);
  at += sizeof value;
  return value;
}

// Sends the design process `owner` made of `line` to every other process: its columns, and for
// the coordinator's report its target and warnings (the rest of the outline is not used past
// the design; names are the line's variables).
void share_design(LineDesign& design, const PreparedLine& line, std::size_t samples, int owner, Pool& pool) {
  const std::size_t columns = line.design_variables.variables.size();
  const bool mine = pool.rank() == owner;
  if (!mine) {
    design.names.clear();
    for (const LineVariable& variable : line.design_variables.variables) design.names.push_back(variable.name);
    design.ranks.resize(columns);
    design.values.resize(columns);
    design.strictly_increasing.assign(columns, 0);
  }
  for (std::size_t j = 0; j < columns; ++j) {
    pool.broadcast_vector(design.ranks[j], samples, owner);
    pool.broadcast_vector(design.values[j], samples, owner);
  }
  pool.broadcast_bytes(std::as_writable_bytes(std::span(design.strictly_increasing)), owner);

  // The message: m, the m x m target Spearman matrix (m = 0: none), then each warning's length
  // and text.
  std::string message;
  if (mine) {
    const Eigen::Index m = design.target ? design.target->target_spearman.rows() : 0;
    append_bytes(message, static_cast<std::uint64_t>(m));
    for (Eigen::Index a = 0; a < m; ++a) {
      for (Eigen::Index b = 0; b < m; ++b) append_bytes(message, design.target->target_spearman(a, b));
    }
    for (const std::string& warning : design.warnings) {
      append_bytes(message, static_cast<std::uint64_t>(warning.size()));
      message += warning;
    }
  }
  std::uint64_t size = message.size();
  pool.broadcast_bytes(std::as_writable_bytes(std::span(&size, 1)), owner);
  message.resize(size);
  pool.broadcast_bytes(std::as_writable_bytes(std::span(message.data(), message.size())), owner);
  if (mine) return;
  std::size_t at = 0;
  const auto m = static_cast<Eigen::Index>(read_bytes<std::uint64_t>(message, at));
  if (m > 0) {
    ImanConoverTarget target;
    target.names = design.names;
    target.target_spearman.resize(m, m);
    for (Eigen::Index a = 0; a < m; ++a) {
      for (Eigen::Index b = 0; b < m; ++b) target.target_spearman(a, b) = read_bytes<double>(message, at);
    }
    design.target = std::move(target);
  }
  design.warnings.clear();
  while (at < message.size()) {
    const auto length = static_cast<std::size_t>(read_bytes<std::uint64_t>(message, at));
    design.warnings.push_back(message.substr(at, length));
    at += length;
  }
}

}  // namespace

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

namespace {

// What the coordinator's action threw, to be raised on every process when they next meet
// (share): the coordinator's work after a line (handing it to the writers) then holds nobody up,
// and a failure still stops every process at the same point.
class CoordinatorFailure {
 public:
  // On the coordinator: action(), unless an earlier action failed; what it throws is kept.
  void run(Pool& pool, const std::function<void()>& action) {
    if (!pool.is_coordinator() || failure_) return;
    try {
      action();
    } catch (const InputError& error) {
      message_ = "I" + error.location() + '\0' + error.problem();
      failure_ = std::current_exception();
    } catch (const std::exception& error) {
      message_ = std::string("E") + '\0' + error.what();
      failure_ = std::current_exception();
    }
  }

  // Every process: raises the kept failure everywhere (InputError as InputError, anything else
  // as std::runtime_error; on the coordinator the original exception).
  void share(Pool& pool) {
    // Message layout: kind ('I' InputError, 'E' other), location, NUL, problem.
    const std::string message = pool.broadcast(message_);
    if (failure_) std::rethrow_exception(failure_);
    if (message.empty()) return;
    const std::size_t separator = message.find('\0');
    if (message[0] == 'I') throw InputError(message.substr(1, separator - 1), message.substr(separator + 1));
    throw std::runtime_error(message.substr(separator + 1));
  }

 private:
  std::string message_;
  std::exception_ptr failure_;
};

}  // namespace

void on_coordinator(Pool& pool, const std::function<void()>& action) {
  CoordinatorFailure failure;
  failure.run(pool, action);
  failure.share(pool);
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// A line's LineResult without values: its name and columns (inputs in their line-file unit,
// then outputs in their default unit).
LineResult result_layout(const PreparedCampaign& campaign, const PreparedLine& line) {
  LineResult result;
  result.name = line.campaign_line.name;
  for (const LineVariable& variable : line.design_variables.variables) {
    result.columns.push_back(ResultColumn{variable.name, variable.unit, true, {}});
  }
  for (const std::string& output : campaign.computed_outputs()) {
    const Quantity* quantity = find_quantity(output);
    result.columns.push_back(ResultColumn{output, &find_unit(quantity->default_unit, "quantity table", output), false, {}});
  }
  return result;
}

// The evaluated outputs of a line (in their default units, v scaled by kappa) and every sample's
// status: filled by the chunks on the coordinator, then sent to every process.
struct LineOutputs {
  std::vector<LargeVector<double>> columns;  // campaign.computed_outputs() order
  LargeVector<SampleStatus> status;
};

// v *= kappa. v is linear in kappa (growth_rate.hpp), so this equals evaluating with kappa;
// a product that leaves the normal range is flagged like the growth evaluator would.
void apply_kappa(std::span<double> v, std::span<SampleStatus> status, double kappa) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (status[i] != SampleStatus::ok) continue;
    v[i] *= kappa;
    if (!std::isnormal(v[i])) {
      v[i] = std::numeric_limits<double>::quiet_NaN();
      status[i] = SampleStatus::out_of_range;
    }
  }
}

// The coordinator's LineResult: the design's inputs and the evaluated outputs, moved in.
LineResult assemble_result(const PreparedCampaign& campaign, const PreparedLine& line, LineDesign& design,
                           LineOutputs& outputs) {
  LineResult result = result_layout(campaign, line);
  const std::size_t inputs = design.values.size();
  for (std::size_t c = 0; c < result.columns.size(); ++c) {
    result.columns[c].values = std::move(c < inputs ? design.values[c] : outputs.columns[c - inputs]);
  }
  result.status.assign(outputs.status.begin(), outputs.status.end());
  result.correlated_inputs = design.names;
  if (design.target) result.target_spearman = design.target->target_spearman;
  if (result.status.size() >= 2 && !design.ranks.empty()) {
    const std::vector<std::span<const std::uint32_t>> ranks(design.ranks.begin(), design.ranks.end());
    result.achieved_spearman = spearman_matrix_of_ranks(ranks);
  }
  return result;
}

bool wants_summary(const std::vector<std::string>& outputs, std::string_view quantity) {
  return std::find(outputs.begin(), outputs.end(), quantity) != outputs.end();
}

// One column's share of the line's statistics, as the pool carries it (doubles): its
// ColumnAnalysis without the order statistics, and its summary when it has one.
//   [verdict, count, mean, squared deviations, has summary,
//    n, n_flagged, median, q1, q3, iqr, p10, p90, mean, sd, median_ci_low, median_ci_high,
//    number of ranks, the ranks' bytes (two 32-bit ranks per double)]
constexpr std::size_t column_header_size = 18;

struct ColumnStatistics {
  ColumnAnalysis analysis;
  std::optional<QuantitySummary> summary;  // line, quantity and unit left empty
};

std::vector<double> serialize(const ColumnStatistics& statistics) {
  const ColumnAnalysis& analysis = statistics.analysis;
  const std::size_t ranks = analysis.twice_ranks.size();
  std::vector<double> message = {static_cast<double>(analysis.verdict), static_cast<double>(analysis.moments.count),
                                 analysis.moments.mean, analysis.moments.squared_deviations,
                                 statistics.summary ? 1.0 : 0.0};
  const QuantitySummary s = statistics.summary.value_or(QuantitySummary{});
  message.insert(message.end(), {static_cast<double>(s.n), static_cast<double>(s.n_flagged), s.median, s.q1, s.q3, s.iqr,
                                 s.p10, s.p90, s.mean, s.sd, s.median_ci_low, s.median_ci_high, static_cast<double>(ranks)});
  message.resize(column_header_size + (ranks + 1) / 2);
  if (ranks > 0) std::memcpy(message.data() + column_header_size, analysis.twice_ranks.data(), ranks * sizeof(std::uint32_t));
  return message;
}

ColumnStatistics deserialize(std::span<const double> message) {
  if (message.size() < column_header_size) throw std::logic_error("column statistics message too short");
  ColumnStatistics statistics;
  ColumnAnalysis& analysis = statistics.analysis;
  analysis.verdict = static_cast<ColumnAnalysis::Verdict>(static_cast<int>(message[0]));
  analysis.moments = {static_cast<std::size_t>(message[1]), message[2], message[3]};
  if (message[4] != 0.0) {
    QuantitySummary s;
    s.n = static_cast<std::size_t>(message[5]);
    s.n_flagged = static_cast<std::size_t>(message[6]);
    s.median = message[7];
    s.q1 = message[8];
    s.q3 = message[9];
    s.iqr = message[10];
    s.p10 = message[11];
    s.p90 = message[12];
    s.mean = message[13];
    s.sd = message[14];
    s.median_ci_low = message[15];
    s.median_ci_high = message[16];
    statistics.summary = s;
  }
  const auto ranks = static_cast<std::size_t>(message[17]);
  if (message.size() != column_header_size + (ranks + 1) / 2) throw std::logic_error("column statistics message of unexpected size");
  analysis.twice_ranks.resize(ranks);
  if (ranks > 0) std::memcpy(analysis.twice_ranks.data(), message.data() + column_header_size, ranks * sizeof(std::uint32_t));
  return statistics;
}

// Column c's statistics: the analysis over the ok samples (analysis_samples), and, when the
// campaign reports the quantity, its summary. One sort serves both when the summary counts the
// same samples (no v = 0 of a no_growth sample among them, every ok value finite); otherwise
// summarize_quantity selects its order statistics itself.
ColumnStatistics column_statistics(const ResultColumn& column, std::span<const double> values,
                                   std::span<const std::uint32_t> strata, std::span<const SampleStatus> status,
                                   std::span<const std::uint32_t> used, const std::vector<std::string>& outputs) {
  const bool summarize = wants_summary(outputs, column.quantity);
  const bool no_growth =
      column.quantity == "v" && std::find(status.begin(), status.end(), SampleStatus::no_growth) != status.end();
  ColumnStatistics statistics;
  const bool analyzed = used.size() >= 3;  // analyze_line's minimum
  std::vector<std::size_t> positions;
  if (summarize && !no_growth) positions = summary_positions(used.size());
  if (analyzed) statistics.analysis = analyze_column(values, used, positions, strata);
  if (!summarize) return statistics;
  if (analyzed && !no_growth && statistics.analysis.verdict == ColumnAnalysis::Verdict::used) {
    statistics.summary = summary_from_order("", column, values.size() - used.size(), statistics.analysis.moments,
                                            statistics.analysis.order_statistics);
  } else {
    ResultColumn copy{column.quantity, column.unit, column.is_input, {values.begin(), values.end()}};
    statistics.summary = summarize_quantity("", copy, status);
  }
  return statistics;
}

}  // namespace

LineStatistics line_statistics(const LineResult& result, const std::vector<std::string>& outputs) {
  LineStatistics statistics;
  for (const std::string& output : outputs) {
    for (const ResultColumn& column : result.columns) {
      if (column.quantity == output) statistics.summaries.push_back(summarize_quantity(result.name, column, result.status));
    }
  }
  statistics.analysis = analyze_line(result);
  return statistics;
}

RunOutcome run_campaign_lines(const PreparedCampaign& campaign, Pool& pool, RunObserver& observer, ChunkJournal* journal) {
  RunOutcome outcome;
  const std::size_t n = campaign.campaign().samples;
  const std::size_t outputs = campaign.computed_outputs().size();
  // The coordinator finishes each line (gathers its statistics, assembles it, hands it to the
  // observer) when the next one starts, while that line's designer may still be designing it;
  // the other processes need nothing from that. A failure of the observer (writing) reaches them
  // when the next design is shared.
  CoordinatorFailure observer_failure;
  std::function<void()> finish_line;
  const auto finish_previous_line = [&] {
    if (!finish_line) return;
    const auto start = Clock::now();
    observer_failure.run(pool, finish_line);
    finish_line = nullptr;
    outcome.timings.observer += seconds_since(start);
  };
  // Designs are made whole by one process each, one line ahead: rank 0 makes line 0's while
  // line 1's designer makes line 1's, then line i + 1's designer (process 1 + i % (K - 1), never
  // rank 0) makes it while the others compute line i's statistics, which it takes no part in.
  // A design is the same whoever makes it, so the results do not depend on K.
  const std::size_t line_count = campaign.lines().size();
  const int processes = pool.size();
  const auto designer_of = [&](std::size_t line_index) {
    return processes == 1 || line_index == 0 ? 0 : 1 + static_cast<int>((line_index - 1) % static_cast<std::size_t>(processes - 1));
  };
  std::map<std::size_t, LineDesign> held;  // designs this process made of lines not yet shared
  const auto make_design = [&](std::size_t line_index) {
    held.emplace(line_index, campaign.design(campaign.lines()[line_index]));
  };
  for (std::size_t index = 0; index < line_count; ++index) {
    const PreparedLine& line = campaign.lines()[index];
    // The observer sees each line finished before the next one starts.
    finish_previous_line();
    observer_failure.run(pool, [&] { observer.line_started(line, n); });
    auto start = Clock::now();
    if (index == 0 || processes == 1) {
      if (pool.is_coordinator()) make_design(index);
      if (index == 0 && processes > 1 && line_count > 1 && pool.rank() == designer_of(1)) make_design(1);
    }
    auto design = std::make_shared<LineDesign>();
    const int designer = designer_of(index);
    if (pool.rank() == designer) {
      *design = std::move(held.at(index));
      held.erase(index);
    }
    if (processes > 1) share_design(*design, line, n, designer, pool);
    observer_failure.share(pool);
    outcome.timings.design += seconds_since(start);

    // The models, in chunks; the coordinator collects the outputs.
    start = Clock::now();
    const LineResult layout = result_layout(campaign, line);
    auto evaluated = std::make_shared<LineOutputs>();
    evaluated->columns.resize(outputs);
    std::vector<double> to_si;
    for (std::size_t o = 0; o < outputs; ++o) to_si.push_back(layout.columns[design->values.size() + o].unit->to_si);
    if (pool.is_coordinator()) {
      for (LargeVector<double>& column : evaluated->columns) column.resize(n);  // every chunk writes its range
      evaluated->status.resize(n);
    }
    const ChunkWork work = [&](ChunkRange range) { return campaign.evaluate_chunk(line, *design, range); };
    const ChunkSink sink = [&](ChunkRange range, std::span<const double> values) {
      const std::size_t size = range.end - range.begin;
      if (values.size() != (outputs + 1) * size) throw std::logic_error("chunk of unexpected size");
      for (std::size_t o = 0; o < outputs; ++o) {
        double* out = evaluated->columns[o].data() + range.begin;
        for (std::size_t i = 0; i < size; ++i) out[i] = values[o * size + i] / to_si[o];
      }
      for (std::size_t i = 0; i < size; ++i) {
        evaluated->status[range.begin + i] = static_cast<SampleStatus>(static_cast<int>(values[outputs * size + i]));
      }
      observer.chunk_done(range);
    };
    if (journal == nullptr) {
      pool.run(n, campaign.campaign().chunk_size, work, sink);
    } else {
      on_coordinator(pool, [&] { journal->replay(index, sink); });  // a read error stops every process
      const ChunkSink record_then_sink = [&](ChunkRange range, std::span<const double> values) {
        journal->record(index, range, values);
        sink(range, values);
      };
      pool.run(n, campaign.campaign().chunk_size, work, record_then_sink,
               [&](ChunkRange range) { return journal->holds(index, range); });
    }
    const auto v = std::find(campaign.computed_outputs().begin(), campaign.computed_outputs().end(), "v");
    const bool is_reference = campaign.calibrates_kappa() && line.campaign_line.name == campaign.campaign().reference_line;
    if (is_reference) {
      on_coordinator(pool, [&] {
        const LargeVector<double>& v_values = evaluated->columns[static_cast<std::size_t>(v - campaign.computed_outputs().begin())];
        const double v_to_si = to_si[static_cast<std::size_t>(v - campaign.computed_outputs().begin())];
        std::vector<double> v_si(v_values.begin(), v_values.end());
        for (double& value : v_si) value *= v_to_si;
        outcome.kappa = calibrate_kappa(line.campaign_line.name, campaign.experimental_median_growth_rate(),
                                        median_growth_rate(v_si, evaluated->status));
      });
      outcome.calibrated = true;
    }
    if (pool.is_coordinator() && campaign.calibrates_kappa() && v != campaign.computed_outputs().end()) {
      apply_kappa(evaluated->columns[static_cast<std::size_t>(v - campaign.computed_outputs().begin())], evaluated->status,
                  outcome.kappa);
    }
    outcome.timings.evaluation += seconds_since(start);

    // Every process gets the outputs and statuses, to share the statistics out by column.
    start = Clock::now();
    pool.broadcast_vector(evaluated->status, n, 0);
    for (LargeVector<double>& column : evaluated->columns) pool.broadcast_vector(column, n, 0);
    std::vector<std::span<const double>> values(design->values.begin(), design->values.end());
    values.insert(values.end(), evaluated->columns.begin(), evaluated->columns.end());
    outcome.timings.sharing += seconds_since(start);

    // The statistics, column by column, shared out in advance; then the coordinator assembles
    // the line's result and puts the statistics together.
    start = Clock::now();
    auto used = std::make_shared<const std::vector<std::uint32_t>>(analysis_samples(evaluated->status));
    const std::size_t columns = layout.columns.size();
    // An input ranked by its strata costs about a quarter of a sorted column (measured); the
    // coordinator shares its core with its writer thread (about half a column's work).
    std::vector<double> costs(columns, 1.0);
    for (std::size_t c = 0; c < design->ranks.size(); ++c) costs[c] = design->strictly_increasing[c] != 0 ? 0.25 : 1.0;
    // The next line's designer, when it has still to make it, takes none: it designs meanwhile.
    const std::size_t next = index + 1;
    const int next_designer = processes > 1 && next >= 2 && next < line_count ? designer_of(next) : -1;
    const std::vector<int> owner = share_out(costs, pool.size(), 0.5, next_designer);
    auto statistics = std::make_shared<std::vector<ColumnStatistics>>(columns);
    std::vector<double> mine;  // [column, size, message] for each column this process computes
    for (std::size_t c = 0; c < columns; ++c) {
      if (owner[c] != pool.rank()) continue;
      // An input whose values strictly increase with its strata is ranked by them, unsorted.
      const bool by_strata = c < design->ranks.size() && design->strictly_increasing[c] != 0;
      (*statistics)[c] = column_statistics(layout.columns[c], values[c],
                                           by_strata ? std::span<const std::uint32_t>(design->ranks[c])
                                                     : std::span<const std::uint32_t>{},
                                           evaluated->status, *used, campaign.campaign().outputs);
      if (pool.is_coordinator()) continue;
      const std::vector<double> message = serialize((*statistics)[c]);
      mine.push_back(static_cast<double>(c));
      mine.push_back(static_cast<double>(message.size()));
      mine.insert(mine.end(), message.begin(), message.end());
      (*statistics)[c] = {};
    }
    if (pool.is_coordinator()) {
      // Finished during the next line's design (or after the last line).
      finish_line = [&campaign, &pool, &observer, &line, design, evaluated, used, statistics] {
        const std::vector<std::vector<double>> gathered = pool.gather({});
        for (const std::vector<double>& contribution : gathered) {
          for (std::size_t at = 0; at < contribution.size();) {
            const auto c = static_cast<std::size_t>(contribution[at]);
            const auto size = static_cast<std::size_t>(contribution[at + 1]);
            (*statistics)[c] = deserialize(std::span<const double>(contribution).subspan(at + 2, size));
            at += 2 + size;
          }
        }
        LineResult result = assemble_result(campaign, line, *design, *evaluated);
        LineStatistics finished;
        std::vector<ColumnAnalysis> analyses;
        for (ColumnStatistics& column : *statistics) analyses.push_back(std::move(column.analysis));
        finished.analysis = combine_column_analyses(result, *used, analyses);
        for (const std::string& output : campaign.campaign().outputs) {
          for (std::size_t c = 0; c < result.columns.size(); ++c) {
            if (result.columns[c].quantity != output || !(*statistics)[c].summary) continue;
            QuantitySummary summary = *(*statistics)[c].summary;
            summary.line = result.name;
            summary.quantity = result.columns[c].quantity;
            summary.unit = std::string(result.columns[c].unit->symbol);
            finished.summaries.push_back(std::move(summary));
          }
        }
        observer.line_analyzed(std::move(result), std::move(finished), design->warnings);
      };
    } else {
      pool.gather(std::move(mine));
    }
    outcome.timings.statistics += seconds_since(start);
    if (pool.rank() == next_designer) {
      start = Clock::now();
      make_design(next);
      outcome.timings.design += seconds_since(start);
    }
  }
  finish_previous_line();
  observer_failure.share(pool);
  return outcome;
}

}  // namespace growthuq
