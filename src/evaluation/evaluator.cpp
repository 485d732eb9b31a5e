#include "growthuq/evaluation/evaluator.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
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

// A position-keyed sum of a column's bits: changing, adding or swapping values changes it
// except for changes built to cancel, and it reads the column once without copying it (a copy
// and compare of every column cost more than the fast models themselves).
std::uint64_t fingerprint(std::span<const double> values) {
  std::uint64_t sum = 0;
  std::uint64_t key = 0;  // i * 0x9E37...: the position (a running sum, so the loop vectorizes)
  for (const double value : values) {
    sum += std::bit_cast<std::uint64_t>(value) ^ key;
    key += 0x9E3779B97F4A7C15ull;
  }
  return sum;
}

// The block as the next evaluator finds it: each column's fingerprint and every status.
class DeclarationCheck {
 public:
  explicit DeclarationCheck(const SampleBlock& block) {
    for (std::string& quantity : block.quantities()) {
      const std::uint64_t print = fingerprint(block.column(quantity));
      columns_.emplace_back(std::move(quantity), print);
    }
    status_.assign(block.status().begin(), block.status().end());
  }

  // After `evaluator` ran on `block`: its declaration kept (evaluate_checked), then the block's
  // state taken for the next one.
  void after(const Evaluator& evaluator, const SampleBlock& block) {
    const std::vector<std::string> writes = evaluator.writes();
    const std::span<const SampleStatus> status = block.status();
    // Each test over all samples first, without branches (they vectorize); the sample to name
    // is looked for only when one fails.
    bool flag_changed = false;
    for (std::size_t i = 0; i < block.size(); ++i) flag_changed |= status_[i] != SampleStatus::ok && status[i] != status_[i];
    for (std::size_t i = 0; flag_changed && i < block.size(); ++i) {
      if (status_[i] != SampleStatus::ok && status[i] != status_[i]) {
        broken_declaration(evaluator, "it changed the status of sample " + std::to_string(i) + " from " +
                                          std::string(to_string(status_[i])) + " to " + std::string(to_string(status[i])));
      }
    }
    for (const std::string& quantity : writes) {
      if (!block.has(quantity)) broken_declaration(evaluator, "it did not write the declared column '" + quantity + "'");
      const std::span<const double> values = block.column(quantity);
      bool unwritten = false;
      for (std::size_t i = 0; i < block.size(); ++i) unwritten |= status[i] == SampleStatus::ok && !std::isfinite(values[i]);
      for (std::size_t i = 0; unwritten && i < block.size(); ++i) {
        if (status[i] == SampleStatus::ok && !std::isfinite(values[i])) {
          broken_declaration(evaluator, "the declared column '" + quantity + "' holds " + std::to_string(values[i]) +
                                            " for sample " + std::to_string(i) + ", whose status is ok");
        }
      }
      // A value where the sample is flagged reads as computed (samples.csv, summaries): only
      // a flag this evaluator raised under one of the column's valued statuses may keep one.
      const StatusSet valued = evaluator.valued_statuses(quantity);
      const auto stray = [&](std::size_t i) {
        return status[i] != SampleStatus::ok && std::isfinite(values[i]) &&
               !(status_[i] == SampleStatus::ok && valued.contains(status[i]));
      };
      bool any_stray = false;
      for (std::size_t i = 0; i < block.size(); ++i) any_stray |= stray(i);
      for (std::size_t i = 0; any_stray && i < block.size(); ++i) {
        if (stray(i)) {
          broken_declaration(evaluator, "the declared column '" + quantity + "' holds " + std::to_string(values[i]) +
                                            " for sample " + std::to_string(i) + ", flagged " +
                                            std::string(to_string(status[i])) + " (expected NaN: not computed)");
        }
      }
    }
    std::vector<std::pair<std::string, std::uint64_t>> columns;
    for (std::string& quantity : block.quantities()) {
      const std::uint64_t print = fingerprint(block.column(quantity));
      const auto before = std::find_if(columns_.begin(), columns_.end(), [&](const auto& column) { return column.first == quantity; });
      if (!contains(writes, quantity)) {
        if (before == columns_.end()) broken_declaration(evaluator, "it added the column '" + quantity + "', which writes() does not name");
        if (before->second != print) broken_declaration(evaluator, "it changed the column '" + quantity + "', which writes() does not name");
      }
      columns.emplace_back(std::move(quantity), print);
    }
    columns_ = std::move(columns);
    status_.assign(status.begin(), status.end());
  }

 private:
  std::vector<std::pair<std::string, std::uint64_t>> columns_;
  std::vector<SampleStatus> status_;
};

}  // namespace

void evaluate_checked(const Evaluator& evaluator, SampleBlock& block) {
  DeclarationCheck check(block);
  evaluator.evaluate(block);
  check.after(evaluator, block);
}

double seconds_per_sample(std::span<const Evaluator* const> plan) {
  double seconds = 0.0;
  for (const Evaluator* evaluator : plan) seconds += evaluator->seconds_per_sample();
  return seconds;
}

void run_plan(std::span<const Evaluator* const> plan, SampleBlock& block) {
  DeclarationCheck check(block);  // one look at the block before each evaluator, the last one's after
  for (const Evaluator* evaluator : plan) {
    evaluator->evaluate(block);
    check.after(*evaluator, block);
  }
}

}  // namespace growthuq
