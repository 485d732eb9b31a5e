#include "growthuq/campaign/tradeoff_choice.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "campaign/tradeoff_worst.hpp"

namespace growthuq {
namespace {

// The worse of a run's worst median and IQR errors: what "closest to the target" compares.
double worse_of_two(const TradeoffRunAgainstFe& run) {
  return worse_error(run.iqr_error_pct.value, run.median_error_pct.value) ? run.iqr_error_pct.value
                                                                           : run.median_error_pct.value;
}

bool cheaper(const TradeoffRunAgainstFe& candidate, const TradeoffRunAgainstFe& current) {
  if (candidate.seconds != current.seconds) return candidate.seconds < current.seconds;
  return candidate.samples < current.samples;
}

}  // namespace

std::optional<TradeoffChoice> choose_cheapest_run(std::span<const TradeoffRow> rows, double target_pct) {
  if (!(target_pct > 0)) throw std::invalid_argument("choose_cheapest_run: the target must be positive");
  TradeoffChoice choice;
  choice.target_pct = target_pct;
  bool has_fe = false;
  for (const TradeoffRow& row : rows) {
    if (row.fidelity != shell_fe_label) continue;
    has_fe = true;
    if (row.samples > choice.reference_samples) choice.reference_samples = row.samples;
  }
  if (!has_fe) return std::nullopt;

  // Runs by fidelity in order of first appearance, then by sample count.
  std::vector<std::string> fidelities;
  std::map<std::pair<std::string, std::size_t>, std::vector<const TradeoffRow*>> rows_of_run;
  for (const TradeoffRow& row : rows) {
    if (std::find(fidelities.begin(), fidelities.end(), row.fidelity) == fidelities.end()) {
      fidelities.push_back(row.fidelity);
    }
    rows_of_run[{row.fidelity, row.samples}].push_back(&row);
  }
  for (const std::string& fidelity : fidelities) {
    for (auto it = rows_of_run.lower_bound({fidelity, 0}); it != rows_of_run.end() && it->first.first == fidelity; ++it) {
      const std::vector<const TradeoffRow*>& members = it->second;
      TradeoffRunAgainstFe run;
      run.fidelity = fidelity;
      run.samples = it->first.second;
      run.seconds = members.front()->seconds;
      run.is_reference = fidelity == shell_fe_label && run.samples == choice.reference_samples;
      run.meets_target = !run.is_reference;
      bool first = true;
      for (const TradeoffRow* row : members) {
        keep_worst_error(run.median_error_pct, row->fe_median_error_pct, row->line, row->quantity, first);
        keep_worst_error(run.iqr_error_pct, row->fe_iqr_error_pct, row->line, row->quantity, first);
        first = false;
        // NaN compares false: an undefined error never meets the target.
        if (!(row->fe_median_error_pct < target_pct && row->fe_iqr_error_pct < target_pct)) run.meets_target = false;
      }
      choice.runs.push_back(std::move(run));
    }
  }

  for (std::size_t i = 0; i < choice.runs.size(); ++i) {
    const TradeoffRunAgainstFe& run = choice.runs[i];
    if (run.is_reference) continue;
    if (run.meets_target && (!choice.cheapest || cheaper(run, choice.runs[*choice.cheapest]))) choice.cheapest = i;
    if (!choice.closest) {
      choice.closest = i;
      continue;
    }
    const TradeoffRunAgainstFe& best = choice.runs[*choice.closest];
    const double error = worse_of_two(run), best_error = worse_of_two(best);
    const bool tie = error == best_error || (std::isnan(error) && std::isnan(best_error));
    if (worse_error(best_error, error) || (tie && cheaper(run, best))) choice.closest = i;
  }
  if (choice.cheapest) choice.closest.reset();
  return choice;
}

}  // namespace growthuq
