#include "growthuq/evaluation/evaluator.hpp"

#include <algorithm>

#include "growthuq/core/error.hpp"

namespace growthuq {
namespace {

bool contains(const std::vector<std::string>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

const Evaluator* producer_of(std::span<const Evaluator* const> available, std::string_view quantity) {
  for (const Evaluator* evaluator : available) {
    if (contains(evaluator->writes(), quantity)) return evaluator;
  }
  return nullptr;
}

// Depth-first: schedule what `quantity` needs, then its producer. `chain` holds the
// quantities being resolved, to report a cycle instead of recursing forever.
void schedule(std::span<const Evaluator* const> available, const std::vector<std::string>& inputs,
              std::string_view quantity, std::vector<std::string>& chain,
              std::vector<const Evaluator*>& plan) {
  if (contains(inputs, quantity)) return;
  const Evaluator* producer = producer_of(available, quantity);
  if (producer == nullptr) {
    std::string path;
    for (const auto& step : chain) path += step + " <- ";
    throw InputError("outputs", "cannot compute '" + path + std::string(quantity) +
                                    "': it is neither an input of the line nor written by any model");
  }
  if (std::find(plan.begin(), plan.end(), producer) != plan.end()) return;
  if (contains(chain, quantity)) {
    throw InputError("outputs", "models depend on each other in a cycle through '" + std::string(quantity) + "'");
  }
  chain.emplace_back(quantity);
  for (const std::string& needed : producer->reads()) schedule(available, inputs, needed, chain, plan);
  chain.pop_back();
  plan.push_back(producer);
}

}  // namespace

std::vector<const Evaluator*> plan_evaluation(std::span<const Evaluator* const> available,
                                              std::span<const std::string> inputs,
                                              std::span<const std::string> outputs) {
  const std::vector<std::string> input_names(inputs.begin(), inputs.end());
  std::vector<const Evaluator*> plan;
  std::vector<std::string> chain;
  for (const std::string& output : outputs) schedule(available, input_names, output, chain, plan);
  return plan;
}

void run_plan(std::span<const Evaluator* const> plan, SampleBlock& block) {
  for (const Evaluator* evaluator : plan) evaluator->evaluate(block);
}

}  // namespace growthuq
