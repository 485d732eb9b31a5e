#include "campaign/campaign_outputs.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <sstream>
#include <thread>
#include <utility>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#include <unistd.h>
#endif

#include "campaign/campaign_report.hpp"
#include "campaign/checkpoint.hpp"
#include "campaign/csv_results.hpp"
#include "campaign/output_lock.hpp"
#include "campaign/provenance.hpp"
#include "growthuq/campaign/data_uncertainty.hpp"
#include "campaign/line_comparison_outputs.hpp"
#include "campaign/raw_data_outputs.hpp"
#include "campaign/sensitivity_outputs.hpp"
#include "campaign/sensitivity_settings.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/printable.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/io/results_h5.hpp"
#include "growthuq/sensitivity/line_sensitivity.hpp"
#include "growthuq/stats/line_analysis.hpp"
#include "growthuq/stats/quantity_summary.hpp"

namespace growthuq {
namespace {

namespace fs = std::filesystem;

// Four significant digits: for reading, not for round trips.
std::string format_significant(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

std::string in_directory(const std::string& directory, const char* name) { return (fs::path(directory) / name).string(); }

// `path` as a shell word, quoted when it holds anything but letters, digits and _ . / - : the
// messages give a command to paste.
std::string shell_word(const std::string& path) {
  constexpr std::string_view safe = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_./-";
  const bool plain = !path.empty() && path.find_first_not_of(safe) == std::string::npos;
  if (plain) return path;
  std::string quoted = "'";
  for (const char c : path) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// The result files of a run, in the order the commit moves them into the output directory:
// summary.csv last, so a directory with a summary.csv holds the whole set.
constexpr std::array<const char*, 9> result_names{results_h5_name,      samples_csv_name, data_uncertainty_csv_name,
                                                  comparisons_csv_name, letters_csv_name, sensitivity_csv_name,
                                                  audit_csv_name,       provenance_json_name, summary_csv_name};

// Where a run writes its results until they are all complete (output_dir/staging).
std::string staging_directory(const std::string& output_dir) { return in_directory(output_dir, staging_name); }

// check_output_directory once the directory is locked (by this run: no in-use test).
void check_directory_contents(const Campaign& campaign, Overwrite overwrite) {
  const std::string& directory = campaign.output_dir;
  if (directory == "-") {
    throw InputError(directory, "standard output cannot take a campaign's results (a folder of files): expected a "
                                "directory name (./- for one named -)");
  }
  std::error_code error;
  if (!fs::exists(directory, error)) return;
  if (overwrite == Overwrite::refuse && has_checkpoint(directory)) {
    throw InputError(directory, "holds an interrupted run; finish it with: growthuq run --resume " + shell_word(directory) +
                                    " (or pass --force to start it again)");
  }
  if (overwrite == Overwrite::refuse) {
    throw InputError(directory, "output directory already exists; choose another (--out DIR) or pass --force to replace its results");
  }
  if (!fs::is_directory(directory, error)) throw InputError(directory, "exists and is not a directory");
  // Every file a run writes or removes there is a regular file or absent, so neither the
  // writers nor the commit's removals touch a device, FIFO or folder of that name.
  for (const char* name : result_names) check_can_write(in_directory(directory, name), Overwrite::allow);
}

// Locks the output directory (creating it if needed) and checks it. Returns whether the
// directory was created by this run.
bool prepare_output_directory(const Campaign& campaign, Overwrite overwrite, std::optional<OutputDirectoryLock>& lock) {
  const std::string& directory = campaign.output_dir;
  std::error_code error;
  // Locked before anything is said about what it holds: the checkpoint of a live run is no
  // interrupted run to resume.
  if (directory != "-" && fs::is_directory(directory, error)) lock.emplace(directory);
  check_directory_contents(campaign, overwrite);
  if (fs::exists(directory, error)) {
    fs::remove_all(staging_directory(directory), error);  // what a killed run had staged
    return false;
  }
  fs::create_directories(directory, error);
  if (error) throw WriteError(directory, "cannot create the output directory: " + error.message());
  lock.emplace(directory);
  return true;
}

// The multi-file commit: the old results are removed, then the staged ones moved in (summary.csv
// last), then the staging folder removed. The directory never holds new results beside old
// ones; a kill in between leaves part of the new set, the rest staged and the checkpoint, and
// --resume writes the set again.
void commit_staged_results(const std::string& output_dir) {
  const std::string staging = staging_directory(output_dir);
  std::error_code error;
  for (const char* name : result_names) {
    const std::string path = in_directory(output_dir, name);
    check_can_write(path, Overwrite::allow);  // (only regular files are removed)
    if (fs::remove(path, error); error) throw WriteError(path, "cannot remove the previous run's result: " + error.message());
  }
  for (const char* name : result_names) {
    const std::string staged = in_directory(staging, name);
    if (fs::exists(staged, error)) move_into_place(staged, in_directory(output_dir, name));
  }
  fs::remove_all(staging, error);
}

// The coordinator's stop request (0: none), on every process.
int coordinator_stop_request(Pool& pool) {
  const std::string request = pool.broadcast(pool.is_coordinator() ? std::to_string(pool.stop_requested()) : std::string());
  return std::stoi(request);
}

// The samples.csv columns: every line's inputs (first seen first), then the computed outputs.
std::vector<std::string> sample_columns(const PreparedCampaign& campaign) {
  std::vector<std::string> columns;
  auto add = [&](const std::string& name) {
    if (std::find(columns.begin(), columns.end(), name) == columns.end()) columns.push_back(name);
  };
  for (const PreparedLine& line : campaign.lines()) {
    for (const LineVariable& variable : line.design_variables.variables) add(column_name(variable.name, *variable.unit));
  }
  for (const std::string& output : campaign.computed_outputs()) add(default_column_name(*find_quantity(output)));
  return columns;
}

// Lets the calling thread run on any processor. mpirun binds each process to one core, and a
// thread inherits its process's binding: the writer would then take its time from the
// coordinator's own core while the other cores wait for the coordinator (measured: the
// coordinator's share of a 2-process campaign 40 % slower). Where this is not possible nothing
// changes.
void use_every_processor() {
#if defined(__linux__)
  cpu_set_t every;
  CPU_ZERO(&every);
  const long processors = sysconf(_SC_NPROCESSORS_ONLN);
  for (long cpu = 0; cpu < processors && cpu < CPU_SETSIZE; ++cpu) CPU_SET(static_cast<int>(cpu), &every);
  pthread_setaffinity_np(pthread_self(), sizeof every, &every);
#endif
}

// Streams each finished line to the writers and keeps only its summaries and report text. The
// files are written on a thread of their own, one line at a time, while the processes go on
// with the next line (a 1e6-sample line is about 90 MB of results.h5, which costs the kernel
// 0.1-0.6 s to take, measured); the next line waits only if the previous one is still being
// written. A write that failed is reported at the next line or at finish().
class OutputObserver final : public RunObserver {
 public:
  OutputObserver(const PreparedCampaign& campaign, const OutputSettings& settings, std::ostream& log)
      : campaign_(campaign),
        log_(log),
        progress_(settings.progress, log, campaign.campaign().samples * campaign.lines().size()) {}

  ~OutputObserver() override {
    if (writer_.joinable()) writer_.join();
  }

  // The writers, in the staging folder (commit_staged_results moves their files out).
  void open(const PreparedCampaign& campaign) {
    const Campaign& c = campaign.campaign();
    staging_is_ours_ = true;  // called only once the output directory is locked by this run
    std::error_code error;
    fs::create_directories(staging_, error);
    if (error) throw WriteError(staging_, "cannot create the folder the results are written to: " + error.message());
    if (c.formats.csv) samples_.emplace(in_directory(staging_, samples_csv_name), sample_columns(campaign));
    if (c.formats.hdf5) {
      h5_.emplace(in_directory(staging_, results_h5_name), Overwrite::allow);
      std::vector<std::string> names;  // the campaign's order; the lines run with the reference line first
      for (const CampaignLine& line : c.lines) names.push_back(line.name);
      h5_->declare_lines(names);
    }
  }

  void line_started(const PreparedLine& line, std::size_t samples) override {
    progress_.line_started(line.campaign_line.name, samples);
  }

  void chunk_done(ChunkRange range) override { progress_.advance(range.end - range.begin); }
  void chunk_replayed(ChunkRange range) override { progress_.advance_replayed(range.end - range.begin); }

  void line_done(const LineResult& result, const std::vector<std::string>& warnings) override {
    LineResult copy = result;
    line_analyzed(std::move(copy), line_statistics(result, campaign_.campaign().outputs), warnings);
  }

  void line_analyzed(LineResult&& result, LineStatistics&& statistics, const std::vector<std::string>& warnings) override {
    // Before anything of the line is written: a statistic that overflowed would reach
    // results.h5 as inf and summary.csv as an empty cell, which reads as "undefined".
    for (const QuantitySummary& summary : statistics.summaries) require_finite_statistics(summary, campaign_.campaign().path);
    progress_.line_finished();
    for (const std::string& warning : warnings) log_ << printable("growthuq run: line '" + result.name + "': " + warning) << "\n";
    summaries_.insert(summaries_.end(), statistics.summaries.begin(), statistics.summaries.end());
    // The sensitivity indices from the line's own samples (one sort per input; Eq. (S1),
    // src/sensitivity/README.md), on the coordinator before the line goes to the writer.
    sensitivity_.push_back(line_sensitivity(result, campaign_.campaign().seed));
    line_reports_ += "\nline " + result.name + ": input rank correlation (Spearman)\n" + format_input_correlation(result) +
                     format_line_analysis(statistics.analysis) + format_line_sensitivity(sensitivity_.back());
    // The Shapley effects, when the campaign asks for them: new runs of the line's models, on
    // this process alone (src/campaign/line_shapley.hpp).
    if (sensitivity_settings_.shapley) {
      shapley_.push_back(line_shapley(campaign_, result, sensitivity_settings_));
      line_reports_ += format_line_shapley(shapley_.back());
    }
    if (sensitivity_settings_.sobol) {
      sobol_.push_back(line_sobol(campaign_, result, sensitivity_settings_));
      line_reports_ += format_line_sobol(sobol_.back());
    }
    wait_for_writer();
    writer_ = std::thread([this, line = std::move(result), written = std::move(statistics)] {
      use_every_processor();
      try {
        if (samples_) samples_->write_line(line);
        if (h5_) h5_->write_line(line, written.summaries, written.analysis);
      } catch (...) {
        failure_ = std::current_exception();
      }
    });
  }

  // Every result file complete in the staging folder; returns the report for stdout.
  std::string finish(const CampaignOutcome& outcome, DataUncertaintyResult uncertainty, const OutputSettings& settings) {
    wait_for_writer();
    const Campaign& c = campaign_.campaign();
    if (samples_) samples_->finish();
    add_data_intervals(summaries_, uncertainty.rows);
    if (h5_) h5_->replace_summaries(summaries_);
    write_file_atomically(in_directory(staging_, summary_csv_name), summary_csv_text(summaries_), Overwrite::allow);
    write_sensitivity(sensitivity_in_campaign_order(), shapley_, sobol_, h5_ ? &*h5_ : nullptr, staging_);
    std::vector<std::string> measurement_error_lines;
    for (const DataUncertainty& row : uncertainty.rows) {
      if (row.measurement_error && std::find(measurement_error_lines.begin(), measurement_error_lines.end(), row.line) ==
                                       measurement_error_lines.end()) {
        measurement_error_lines.push_back(row.line);
      }
    }
    const std::string raw_data_report =
        write_raw_data_outputs(campaign_, summaries_, std::move(uncertainty), h5_ ? &*h5_ : nullptr, staging_);
    RunProvenance provenance = run_provenance(campaign_);
    const std::string extra_report = settings.addition ? settings.addition->write(provenance, h5_ ? &*h5_ : nullptr, staging_) : "";
    // Written whatever the formats: it is what `growthuq report` and a reader of the CSVs cite.
    write_file_atomically(in_directory(staging_, provenance_json_name), provenance_json(provenance), Overwrite::allow);
    if (h5_) {
      write_provenance(*h5_, provenance);
      CampaignMetadata metadata;
      metadata.campaign_text = c.text;
      metadata.campaign_path = c.path;
      metadata.command_line = settings.command_line;
      metadata.engine_version = GROWTHUQ_VERSION;
      metadata.seed = c.seed;
      if (outcome.run.calibrated) metadata.kappa = outcome.run.kappa;
      metadata.samples_per_line = c.samples;
      h5_->finish(metadata);
    }
    std::ostringstream report;
    report << "campaign '" << c.name << "': " << c.lines.size() << " lines x " << c.samples << " samples, seed " << c.seed
           << ", results in " << c.output_dir << "\n\n"
           << format_summary_table(summaries_) << format_interval_note(c, measurement_error_lines) << extra_report;
    if (outcome.run.calibrated) {
      report << "\nkappa = " << format_double(outcome.run.kappa) << " (calibrated on " << c.reference_line
             << ": its predicted median v equals the median of its v_exp, "
             << format_significant(to_um_per_s(campaign_.experimental_median_growth_rate())) << " um/s)\n";
    }
    if (settings.line_reports) {
      report << line_reports_ << raw_data_report;
    } else {
      report << "\n(per-line reports not printed: --summary-only)\n";
    }
    return report.str();
  }

  const std::vector<QuantitySummary>& summaries() const { return summaries_; }

  // After a failure or a stop: closes the writers, which remove their .partial files, and
  // removes what was staged (coordinator). A run that failed before open() (refused by the lock
  // or by the directory checks) staged nothing: the staging folder there may be a live run's.
  void abandon(bool coordinator) {
    progress_.stopped();
    if (writer_.joinable()) writer_.join();
    samples_.reset();
    h5_.reset();
    std::error_code ignored;
    if (coordinator && staging_is_ours_) fs::remove_all(staging_, ignored);
  }

 private:
  // Waits for the line being written and raises what its writing threw.
  void wait_for_writer() {
    if (writer_.joinable()) writer_.join();
    if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
  }

  // The lines' sensitivity in the campaign's order (the lines run with the reference line first).
  std::vector<LineSensitivity> sensitivity_in_campaign_order() const {
    std::vector<LineSensitivity> ordered;
    for (const CampaignLine& line : campaign_.campaign().lines) {
      for (const LineSensitivity& s : sensitivity_) {
        if (s.line == line.name) ordered.push_back(s);
      }
    }
    return ordered;
  }

  const PreparedCampaign& campaign_;
  std::ostream& log_;
  std::string staging_ = staging_directory(campaign_.campaign().output_dir);
  bool staging_is_ours_ = false;  // open() ran: this run holds the lock and made staging_
  Progress progress_;
  std::optional<SamplesCsvWriter> samples_;
  std::optional<ResultsH5Writer> h5_;
  std::vector<QuantitySummary> summaries_;
  std::vector<LineSensitivity> sensitivity_;
  SensitivitySettings sensitivity_settings_ = sensitivity_settings(campaign_.campaign());
  std::vector<LineShapley> shapley_;
  std::vector<LineSobol> sobol_;
  std::string line_reports_;
  std::thread writer_;
  std::exception_ptr failure_;
};

// A failed run leaves no output directory of its own making behind (an empty one would only
// make the rerun need --force); the results of a forced directory stay as they were (nothing
// was committed). A resume would fail the same way, so a new run's checkpoint goes too; a
// resumed run keeps the chunks an earlier run paid for. Rethrows the exception being handled.
[[noreturn]] void throw_after_failure(bool starting_checkpoint, bool created, const std::string& directory, Pool& pool) {
  std::error_code ignored;
  if (starting_checkpoint && pool.is_coordinator()) fs::remove_all(checkpoint_directory(directory), ignored);
  if (created) fs::remove(directory, ignored);
  throw;
}

}  // namespace

void check_output_directory(const Campaign& campaign, Overwrite overwrite) {
  std::error_code error;
  // A live run's checkpoint is no interrupted run to resume, and its directory is not to reuse.
  if (campaign.output_dir != "-" && fs::is_directory(campaign.output_dir, error)) refuse_if_in_use(campaign.output_dir);
  check_directory_contents(campaign, overwrite);
}

CampaignOutcome run_campaign_with_outputs(const PreparedCampaign& campaign, Pool& pool, const OutputSettings& settings,
                                          std::ostream& report, std::ostream& log) {
  OutputObserver observer(campaign, settings, log);
  const bool resuming = settings.checkpointing == Checkpointing::resume;
  bool created = false;
  std::optional<OutputDirectoryLock> lock;  // the coordinator's, for the whole run
  std::unique_ptr<RunCheckpoint> checkpoint, addition_checkpoint;
  bool starting_checkpoint = false;
  CampaignOutcome outcome;
  const std::string& directory = campaign.campaign().output_dir;
  try {
    on_coordinator(pool, [&] {
      created = prepare_output_directory(campaign.campaign(), resuming ? Overwrite::allow : settings.overwrite, lock);
      observer.open(campaign);
    });
    if (settings.checkpointing == Checkpointing::start) {
      starting_checkpoint = true;  // from here the checkpoint directory is this run's
      checkpoint = RunCheckpoint::start(pool, campaign, settings.manifest);
    }
    if (resuming) checkpoint = RunCheckpoint::resume(pool, campaign);
    if (settings.addition != nullptr) {
      if (checkpoint) addition_checkpoint = RunCheckpoint::open_audit(pool, directory, settings.addition->chunk_shape(), resuming);
      settings.addition->run(pool, addition_checkpoint.get());
    }
    outcome.run = run_campaign_lines(campaign, pool, observer, checkpoint.get());
    // All processes run the bootstrap while the coordinator's writer may still write the last line.
    DataUncertaintyResult uncertainty = estimate_data_uncertainty(campaign, pool, settings.progress, log);
    std::string report_text;
    on_coordinator(pool, [&] { report_text = observer.finish(outcome, std::move(uncertainty), settings); });
    // A stop asked for while the results were written is not ignored: they stay staged and are
    // dropped, the checkpoint is kept, and --resume writes them again.
    if (const int stop = coordinator_stop_request(pool)) throw PoolInterrupted(stop);
    on_coordinator(pool, [&] {
      commit_staged_results(directory);
      addition_checkpoint.reset();
      if (checkpoint) checkpoint->remove();
      report << report_text;
    });
  } catch (const PoolInterrupted& interrupted) {
    observer.abandon(pool.is_coordinator());
    lock.reset();
    if (!checkpoint) {
      std::error_code ignored;
      if (created) fs::remove(directory, ignored);
      throw RunInterrupted(interrupted.reason(), "interrupted; nothing was kept to resume (--no-checkpoint)");
    }
    const std::size_t total = campaign.campaign().samples * campaign.lines().size();
    // The audit's finite-element samples are counted apart: they are no part of the lines'.
    std::string audit;
    if (addition_checkpoint) {
      const ChunkShape shape = settings.addition->chunk_shape();
      audit = " (and " + std::to_string(addition_checkpoint->samples_held()) + " of the audit's " +
              std::to_string(shape.samples * shape.chunk_sizes.size()) + ")";
    }
    throw RunInterrupted(interrupted.reason(), "interrupted after " + std::to_string(checkpoint->samples_held()) + " of " +
                                                   std::to_string(total) + " samples" + audit +
                                                   "; finish with: growthuq run --resume " + shell_word(directory));
  } catch (const WriteError& error) {
    // A full disk (or a quota, a read-only remount): the checkpoint's chunks are still good, so
    // they stay, whoever started them, for a resume once there is room.
    observer.abandon(pool.is_coordinator());
    addition_checkpoint.reset();
    checkpoint.reset();
    lock.reset();
    if (!pool.is_coordinator() || !has_checkpoint(directory)) throw_after_failure(starting_checkpoint, created, directory, pool);
    throw WriteError(error.location(), error.problem() + "; the checkpoint keeps the finished chunks: make room, then finish "
                                                         "with: growthuq run --resume " + shell_word(directory));
  } catch (...) {
    observer.abandon(pool.is_coordinator());
    addition_checkpoint.reset();
    checkpoint.reset();
    lock.reset();
    throw_after_failure(starting_checkpoint, created, directory, pool);
  }
  outcome.summaries = observer.summaries();
  return outcome;
}

}  // namespace growthuq
