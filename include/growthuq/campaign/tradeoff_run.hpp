// Running a campaign at several fidelities and sample counts for the speed/accuracy trade
// (tradeoff.hpp): once per fidelity and count, through the same pool (so it works under mpirun too), keeping only the
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

// The fidelity column of tradeoff.csv: to_string(fidelity).
std::string fidelity_label(Fidelity fidelity);

// The runs of one fidelity: its sample counts per line, increasing.
struct TradeoffSeries {
  Fidelity fidelity = Fidelity::closed_form;
  std::vector<std::size_t> sample_counts;
};

// `campaign` with every line at `fidelity`: the trade compares fidelities run by run, so a
// line's own `fidelity =` override does not apply.
Campaign campaign_at_fidelity(Campaign campaign, Fidelity fidelity);

// Runs `campaign` at each series' fidelity (campaign_at_fidelity) with `samples` = each of its
// counts in turn (the campaign's samples key is not used), series in the order given. The seed
// is the same for every count and fidelity, so the designs at different counts are independent
// Latin hypercube draws (a design depends on seed, line, variable and n) and two fidelities at
// the same count evaluate the same samples. The campaign is prepared once per fidelity (line
// files or raw-data fits, physics correlation, the fidelity's models); a run's seconds are the
// wall time on the coordinator from its first design to its last line's summaries, without
// writing any file. Every process calls it; the runs (with summaries) are returned on the
// coordinator, runs without summaries elsewhere. Progress goes to `log` in `progress` mode,
// design warnings always.
std::vector<TradeoffRun> run_tradeoff(const Campaign& campaign, std::span<const TradeoffSeries> series, Pool& pool,
                                      ProgressMode progress, std::ostream& log);

// One series at the campaign's [campaign] fidelity.
std::vector<TradeoffRun> run_tradeoff(const Campaign& campaign, std::span<const std::size_t> sample_counts, Pool& pool,
                                      ProgressMode progress, std::ostream& log);

}  // namespace growthuq
