// A campaign run with its outputs: the output directory (refused when it exists, unless
// forced), samples.csv and results.h5 written line by line as lines finish, summary.csv always,
// progress on stderr and the readable summary on stdout. What `growthuq run` does after
// validating the campaign.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/campaign/line_result.hpp"
#include "growthuq/campaign/progress.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/pool/pool.hpp"

namespace growthuq {

struct OutputSettings {
  Overwrite overwrite = Overwrite::refuse;  // allow: reuse an existing output directory (--force)
  ProgressMode progress = ProgressMode::none;
  std::string command_line;                 // stored in results.h5
};

struct CampaignOutcome {
  RunOutcome run;
  std::vector<QuantitySummary> summaries;  // rows of summary.csv (coordinator only)
};

// The names of the files a run writes in the output directory.
inline constexpr const char* samples_csv_name = "samples.csv";
inline constexpr const char* summary_csv_name = "summary.csv";
inline constexpr const char* results_h5_name = "results.h5";

// Every process calls it. Rank 0 checks and creates campaign.output_dir before any sampling
// (InputError naming it when it exists and overwrite is refuse; with allow, result files of
// formats not written this time are removed so the folder never mixes two runs), streams the
// lines, writes `report` (stdout) and `log` (stderr: progress, design warnings). When the run
// fails (e.g. kappa cannot be calibrated because no reference tube grows), the .partial files
// are removed and so is the output directory if this run created it.
CampaignOutcome run_campaign_with_outputs(const PreparedCampaign& campaign, Pool& pool, const OutputSettings& settings,
                                          std::ostream& report, std::ostream& log);

}  // namespace growthuq
