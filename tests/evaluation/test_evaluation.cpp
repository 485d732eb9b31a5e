// The planner picks exactly the evaluators an output needs, in a runnable order; the statuses
// it carries have one name each.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/evaluation/evaluator.hpp"

using namespace growthuq;

namespace {

// y = sum of inputs; flags samples whose first input is negative.
class SumEvaluator final : public Evaluator {
 public:
  SumEvaluator(std::string name, std::vector<std::string> reads, std::string writes)
      : name_(std::move(name)), reads_(std::move(reads)), writes_(std::move(writes)) {}
  std::string_view name() const override { return name_; }
  std::vector<std::string> reads() const override { return reads_; }
  std::vector<std::string> writes() const override { return {writes_}; }
  void evaluate(SampleBlock& block) const override {
    auto out = block.add_column(writes_);
    for (std::size_t i = 0; i < block.size(); ++i) {
      if (block.status()[i] != SampleStatus::ok) continue;
      if (block.column(reads_[0])[i] < 0) {
        block.flag(i, SampleStatus::invalid_input);
        continue;
      }
      double sum = 0;
      for (const auto& input : reads_) sum += block.column(input)[i];
      out[i] = sum;
    }
  }

 private:
  std::string name_;
  std::vector<std::string> reads_;
  std::string writes_;
};

}  // namespace

TEST_CASE("planner chooses only what the outputs need") {
  const SumEvaluator turgor("turgor", {"k", "d", "d0"}, "p");
  const SumEvaluator modulus("modulus", {"p", "h"}, "E");
  const SumEvaluator viscosity("viscosity", {"tau", "einf", "E"}, "eta");
  const std::vector<const Evaluator*> available{&viscosity, &modulus, &turgor};

  const std::vector<std::string> turgor_inputs{"k", "d", "d0"};
  const std::vector<std::string> want_p{"p"};
  const auto plan_p = plan_evaluation(available, turgor_inputs, want_p);
  REQUIRE(plan_p.size() == 1);
  CHECK(plan_p[0] == &turgor);

  const std::vector<std::string> all_inputs{"k", "d", "d0", "h", "tau", "einf"};
  const std::vector<std::string> want_eta{"eta", "p"};
  const auto plan_eta = plan_evaluation(available, all_inputs, want_eta);
  REQUIRE(plan_eta.size() == 3);
  CHECK(plan_eta[0] == &turgor);
  CHECK(plan_eta[1] == &modulus);
  CHECK(plan_eta[2] == &viscosity);

  const std::vector<std::string> want_E{"E"};
  CHECK_THROWS_WITH_AS(plan_evaluation(available, turgor_inputs, want_E),
                       "outputs: cannot compute 'E <- h': it is neither an input of the line nor written by any model",
                       InputError);
}

TEST_CASE("running a plan fills columns and keeps the first status") {
  const SumEvaluator first("first", {"a", "b"}, "c");
  const SumEvaluator second("second", {"c", "a"}, "d");
  SampleBlock block(3);
  block.set_column("a", std::vector<double>{1, -1, 2});
  block.set_column("b", std::vector<double>{10, 10, 20});
  const std::vector<const Evaluator*> plan{&first, &second};
  run_plan(plan, block);
  CHECK(block.column("d")[0] == 12);
  CHECK(block.column("d")[2] == 24);
  CHECK(block.status()[1] == SampleStatus::invalid_input);
  CHECK(std::isnan(block.column("d")[1]));
  CHECK(to_string(block.status()[1]) == "invalid_input");
}

TEST_CASE("every status code has its own name and sentence and a row in README's statuses table") {
  // The codes run 0 .. last_sample_status without a gap (results.h5 writes names[code]); the
  // code after the last has no name, so a status appended without moving last_sample_status
  // shows up here.
  std::ifstream file(std::string(GROWTHUQ_SOURCE_DIR) + "/README.md");
  REQUIRE(file);
  const std::string readme((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  std::set<std::string> names;
  std::set<std::string> sentences;
  const int last = static_cast<int>(last_sample_status);
  CHECK(last == 9);
  for (int code = 0; code <= last; ++code) {
    const auto status = static_cast<SampleStatus>(code);
    const std::string name(to_string(status));
    CAPTURE(code);
    CHECK(name != "unknown");
    CHECK(describe(status) != "unknown status");
    CHECK(readme.find("| `" + name + "` |") != std::string::npos);
    names.insert(name);
    sentences.emplace(describe(status));
  }
  CHECK(names.size() == static_cast<std::size_t>(last + 1));
  CHECK(sentences.size() == static_cast<std::size_t>(last + 1));
  CHECK(to_string(static_cast<SampleStatus>(last + 1)) == "unknown");
  CHECK(to_string(SampleStatus::unstable_branch) == "unstable_branch");
}
