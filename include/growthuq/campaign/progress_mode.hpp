// How a campaign's steps report their progress on a stream: a bar on a terminal, one line per
// finished step in logs and batch jobs, or nothing. A program chooses once and passes the mode
// to the steps (PreparedCampaign, run_tradeoff, estimate_data_uncertainty); the bar and the
// lines themselves are the engine's business.
#pragma once

namespace growthuq {

enum class ProgressMode { none, lines, bar };

// bar when stderr is a terminal, lines otherwise, none when `quiet`.
ProgressMode choose_progress_mode(bool quiet);

}  // namespace growthuq
