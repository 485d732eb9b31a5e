// The finite-element inverse as a campaign's evaluator (evaluation/evaluator.hpp), fidelity
// shell_fe: per sample one invert_indentation() (minutes of one core at the default mesh), so a
// campaign hands out its samples one by one (Campaign::chunk_size_of).
//   ShellFeTurgorModulus   reads k, d, d0, h   writes p, E
// A sample the model cannot invert gets the finite-element status (sample_status.hpp), never
// an exception.
#pragma once

#include "growthuq/evaluation/evaluator.hpp"
#include "growthuq/fe/indentation.hpp"
#include "growthuq/mechanics/instrument.hpp"

namespace growthuq {

// The sample status of a finite-element status (the shared ones keep their names).
SampleStatus sample_status(ShellFeStatus status);

class ShellFeTurgorModulus final : public Evaluator {
 public:
  // InputError (naming `location`) when the instrument or the options are invalid.
  ShellFeTurgorModulus(const Instrument& instrument, const ShellFeOptions& options, std::string_view location);
  std::string_view name() const override { return "shell_fe_turgor_modulus"; }
  std::vector<std::string> reads() const override { return {"k", "d", "d0", "h"}; }
  std::vector<std::string> writes() const override { return {"p", "E"}; }
  void evaluate(SampleBlock& block) const override;

 private:
  Instrument instrument_;
  ShellFeOptions options_;
};

}  // namespace growthuq
