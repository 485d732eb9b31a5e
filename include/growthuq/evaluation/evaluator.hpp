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

  // Adds every column of writes() to `block`. Samples whose status is not ok on entry are
  // skipped (their outputs stay NaN).
  virtual void evaluate(SampleBlock& block) const = 0;
};

// The evaluators, in an order that can run, that turn `inputs` into `outputs`. Among
// `available` the first that writes a needed quantity is chosen; an evaluator is chosen only
// if one of its writes is needed. InputError naming the quantity (and what it lacks) when an
// output cannot be produced from the inputs.
std::vector<const Evaluator*> plan_evaluation(std::span<const Evaluator* const> available,
                                              std::span<const std::string> inputs,
                                              std::span<const std::string> outputs);

// Runs `plan` in order on `block`.
void run_plan(std::span<const Evaluator* const> plan, SampleBlock& block);

}  // namespace growthuq
