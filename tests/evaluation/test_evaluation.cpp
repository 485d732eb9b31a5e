// The planner picks exactly the evaluators an output needs, in a runnable order; the statuses
// it carries have one name each.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <stdexcept>
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

TEST_CASE("every status code has its own name and sentence and a row in campaigns/README.md's statuses table") {
  // The codes run 0 .. last_sample_status without a gap (results.h5 writes names[code]); the
  // code after the last has no name, so a status appended without moving last_sample_status
  // shows up here.
  std::ifstream file(std::string(GROWTHUQ_SOURCE_DIR) + "/campaigns/README.md");
  REQUIRE(file);
  const std::string readme((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  std::set<std::string> names;
  std::set<std::string> sentences;
  const int last = static_cast<int>(last_sample_status);
  CHECK(last == 17);
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

namespace {

// Declares x -> y but, as `fault` says, breaks the declaration in one way.
enum class Fault {
  none, writes_undeclared, leaves_declared_unwritten, changes_its_read, leaves_nan_for_ok, clears_a_flag,
  writes_a_flagged_sample,  // a value for sample 0, which entered flagged (it never ran there)
  flags_and_keeps_value,    // y of sample 2 written, then flagged out_of_range
  flags_valued,             // y = 0 of sample 2 flagged no_growth, a status y is declared valued under: allowed
};

class FaultyEvaluator final : public Evaluator {
 public:
  explicit FaultyEvaluator(Fault fault) : fault_(fault) {}
  std::string_view name() const override { return "faulty"; }
  std::vector<std::string> reads() const override { return {"x"}; }
  std::vector<std::string> writes() const override { return {"y"}; }
  StatusSet valued_statuses(std::string_view) const override { return {SampleStatus::no_growth}; }
  void evaluate(SampleBlock& block) const override {
    if (fault_ == Fault::clears_a_flag) block.status()[0] = SampleStatus::ok;
    if (fault_ == Fault::writes_undeclared) block.add_column("z");
    if (fault_ == Fault::changes_its_read) block.column("x")[1] = 0.5;
    if (fault_ == Fault::leaves_declared_unwritten) return;
    const auto y = block.add_column("y");
    for (std::size_t i = 0; i < block.size(); ++i) {
      if (block.status()[i] != SampleStatus::ok) continue;
      if (fault_ == Fault::leaves_nan_for_ok && i == 2) continue;
      y[i] = 2 * block.column("x")[i];
    }
    if (fault_ == Fault::writes_a_flagged_sample) y[0] = 2.0;
    if (fault_ == Fault::flags_and_keeps_value) block.flag(2, SampleStatus::out_of_range);
    if (fault_ == Fault::flags_valued) {
      y[2] = 0.0;
      block.flag(2, SampleStatus::no_growth);
    }
  }

 private:
  Fault fault_;
};

SampleBlock block_with_x() {
  SampleBlock block(3);
  const double x[] = {1.0, 2.0, 3.0};
  block.set_column("x", x);
  block.flag(0, SampleStatus::invalid_input);  // entered flagged: y stays NaN there
  return block;
}

}  // namespace

TEST_CASE("evaluate_checked passes an evaluator that keeps its declaration") {
  SampleBlock block = block_with_x();
  const FaultyEvaluator honest(Fault::none);
  evaluate_checked(honest, block);
  CHECK(std::isnan(block.column("y")[0]));  // flagged on entry: left NaN, and that is allowed
  CHECK(block.column("y")[1] == 4.0);
  CHECK(block.column("y")[2] == 6.0);
  CHECK(block.status()[0] == SampleStatus::invalid_input);
}

TEST_CASE("evaluate_checked stops an evaluator that breaks its declaration, naming it") {
  const auto message_of = [](Fault fault) {
    SampleBlock block = block_with_x();
    const FaultyEvaluator faulty(fault);
    try {
      evaluate_checked(faulty, block);
    } catch (const std::logic_error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  CHECK(message_of(Fault::writes_undeclared) ==
        "evaluator 'faulty' broke its declaration: it added the column 'z', which writes() does not name");
  CHECK(message_of(Fault::leaves_declared_unwritten) ==
        "evaluator 'faulty' broke its declaration: it did not write the declared column 'y'");
  CHECK(message_of(Fault::changes_its_read) ==
        "evaluator 'faulty' broke its declaration: it changed the column 'x', which writes() does not name");
  CHECK(message_of(Fault::leaves_nan_for_ok) ==
        "evaluator 'faulty' broke its declaration: the declared column 'y' holds nan for sample 2, whose status is ok");
  CHECK(message_of(Fault::clears_a_flag) ==
        "evaluator 'faulty' broke its declaration: it changed the status of sample 0 from invalid_input to ok");
  // A value beside a flag would read as computed in samples.csv and the summaries.
  CHECK(message_of(Fault::writes_a_flagged_sample) ==
        "evaluator 'faulty' broke its declaration: the declared column 'y' holds 2.000000 for sample 0, flagged "
        "invalid_input (expected NaN: not computed)");
  CHECK(message_of(Fault::flags_and_keeps_value) ==
        "evaluator 'faulty' broke its declaration: the declared column 'y' holds 6.000000 for sample 2, flagged "
        "out_of_range (expected NaN: not computed)");
  CHECK(message_of(Fault::flags_valued) == "no error");
}

TEST_CASE("run_plan checks every evaluator of the plan") {
  SampleBlock block = block_with_x();
  const FaultyEvaluator faulty(Fault::writes_undeclared);
  const std::vector<const Evaluator*> plan{&faulty};
  CHECK_THROWS_AS(run_plan(plan, block), std::logic_error);
}

TEST_CASE("a status set holds exactly the statuses given") {
  const StatusSet none;
  const StatusSet growth{SampleStatus::no_growth};
  const StatusSet two{SampleStatus::ok, SampleStatus::unstable_branch};
  CHECK(none.empty());
  CHECK_FALSE(growth.empty());
  for (int code = 0; code <= static_cast<int>(last_sample_status); ++code) {
    const auto status = static_cast<SampleStatus>(code);
    CHECK_FALSE(none.contains(status));
    CHECK(growth.contains(status) == (status == SampleStatus::no_growth));
    CHECK(two.contains(status) == (status == SampleStatus::ok || status == SampleStatus::unstable_branch));
  }
}
