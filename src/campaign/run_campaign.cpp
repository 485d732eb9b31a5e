#include "growthuq/campaign/run_campaign.hpp"

#include <chrono>
#include <memory>
#include <cstdio>
#include <optional>
#include <utility>

#include "campaign/audit_addition.hpp"
#include "campaign/campaign_outputs.hpp"
#include "growthuq/campaign/campaign_audit.hpp"
#include "campaign/checkpoint.hpp"
#include "campaign/checkpoint_manifest.hpp"
#include "growthuq/campaign/run_footprint.hpp"
#include "growthuq/campaign/run_time_estimate.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/interrupt.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/printable.hpp"

namespace growthuq {

namespace {

// Where a stream option is null, the output goes nowhere (a stream without a buffer).
class Streams {
 public:
  explicit Streams(const RunOptions& options)
      : report_(options.report != nullptr ? *options.report : nowhere_), log_(options.log != nullptr ? *options.log : nowhere_) {}
  std::ostream& report() { return report_; }
  std::ostream& log() { return log_; }

 private:
  std::ostream nowhere_{nullptr};
  std::ostream& report_;
  std::ostream& log_;
};

OutputSettings settings_of(const RunOptions& options, const Pool& pool) {
  OutputSettings settings;
  settings.overwrite = options.overwrite;
  settings.progress = pool.is_coordinator() ? options.progress : ProgressMode::none;
  settings.line_reports = options.line_reports;
  settings.command_line = options.command_line;
  return settings;
}

// An edited campaign file does not change a resumed run (it finishes the run as started, from
// the text stored in the manifest), but the user who edited it should hear so: one line.
void warn_if_campaign_file_differs(const CheckpointManifest& manifest, const std::string& manifest_path,
                                   const std::string& caller, std::ostream& log) {
  const CampaignFileNow now = campaign_file_now(manifest);
  if (now == CampaignFileNow::unchanged) return;
  log << printable(caller + ": warning: " + locate(manifest, manifest.campaign_path) +
                   (now == CampaignFileNow::changed ? " changed since the run started" : " cannot be read now") +
                   "; resuming with the campaign text stored in " + manifest_path +
                   " (to run the file as it is now, start the run again with --force)")
      << "\n";
}

// Where the run's sample count was given, for require_room's message: the checkpoint of a
// resumed run, the caller's flag, or the campaign file.
struct SamplesOrigin {
  std::string location;
  std::string key;
};

// A run this machine cannot hold is refused now rather than killed part way (run_footprint.hpp);
// a finite-element run says how long it will take, with no progress asked too (a run of days
// must not start without a word).
void check_before_running(const PreparedCampaign& prepared, Pool& pool, const OutputSettings& settings,
                          const SamplesOrigin& samples, bool resuming, const std::string& caller, std::ostream& log) {
  on_coordinator(pool, [&] {
    const RunShape shape = run_shape(prepared, !resuming && settings.checkpointing == Checkpointing::start);
    require_room(estimate_run_footprint(shape), machine_room(pool.processes_on_this_machine(), prepared.campaign().output_dir),
                 samples.location, samples.key);
    if (const auto time = estimate_shell_fe_time(prepared)) {
      std::string text = describe_shell_fe_time(*time, pool.size());
      // The checkpoint's finished samples are read later, by the pool: the count above is the
      // whole run's, so for a resumed run it bounds the time from above.
      if (resuming) text.insert(text.size() - 1, "; at most that: the samples the checkpoint holds are not run again");
      log << caller << ": " << text << std::flush;
    }
  });
}

// The run, with the audit of its fast fidelity where the campaign asks for one ([audit],
// audit_addition.hpp): checkpointed and committed with the run's results.
RunSummary run_prepared(const PreparedCampaign& prepared, const CampaignAudit* audit, Pool& pool, OutputSettings settings,
                        const RunOptions& options, Streams& streams, bool resuming) {
  const auto start = std::chrono::steady_clock::now();
  RunSummary summary;
  summary.resumed = resuming;
  summary.campaign = prepared.campaign().name;
  summary.output_dir = prepared.campaign().output_dir;
  summary.lines = prepared.lines().size();
  summary.samples_per_line = prepared.campaign().samples;
  // From here a first signal stops the pool at the next chunk (the coordinator's signal decides
  // for every process); a second one ends the process.
  std::optional<InterruptHandlers> handlers;
  if (options.stop_on_signals) {
    handlers.emplace();
    pool.stop_when([] { return interrupt_signal(); });
  }
  std::unique_ptr<RunAddition> addition;
  if (audit != nullptr) {
    addition = audit_addition(*audit, settings.progress, streams.log());
    settings.addition = addition.get();
  }
  try {
    CampaignOutcome outcome = run_campaign_with_outputs(prepared, pool, settings, streams.report(), streams.log());
    summary.completed = true;
    summary.kappa = outcome.run.kappa;
    summary.calibrated = outcome.run.calibrated;
    summary.timings = outcome.run.timings;
    summary.summaries = std::move(outcome.summaries);
  } catch (const RunInterrupted& interrupted) {
    summary.stop_reason = interrupted.reason();
    summary.stop_message = interrupted.what();
  }
  if (options.stop_on_signals) pool.stop_when({});
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

// Three significant digits below 100 s ("0.0123", "4.56"), whole seconds from there.
std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, seconds < 100 ? "%.3g" : "%.0f", seconds);
  return text;
}

}  // namespace

