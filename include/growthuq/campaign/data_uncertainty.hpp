// How much the medians of a campaign move because its raw-data lines were fitted to 20-60
// tubes: a parametric bootstrap over tubes, on by default for a campaign with a raw-data line
// (campaign_file.hpp, DataUncertaintySettings). The Monte Carlo 95 % CI of a median in
// summary.csv (median_ci_low/high) reflects the error of the campaign's samples only; with laws
// fitted to a few dozen tubes the data's own uncertainty is usually larger. Its interval is
// data_ci_low/high of summary.csv and results.h5.
//
// Replicate b (of [data_uncertainty] replicates): every raw-data line's variables are redrawn,
// n values each (n = the tubes or fitted curves the line has for that variable), from the law
// the campaign fitted, and refitted exactly as the campaign did (all candidate families, least
// AIC). A line file's law that states `tubes = N` is redrawn N values and refitted within its
// own family by maximum likelihood (campaign/parametric_resample.hpp); its laws without `tubes`
// stay fixed, and so does every law of a line file that states none. The replicate campaign (same outputs,
// instrument, correlation targets and kappa calibration on the reference line) is sampled with
// its own seed, counter_bits(derive_key(mix64(seed), "data_uncertainty"), b), at [data_uncertainty]
// samples per line, and the median of each output is taken as summary.csv takes it. The 2.5 and
// 97.5 % quantiles of the replicate medians form the percentile interval (Efron & Tibshirani
// 1993, ch. 13): it holds the data's and the replicates' Monte Carlo uncertainty together. Curve
// fits are not redone: the spread of the fitted tau and einf already holds their measurement
// error, and a replicate redraws from that spread. k of force curves is, by default, also drawn
// within each tube's measurement uncertainty u (parametric_resample.hpp add_measurement_error;
// [force_curves] measurement_error, src/forcecurves/README.md Eq. (C11)). A replicate that fails (e.g. no sample of the
// reference line grows, so kappa cannot be calibrated) is counted and left out.
#pragma once

#include <cstddef>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/campaign/progress_mode.hpp"
#include "growthuq/pool/pool.hpp"

namespace growthuq {

struct DataUncertainty {
  std::string line;
  std::string quantity;
  std::string unit;             // symbol, as in summary.csv
  std::size_t replicates = 0;   // replicates that gave a median
  std::size_t failed = 0;       // replicates that failed or had no counted sample
  std::size_t samples = 0;      // per line and replicate
  double low = std::numeric_limits<double>::quiet_NaN();   // 2.5 % of the replicate medians
  double high = std::numeric_limits<double>::quiet_NaN();  // 97.5 %
  double sd = std::numeric_limits<double>::quiet_NaN();    // standard deviation of the replicate medians
  std::vector<double> replicate_medians;                   // of the successful replicates, in order
  std::vector<std::size_t> replicate_indices;              // b of each of them: replicate b of two
                                                           // lines is one replicate campaign
  // Whether the line's laws were redrawn in each replicate (a raw-data line); false: its
  // replicate medians vary by Monte Carlo error only, and line comparisons leave it out.
  bool resampled = false;
  // Whether the line's values were drawn within their measurement uncertainty too (k of force
  // curves, [force_curves] measurement_error = bootstrap): the interval then includes
  // measurement error.
  bool measurement_error = false;
  // The campaign's own median and its Monte Carlo 95 % CI (summary.csv), next to the interval
  // for reports; filled by the outputs (raw_data_outputs.hpp), NaN until then.
  double median = std::numeric_limits<double>::quiet_NaN();
  double median_ci_low = std::numeric_limits<double>::quiet_NaN();
  double median_ci_high = std::numeric_limits<double>::quiet_NaN();
};

struct DataUncertaintyResult {
  std::vector<DataUncertainty> rows;     // per line (run order) and output (campaign order)
  std::vector<std::string> failures;     // the first few reasons replicates failed
};

// Runs the bootstrap of `campaign` (replicates and samples from its [data_uncertainty]
// settings; nothing when replicates = 0) with its replicates shared out over the processes of
// `pool`, handed out one at a time as processes become free. Every process calls it; rank 0
// gets the result, the others an empty one. The result does not depend on the number of
// processes (replicate b's seed depends on b alone; rank 0 takes the medians in order of b).
// InputError on every process when every replicate failed. Progress ("data uncertainty:
// replicate 120/400, 4 s, about 9 s left") on `log` as `progress` says (none off rank 0).
DataUncertaintyResult estimate_data_uncertainty(const PreparedCampaign& campaign, Pool& pool, ProgressMode progress,
                                                std::ostream& log);

// Which variables of which lines the bootstrap redraws, one text per line in run order, e.g.
// "pme48 (line file): k (tubes = 21, lognormal refitted within its family); fixed: h, d, d0".
// Only the variables the campaign samples are named, and the reference line's v_exp (it
// calibrates kappa).
std::vector<std::string> data_uncertainty_sources(const PreparedCampaign& campaign);

// The same by this process alone, without progress.
DataUncertaintyResult estimate_data_uncertainty(const PreparedCampaign& campaign);

}  // namespace growthuq
