// A campaign validated end to end before any sampling (PreparedCampaign): every line file and
// correlation file read, raw-data lines fitted, each line's models planned, the reference line
// checked. What a run (campaign_run.hpp), `growthuq check` and the sensitivity estimators start from.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/evaluation/line_result.hpp"
#include "growthuq/campaign/progress_mode.hpp"
#include "growthuq/correlation/matrix_file.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/evaluation/evaluator.hpp"
#include "growthuq/growth/kappa.hpp"
#include "growthuq/pool/pool.hpp"
#include "growthuq/rawdata/raw_line_fit.hpp"
#include "growthuq/sampling/line_design.hpp"
#include "growthuq/stats/line_analysis.hpp"

namespace growthuq {

// One line, validated and ready to sample.
struct PreparedLine {
  CampaignLine campaign_line;
  LineDistributions distributions;
  std::shared_ptr<const RawLineFit> raw_fit;  // the fits behind `distributions` for raw = FILE lines
  // The line-file variables the run samples (those the models read, plus outputs that are
  // measurements), in line-file order. Unneeded variables are not sampled, so a turgor-only
  // campaign runs on lines without thickness or relaxation data.
  LineDistributions design_variables;
  // The target over design variables (a matrix file or the `physics` matrix restricted to the
  // variables sampled); empty when the line is uncorrelated or fewer than two variables remain.
  std::optional<RankCorrelationFile> correlation;
  std::vector<const Evaluator*> plan;  // points into the owning PreparedCampaign's models
};

// A campaign validated end to end before any sampling: every line file and correlation file
// read, each line's models planned from the campaign's list (campaign_models.hpp: only those
// its outputs need), the reference line checked for v_exp.
// The same on every process (pure function of the files), so all processes agree on it.
class PreparedCampaign {
 public:
  // InputError naming file, line or key for any problem. Raw-data lines are fitted here, by
  // this process alone.
  explicit PreparedCampaign(Campaign campaign);
  // The same with the raw-data lines' curve fits shared out over the processes of `pool`
  // (shared_raw_fits.hpp): every process calls it with the same campaign and gets the same
  // prepared campaign. Progress of the fits on `log` as `progress` says (ProgressMode::none
  // off rank 0).
  PreparedCampaign(Campaign campaign, Pool& pool, ProgressMode progress, std::ostream& log);
  PreparedCampaign(const PreparedCampaign&) = delete;
  PreparedCampaign& operator=(const PreparedCampaign&) = delete;

  const Campaign& campaign() const noexcept { return campaign_; }
  // Lines in run order: the reference line first when v is an output, then file order.
  const std::vector<PreparedLine>& lines() const noexcept { return lines_; }
  // The requested outputs that models compute (outputs that are measurements are inputs).
  const std::vector<std::string>& computed_outputs() const noexcept { return computed_outputs_; }
  // True when v is an output: growth runs with kappa = 1 and is rescaled after the reference line.
  bool calibrates_kappa() const noexcept { return calibrates_kappa_; }
  // Median of the reference line's v_exp distribution [m/s]; NaN when !calibrates_kappa().
  double experimental_median_growth_rate() const noexcept { return experimental_median_; }
  // A run's calibration on the reference line (valid when calibrates_kappa()).
  KappaCalibration kappa_calibration() const { return {campaign_.reference_line, experimental_median_}; }

  // Samples per line from now on (growthuq tradeoff runs one preparation at several counts:
  // line distributions, raw-data fits and correlation targets do not depend on it).
  void set_samples(std::size_t samples) noexcept { campaign_.samples = samples; }

  // The line's design (identical on every process for the same campaign and seed).
  LineDesign design(const PreparedLine& line) const;

  // Whether the line's models are slow (evaluator.hpp, seconds_per_sample): its samples are then
  // handed out `[shell_fe] chunk_size` at a time (one by default: they take seconds each and
  // balance only when handed out one by one), `chunk_size` at a time otherwise.
  bool has_slow_samples(const PreparedLine& line) const;
  std::size_t chunk_size_of(const PreparedLine& line) const;

  // The chunk's computed outputs (SI), output after output, then each sample's status as a
  // double: (computed_outputs().size() + 1) * (range.end - range.begin) values, read back with
  // ChunkValues (src/campaign/chunk_values.hpp). Each model's declaration is checked as it runs
  // (evaluate_checked).
  std::vector<double> evaluate_chunk(const PreparedLine& line, const LineDesign& design, ChunkRange range) const;

 private:
  PreparedCampaign(Campaign campaign, Pool* pool, ProgressMode progress, std::ostream* log);

  Campaign campaign_;
  // What the lines' plans choose from, per fidelity the lines use (campaign_models.hpp).
  std::map<Fidelity, std::vector<std::unique_ptr<const Evaluator>>> models_;
  std::vector<PreparedLine> lines_;
  std::vector<std::string> computed_outputs_;
  bool calibrates_kappa_ = false;
  double experimental_median_;
};

// The seed of a line's `physics` correlation draws: derive_key(derive_key(mix64(seed), line),
// "physics_correlation") (random_stream.hpp), so each line draws its own tubes reproducibly.
std::uint64_t physics_correlation_seed(std::uint64_t campaign_seed, std::string_view line);

}  // namespace growthuq