RunSummary run_campaign(Campaign campaign, Pool& pool, const RunOptions& options) {
  Streams streams(options);
  apply_overrides(campaign, options.overrides);
  campaign.validate();
  OutputSettings settings = settings_of(options, pool);
  // The output directory is checked again under its lock (campaign_outputs.hpp); here, before a
  // raw-data campaign's curve fits and the designs, so that a refusal comes at once.
  on_coordinator(pool, [&] { check_output_directory(campaign, settings.overwrite); });
  const PreparedCampaign prepared(std::move(campaign), pool, settings.progress, streams.log());
  if (options.checkpoint) {
    settings.checkpointing = Checkpointing::start;
    on_coordinator(pool, [&] {
      settings.manifest = make_checkpoint_manifest(prepared.campaign(), options.overrides, settings.command_line);
    });
  }
  // The count is named where it was given.
  const SamplesOrigin samples = options.overrides.samples ? SamplesOrigin{options.caller, "--samples"}
                                                          : SamplesOrigin{prepared.campaign().path, "[campaign] samples"};
  // The audit's models are checked before anything is sampled.
  std::optional<CampaignAudit> audit;
  if (prepared.campaign().audit.samples > 0) audit.emplace(prepared, pool);
  check_before_running(prepared, pool, settings, samples, false, options.caller, streams.log());
  return run_prepared(prepared, audit ? &*audit : nullptr, pool, settings, options, streams, false);
}

RunSummary resume_campaign(const std::string& output_dir, Pool& pool, const RunOptions& options) {
  const CampaignOverrides& o = options.overrides;
  if (o.samples || o.seed || o.output_dir || o.lines || o.formats || o.fidelity || options.overwrite == Overwrite::allow ||
      !options.checkpoint) {
    throw InputError(options.caller, "a resumed run keeps the settings of the interrupted one, so that its results are the "
                                     "same: no overrides, overwrite or checkpoint = false");
  }
  Streams streams(options);
  OutputSettings settings = settings_of(options, pool);
  const std::string manifest_path = checkpoint_manifest_path(output_dir);
  std::string text;
  // Rank 0 checks that nothing the run read has changed; every process parses the same text.
  on_coordinator(pool, [&] {
    text = read_checkpoint_manifest_text(output_dir);
    const CheckpointManifest manifest = parse_manifest(text, manifest_path);
    verify_manifest(manifest, manifest_path);
    warn_if_campaign_file_differs(manifest, manifest_path, options.caller, streams.log());
  });
  text = pool.broadcast(text);
  const CheckpointManifest manifest = parse_manifest(text, manifest_path);
  settings.command_line = manifest.command_line;  // results.h5 as the uninterrupted run writes it
  settings.checkpointing = Checkpointing::resume;
  const PreparedCampaign prepared(resumed_campaign(manifest, output_dir), pool, settings.progress, streams.log());
  // The audit's finished samples are in the checkpoint: a resumed run replays them.
  std::optional<CampaignAudit> audit;
  if (prepared.campaign().audit.samples > 0) audit.emplace(prepared, pool);
  check_before_running(prepared, pool, settings, {manifest_path, "samples"}, true, options.caller, streams.log());
  return run_prepared(prepared, audit ? &*audit : nullptr, pool, settings, options, streams, true);
}

std::string RunSummary::brief_report() const {
  if (!completed) return stop_message;
  std::string text = "campaign '" + campaign + "': " + std::to_string(lines) + (lines == 1 ? " line" : " lines") + " x " +
                     std::to_string(samples_per_line) + " samples " + (resumed ? "resumed and finished" : "run") + " in " +
                     seconds_text(seconds) + " s";
  if (calibrated) text += ", kappa " + format_double(kappa);
  return text + ", results in " + output_dir;
}

std::string RunSummary::full_report() const {
  std::string text = brief_report() + "\n";
  if (!summaries.empty()) {
    text += "line  quantity [unit]  median  (q1, q3)  n  flagged\n";
    for (const QuantitySummary& row : summaries) {
      text += "  " + row.line + "  " + row.quantity + " [" + row.unit + "]  " + format_double(row.median) + "  (" +
              format_double(row.q1) + ", " + format_double(row.q3) + ")  " + std::to_string(row.n) + "  " +
              std::to_string(row.n_flagged) + "\n";
    }
  }
  char times[256];
  std::snprintf(times, sizeof times, "time of this process [s]: design %.3f, evaluation %.3f, sharing %.3f, statistics %.3f, "
                                     "writing %.3f\n",
                timings.design, timings.evaluation, timings.sharing, timings.statistics, timings.observer);
  return text + times;
}

}  // namespace growthuq
