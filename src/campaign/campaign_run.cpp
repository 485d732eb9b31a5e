#include "growthuq/campaign/campaign_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <stdexcept>

#include "campaign/chunk_values.hpp"
#include "campaign/column_statistics.hpp"
#include "campaign/coordinator_failure.hpp"
#include "campaign/design_sharing.hpp"
#include "campaign/line_schedule.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/growth/kappa.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/stats/quantity_summary.hpp"
#include "growthuq/stats/rank_correlation.hpp"

namespace growthuq {

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

// The steps of run_campaign_lines and what they share: the schedule, the designs made ahead,
// the kappa calibration, the line waiting to be finished, the timings.
class LineRun {
 public:
  LineRun(const PreparedCampaign& campaign, Pool& pool, RunObserver& observer, ChunkJournal* journal)
      : campaign_(campaign),
        pool_(pool),
        observer_(observer),
        journal_(journal),
        schedule_(campaign.lines().size(), pool.size()),
        samples_(campaign.campaign().samples) {
    if (campaign.calibrates_kappa()) kappa_.emplace(campaign.kappa_calibration());
  }

  void start(std::size_t index) {
    observer_failure_.run(pool_, [&] { observer_.line_started(campaign_.lines()[index], samples_); });
  }

  // The line's design on every process: made here if this process is its designer and has not
  // made it ahead, then sent from the designer to the others.
  std::shared_ptr<LineDesign> design(std::size_t index) {
    const auto start = Clock::now();
    for (const std::size_t line : schedule_.designed_at_start(index, pool_.rank())) make_design(line);
    auto design = std::make_shared<LineDesign>();
    const int designer = schedule_.designer_of(index);
    if (const auto held = held_.find(index); held != held_.end()) {
      *design = std::move(held->second);
      held_.erase(held);
    }
    if (pool_.size() > 1) {
      std::vector<std::string> names;
      for (const LineVariable& variable : campaign_.lines()[index].design_variables.variables) names.push_back(variable.name);
      share_design(*design, names, samples_, designer, pool_);
    }
    observer_failure_.share(pool_);  // a failure of the previous line's writing stops everyone here
    outcome_.timings.design += seconds_since(start);
    return design;
  }

  // The models over the line's samples in chunks through the pool (chunks the journal holds are
  // replayed, new ones recorded); the coordinator collects the outputs, calibrates kappa on the
  // reference line and scales v.
  std::shared_ptr<LineOutputs> evaluate(std::size_t index, const LineDesign& design) {
    const auto start = Clock::now();
    const PreparedLine& line = campaign_.lines()[index];
    const LineResult layout = result_layout(campaign_, line);
    const std::size_t outputs = campaign_.computed_outputs().size();
    auto evaluated = std::make_shared<LineOutputs>();
    evaluated->columns.resize(outputs);
    std::vector<double> to_si;
    for (std::size_t o = 0; o < outputs; ++o) to_si.push_back(layout.columns[design.values.size() + o].unit->to_si);
    if (pool_.is_coordinator()) {
      for (LargeVector<double>& column : evaluated->columns) column.resize(samples_);  // every chunk writes its range
      evaluated->status.resize(samples_);
    }
    const ChunkWork work = [&](ChunkRange range) { return campaign_.evaluate_chunk(line, design, range); };
    // Chunks from the checkpoint are replayed: no work, no part of the rate.
    const auto fill = [&](ChunkRange range, std::span<const double> values, bool replayed) {
      const ChunkValues chunk(values, outputs);
      const std::size_t size = range.end - range.begin;
      if (chunk.samples() != size) throw std::logic_error("chunk of unexpected size");
      for (std::size_t o = 0; o < outputs; ++o) {
        const std::span<const double> in = chunk.output(o);
        double* out = evaluated->columns[o].data() + range.begin;
        for (std::size_t i = 0; i < size; ++i) out[i] = in[i] / to_si[o];
      }
      for (std::size_t i = 0; i < size; ++i) evaluated->status[range.begin + i] = chunk.status(i);
      if (replayed) {
        observer_.chunk_replayed(range);
      } else {
        observer_.chunk_done(range);
      }
    };
    const std::size_t chunk_size = campaign_.chunk_size_of(line);
    // Finite-element samples take seconds to minutes: one at a time per worker, since rank 0
    // answers a worker as soon as its sample is back (it computes its own on another thread), and
    // a queued sample could no longer go to whichever process frees up first, which matters at a
    // line's end.
    pool_.set_queued_chunks(campaign_.has_slow_samples(line) ? 1 : 3);
    const ChunkSink computed = [&](ChunkRange range, std::span<const double> values) { fill(range, values, false); };
    const ChunkSink replayed = [&](ChunkRange range, std::span<const double> values) { fill(range, values, true); };
    run_with_journal(pool_, journal_, index, samples_, chunk_size, work, computed, replayed);
    if (kappa_) scale_growth(line, *evaluated, to_si);
    outcome_.timings.evaluation += seconds_since(start);
    return evaluated;
  }

