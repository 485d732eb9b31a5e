// The fidelity axis of the trade: every (fidelity, sample count) run against the finite-element
// reference (the shell_fe run with the most samples), and the cheapest run whose every median
// and IQR is within a target of it. Pure functions of tradeoff rows (tradeoff.hpp).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "growthuq/campaign/tradeoff.hpp"

namespace growthuq {

// One run condensed over its lines x quantities against the finite-element reference.
struct TradeoffRunAgainstFe {
  std::string fidelity;
  std::size_t samples = 0;
  double seconds = 0;
  TradeoffWorst median_error_pct;  // worst fe_median_error_pct of the run (NaN ranks worst)
  TradeoffWorst iqr_error_pct;     // worst fe_iqr_error_pct
  bool is_reference = false;       // the finite-element reference itself (errors 0 by definition)
  bool meets_target = false;       // every fe median and IQR error defined and below the target
};

struct TradeoffChoice {
  double target_pct = 1.0;
  std::size_t reference_samples = 0;  // of the shell_fe reference run
  std::vector<TradeoffRunAgainstFe> runs;  // fidelities in order of appearance, samples increasing
  // Index into `runs` of the run with the least seconds that meets the target (ties: fewer
  // samples, then first listed); the reference is never chosen (it meets any target trivially).
  std::optional<std::size_t> cheapest;
  // When no run meets the target: index of the run whose worse of its two worst errors is the
  // smallest (an undefined error ranks worst; ties: fewer seconds). Empty when no run besides
  // the reference exists.
  std::optional<std::size_t> closest;
};

// Condenses `rows` (tradeoff_rows) against the shell_fe reference and `target_pct` (> 0).
// Nothing when the rows hold no shell_fe run. std::invalid_argument for a target <= 0.
std::optional<TradeoffChoice> choose_cheapest_run(std::span<const TradeoffRow> rows, double target_pct);

// The table of every run (fidelity, samples/line, seconds, worst median and IQR error against
// the finite-element reference with line and quantity), then one sentence naming the cheapest
// run meeting the target, or saying that none does and which came closest.
std::string format_tradeoff_choice(const TradeoffChoice& choice);

}  // namespace growthuq
