// The evaluator interface and the planner that picks, for the outputs a user asks for, the
// evaluators needed and no others (a turgor-only request never asks for wall thickness).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "growthuq/evaluation/sample_block.hpp"

namespace growthuq {

// A model run on a batch: reads some quantities, writes others. Implementations are pure
// functions of their inputs and constructor parameters, so any process may call them, and
// evaluate() never throws: a sample that cannot be evaluated gets a status and NaN outputs.
class Evaluator {
 public:
  virtual ~Evaluator() = default;

  virtual std::string_view name() const = 0;
  virtual std::vector<std::string> reads() const = 0;
  virtual std::vector<std::string> writes() const = 0;

  // The statuses other than ok, raised by this evaluator, under which the column `written` (one
  // of writes()) still holds a result rather than NaN; none unless an evaluator says so.
  virtual StatusSet valued_statuses(std::string_view written) const {
    (void)written;
    return {};
  }

  // The cost of one sample, in seconds of one core as measured for this model (0: microseconds,
  // the analytic models). What the scheduler asks of a model: a line whose models cost at least
  // slow_sample_seconds is handed out sample by sample, its run time is estimated before it
  // starts (`growthuq check`), and `growthuq eval` prints progress tube by tube.
  virtual double seconds_per_sample() const { return 0.0; }

  // Adds every column of writes() to `block`. Samples whose status is not ok on entry are
  // skipped (their outputs stay NaN).
  virtual void evaluate(SampleBlock& block) const = 0;
};

// The cost from which a model counts as slow (seconds_per_sample).
inline constexpr double slow_sample_seconds = 0.1;

// The seconds of one core per sample of `plan` (the sum of its evaluators').
double seconds_per_sample(std::span<const Evaluator* const> plan);

// The evaluators, in an order that can run, that turn `inputs` into `outputs`. Among
// `available` the first that writes a needed quantity is chosen; an evaluator is chosen only
// if one of its writes is needed. InputError naming the quantity (and what it lacks) when an
// output cannot be produced from the inputs.
std::vector<const Evaluator*> plan_evaluation(std::span<const Evaluator* const> available,
                                              std::span<const std::string> inputs,
                                              std::span<const std::string> outputs);

// Runs `evaluator` on `block` and checks that it kept its declaration, as pagmo's problem
// wrapper checks every fitness call, so each model stays a plain function of its columns:
//   - every column of writes() is in the block, and each sample's value there is finite or the
//     sample carries a non-ok status (a written column left NaN for an ok sample was not
//     written);
//   - and NaN for every sample that leaves with a non-ok status, unless this evaluator raised
//     it and it is one of the column's valued_statuses (v = 0 for no_growth): a finite value
//     is read downstream as computed (samples.csv's cells, the summaries' counts);
//   - no column outside writes() was added, and every column it found that writes() does not
//     name (its reads among them) holds the same bits as before (compared through a
//     position-keyed checksum of each column, so the check reads the block without copying it);
//   - a sample that entered with a non-ok status leaves with that status (the first flag stays).
// std::logic_error naming the evaluator, the column and the sample otherwise: a model that
// breaks its declaration is a bug, stopped at the first batch it breaks.
void evaluate_checked(const Evaluator& evaluator, SampleBlock& block);

// Runs `plan` in order on `block`, each evaluator checked as evaluate_checked checks it.
void run_plan(std::span<const Evaluator* const> plan, SampleBlock& block);

}  // namespace growthuq