  // Every process gets the outputs and statuses, to share the statistics out by column.
  void share(LineOutputs& evaluated) {
    const auto start = Clock::now();
    pool_.broadcast_vector(evaluated.status, samples_, 0);
    for (LargeVector<double>& column : evaluated.columns) pool_.broadcast_vector(column, samples_, 0);
    outcome_.timings.sharing += seconds_since(start);
  }

  // The statistics, column by column, shared out by the schedule; the others send theirs to the
  // coordinator, which gathers them when it finishes the line (while the next line is designed).
  void statistics(std::size_t index, std::shared_ptr<LineDesign> design, std::shared_ptr<LineOutputs> evaluated) {
    const auto start = Clock::now();
    const LineResult layout = result_layout(campaign_, campaign_.lines()[index]);
    std::vector<std::span<const double>> values(design->values.begin(), design->values.end());
    values.insert(values.end(), evaluated->columns.begin(), evaluated->columns.end());
    auto used = std::make_shared<const std::vector<std::uint32_t>>(analysis_samples(evaluated->status));
    const std::size_t columns = layout.columns.size();
    // An input ranked by its strata costs about a quarter of a sorted column (measured).
    std::vector<double> costs(columns, 1.0);
    for (std::size_t c = 0; c < design->ranks.size(); ++c) costs[c] = design->strictly_increasing[c] != 0 ? 0.25 : 1.0;
    const std::vector<int> owner = schedule_.statistics_owners(index, costs);
    auto statistics = std::make_shared<std::vector<ColumnStatistics>>(columns);
    ColumnStatisticsBatch mine;
    for (std::size_t c = 0; c < columns; ++c) {
      if (owner[c] != pool_.rank()) continue;
      // An input whose values strictly increase with its strata is ranked by them, unsorted.
      const bool by_strata = c < design->ranks.size() && design->strictly_increasing[c] != 0;
      ColumnStatistics column = column_statistics(
          layout.columns[c], values[c], by_strata ? std::span<const std::uint32_t>(design->ranks[c]) : std::span<const std::uint32_t>{},
          *used, std::ranges::count(campaign_.campaign().outputs, layout.columns[c].quantity) > 0);
      if (pool_.is_coordinator()) {
        (*statistics)[c] = std::move(column);
      } else {
        mine.columns.emplace_back(c, std::move(column));
      }
    }
    if (pool_.is_coordinator()) {
      finish_line_ = [this, index, design, evaluated, used, statistics] { finish(index, *design, *evaluated, *used, *statistics); };
    } else {
      pool_.gather(mine.encode());
    }
    outcome_.timings.statistics += seconds_since(start);
  }

  // The design this process makes while the others compute line `index`'s statistics, if any.
  void design_ahead(std::size_t index) {
    const std::optional<std::size_t> ahead = schedule_.designed_during_statistics(index);
    if (!ahead || schedule_.designer_of(*ahead) != pool_.rank()) return;
    const auto start = Clock::now();
    make_design(*ahead);
    outcome_.timings.design += seconds_since(start);
  }

  // Coordinator: the line whose statistics were computed last, handed to the observer (the
  // others need nothing from it; a failure reaches them at the next design, or at end()).
  void finish_previous() {
    if (!finish_line_) return;
    const auto start = Clock::now();
    observer_failure_.run(pool_, finish_line_);
    finish_line_ = nullptr;
    outcome_.timings.observer += seconds_since(start);
  }

  RunOutcome end() {
    observer_failure_.share(pool_);
    if (kappa_) outcome_.kappa = kappa_->kappa();
    return outcome_;
  }

 private:
  void make_design(std::size_t line) { held_.emplace(line, campaign_.design(campaign_.lines()[line])); }

  // Coordinator: kappa from the reference line (raised on every process when it cannot be
  // calibrated), then v *= kappa on every line.
  void scale_growth(const PreparedLine& line, LineOutputs& evaluated, const std::vector<double>& to_si) {
    const std::vector<std::string>& computed = campaign_.computed_outputs();
    const auto v = static_cast<std::size_t>(std::find(computed.begin(), computed.end(), KappaCalibration::quantity) - computed.begin());
    if (v == computed.size()) return;
    if (kappa_->is_reference(line.campaign_line.name)) {
      on_coordinator(pool_, [&] { kappa_->calibrate(evaluated.columns[v], to_si[v], evaluated.status); });
      outcome_.calibrated = true;
    }
    if (pool_.is_coordinator()) kappa_->apply(evaluated.columns[v], evaluated.status);
  }

