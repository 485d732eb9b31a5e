// Running a campaign at several sample counts for the speed/accuracy trade (tradeoff.hpp):
// once per count, through the same pool (so it works under mpirun too), keeping only the
// per-line summaries (no samples.csv or results.h5), timed on the coordinator.
#pragma once

#include <cstddef>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/progress_mode.hpp"
#include "growthuq/campaign/tradeoff.hpp"
#include "growthuq/pool/pool.hpp"

namespace growthuq {

// The fidelity column of tradeoff.csv: "analytic" for the thin-shell models.
std::string fidelity_label(Fidelity fidelity);

// Runs `campaign` with `samples` = each of `sample_counts` in turn (its own samples key is not
// used). The seed is the same for every count, so the designs at different counts are
// independent Latin hypercube draws (a design depends on seed, line, variable and n). The
// campaign is prepared once (line files or raw-data fits, physics correlation); a count's
// seconds are the wall time on the coordinator from its first design to its last line's
// summaries, without writing any file. Every process
// calls it; the runs (with summaries) are returned on the coordinator, runs without summaries
// elsewhere. Progress goes to `log` in `progress` mode, design warnings always.
std::vector<TradeoffRun> run_tradeoff(const Campaign& campaign, std::span<const std::size_t> sample_counts, Pool& pool,
                                      ProgressMode progress, std::ostream& log);

}  // namespace growthuq
