#include "growthuq/campaign/tradeoff_run.hpp"

#include <chrono>

#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/campaign/progress.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/printable.hpp"

namespace growthuq {
namespace {

// Keeps each finished line's summaries (the rows summary.csv would hold) and drops its samples.
class SummaryObserver final : public RunObserver {
 public:
  SummaryObserver(const PreparedCampaign& campaign, ProgressMode progress, std::ostream& log)
      : campaign_(campaign), log_(log), progress_(progress, log, campaign.campaign().samples * campaign.lines().size()) {}

  void line_started(const PreparedLine& line, std::size_t samples) override {
    progress_.line_started(line.campaign_line.name, samples);
  }

  void chunk_done(ChunkRange range) override { progress_.advance(range.end - range.begin); }

  void line_done(const LineResult& result, const std::vector<std::string>& warnings) override {
    LineResult copy = result;
    line_analyzed(std::move(copy), line_statistics(result, campaign_.campaign().outputs), warnings);
  }

  // The run's summaries as they are, so that another line's v interval holds kappa's error as in
  // summary.csv (Eq. (G5b), src/growth/README.md).
  void line_analyzed(LineResult&& result, LineStatistics&& statistics, const std::vector<std::string>& warnings) override {
    progress_.line_finished();
    for (const std::string& warning : warnings) {
      log_ << printable("growthuq tradeoff: line '" + result.name + "' at " + std::to_string(result.samples()) + " samples: " + warning) << "\n";
    }
    summaries_.insert(summaries_.end(), statistics.summaries.begin(), statistics.summaries.end());
  }

  std::vector<QuantitySummary> take_summaries() { return std::move(summaries_); }

 private:
  const PreparedCampaign& campaign_;
  std::ostream& log_;
  Progress progress_;
  std::vector<QuantitySummary> summaries_;
};

}  // namespace

std::string fidelity_label(Fidelity fidelity) { return std::string(to_string(fidelity)); }

Campaign campaign_at_fidelity(Campaign campaign, Fidelity fidelity) {
  campaign.fidelity = fidelity;
  for (CampaignLine& line : campaign.lines) line.fidelity.reset();
  return campaign;
}

std::vector<TradeoffRun> run_tradeoff(const Campaign& campaign, std::span<const TradeoffSeries> series, Pool& pool,
                                      ProgressMode progress, std::ostream& log) {
  using Clock = std::chrono::steady_clock;
  std::vector<TradeoffRun> runs;
  for (const TradeoffSeries& one : series) {
    if (one.sample_counts.empty()) continue;
    // Prepared once per fidelity: line files or raw-data fits and correlation targets do not
    // depend on the sample count, and refitting raw data (seconds) at every count would swamp
    // the small runs' times, which are what the trade is about.
    Campaign first = campaign_at_fidelity(campaign, one.fidelity);
    first.samples = one.sample_counts.front();
    PreparedCampaign prepared(std::move(first), pool, progress, log);
    const std::string label = fidelity_label(one.fidelity);
    for (const std::size_t samples : one.sample_counts) {
      if (progress != ProgressMode::none) {
        log << "tradeoff: " << label << ", " << samples << " samples per line\n" << std::flush;
      }
      prepared.set_samples(samples);
      const Clock::time_point start = Clock::now();
      SummaryObserver observer(prepared, progress, log);
      run_campaign_lines(prepared, pool, observer);
      TradeoffRun run;
      run.fidelity = label;
      run.samples = samples;
      run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
      run.summaries = observer.take_summaries();
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

std::vector<TradeoffRun> run_tradeoff(const Campaign& campaign, std::span<const std::size_t> sample_counts, Pool& pool,
                                      ProgressMode progress, std::ostream& log) {
  const TradeoffSeries series{campaign.fidelity, {sample_counts.begin(), sample_counts.end()}};
  return run_tradeoff(campaign, std::span<const TradeoffSeries>(&series, 1), pool, progress, log);
}

}  // namespace growthuq