  // Coordinator: gathers the other processes' columns, assembles the line's result and
  // statistics and hands them to the observer.
  void finish(std::size_t index, LineDesign& design, LineOutputs& evaluated, const std::vector<std::uint32_t>& used,
              std::vector<ColumnStatistics>& statistics) {
    for (const std::vector<double>& contribution : pool_.gather({})) {
      for (auto& [c, column] : ColumnStatisticsBatch::decode(contribution).columns) statistics[c] = std::move(column);
    }
    LineResult result = assemble_result(campaign_, campaign_.lines()[index], design, evaluated);
    LineStatistics finished;
    std::vector<ColumnAnalysis> analyses;
    for (ColumnStatistics& column : statistics) analyses.push_back(std::move(column.analysis));
    finished.analysis = combine_column_analyses(result, used, analyses);
    for (const std::string& output : campaign_.campaign().outputs) {
      for (std::size_t c = 0; c < result.columns.size(); ++c) {
        if (result.columns[c].quantity != output || !statistics[c].summary) continue;
        QuantitySummary summary = *statistics[c].summary;
        summary.line = result.name;
        summary.quantity = result.columns[c].quantity;
        summary.unit = std::string(result.columns[c].unit->symbol);
        // The reference line's v median is kappa's definition; every other line's holds kappa's
        // Monte Carlo error too (kappa.hpp, widen_median_interval).
        if (kappa_ && summary.quantity == KappaCalibration::quantity && !kappa_->is_reference(result.name)) {
          kappa_->widen_median_interval(summary.median, summary.median_ci_low, summary.median_ci_high);
        }
        finished.summaries.push_back(std::move(summary));
      }
    }
    observer_.line_analyzed(std::move(result), std::move(finished), design.warnings);
  }

  const PreparedCampaign& campaign_;
  Pool& pool_;
  RunObserver& observer_;
  ChunkJournal* journal_;
  LineSchedule schedule_;
  std::size_t samples_;
  std::optional<KappaCalibration> kappa_;       // when v is an output
  std::map<std::size_t, LineDesign> held_;      // designs this process made of lines not yet shared
  std::function<void()> finish_line_;           // coordinator: the line analyzed last, to hand over
  CoordinatorFailure observer_failure_;         // raised everywhere at the next design
  RunOutcome outcome_;
};

}  // namespace

LineStatistics line_statistics(const LineResult& result, const std::vector<std::string>& outputs) {
  LineStatistics statistics;
  for (const std::string& output : outputs) {
    for (const ResultColumn& column : result.columns) {
      if (column.quantity == output) statistics.summaries.push_back(summarize_quantity(result.name, column));
    }
  }
  statistics.analysis = analyze_line(result);
  return statistics;
}

void run_with_journal(Pool& pool, ChunkJournal* journal, std::size_t line, std::size_t count, std::size_t chunk_size,
                      const ChunkWork& work, const ChunkSink& sink, const ChunkSink& replayed) {
  if (journal == nullptr) {
    pool.run(count, chunk_size, work, sink);
    return;
  }
  on_coordinator(pool, [&] { journal->replay(line, replayed); });  // a read error stops every process
  const ChunkSink record_then_sink = [&](ChunkRange range, std::span<const double> values) {
    journal->record(line, range, values);
    sink(range, values);
  };
  pool.run(count, chunk_size, work, record_then_sink, [&](ChunkRange range) { return journal->holds(line, range); });
}

RunOutcome run_campaign_lines(const PreparedCampaign& campaign, Pool& pool, RunObserver& observer, ChunkJournal* journal) {
  LineRun run(campaign, pool, observer, journal);
  for (std::size_t line = 0; line < campaign.lines().size(); ++line) {
    run.finish_previous();  // the observer sees each line finished before the next one starts
    run.start(line);
    const std::shared_ptr<LineDesign> design = run.design(line);
    const std::shared_ptr<LineOutputs> outputs = run.evaluate(line, *design);
    run.share(*outputs);
    run.statistics(line, design, outputs);  // the coordinator finishes the line when the next one starts
    run.design_ahead(line);                 // the next line's designer, meanwhile
  }
  run.finish_previous();
  return run.end();
}

}  // namespace growthuq
