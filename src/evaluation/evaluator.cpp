#include "growthuq/evaluation/evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <utility>

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

namespace {

[[noreturn]] void broken_declaration(const Evaluator& evaluator, const std::string& what) {
  throw std::logic_error("evaluator '" + std::string(evaluator.name()) + "' broke its declaration: " + what);
}

}  // namespace

void evaluate_checked(const Evaluator& evaluator, SampleBlock& block) {
  const std::vector<std::string> writes = evaluator.writes();
  // What the evaluator may not change: the columns it does not declare, and the flags.
  std::vector<std::pair<std::string, std::vector<double>>> kept;
  for (std::string& quantity : block.quantities()) {
    if (contains(writes, quantity)) continue;
    const std::span<const double> values = std::as_const(block).column(quantity);
    kept.emplace_back(std::move(quantity), std::vector<double>(values.begin(), values.end()));
  }
  const std::span<const SampleStatus> status = std::as_const(block).status();
  const std::vector<SampleStatus> status_before(status.begin(), status.end());

  evaluator.evaluate(block);

  for (const std::string& quantity : block.quantities()) {
    const bool known = contains(writes, quantity) ||
                       std::any_of(kept.begin(), kept.end(), [&](const auto& column) { return column.first == quantity; });
    if (!known) broken_declaration(evaluator, "it added the column '" + quantity + "', which writes() does not name");
  }
  for (const auto& [quantity, values] : kept) {
    const std::span<const double> after = std::as_const(block).column(quantity);
    if (std::memcmp(after.data(), values.data(), values.size() * sizeof(double)) != 0) {
      broken_declaration(evaluator, "it changed the column '" + quantity + "', which writes() does not name");
    }
  }
  for (std::size_t i = 0; i < block.size(); ++i) {
    if (status_before[i] != SampleStatus::ok && status[i] != status_before[i]) {
      broken_declaration(evaluator, "it changed the status of sample " + std::to_string(i) + " from " +
                                        std::string(to_string(status_before[i])) + " to " + std::string(to_string(status[i])));
    }
  }
  for (const std::string& quantity : writes) {
    if (!block.has(quantity)) broken_declaration(evaluator, "it did not write the declared column '" + quantity + "'");
    const std::span<const double> values = std::as_const(block).column(quantity);
    for (std::size_t i = 0; i < block.size(); ++i) {
      if (status[i] == SampleStatus::ok && !std::isfinite(values[i])) {
        broken_declaration(evaluator, "the declared column '" + quantity + "' holds " + std::to_string(values[i]) +
                                          " for sample " + std::to_string(i) + ", whose status is ok");
      }
    }
  }
}

void run_plan(std::span<const Evaluator* const> plan, SampleBlock& block) {
  for (const Evaluator* evaluator : plan) evaluate_checked(*evaluator, block);
}

}  // namespace growthuq
