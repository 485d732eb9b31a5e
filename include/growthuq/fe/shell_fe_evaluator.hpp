// The finite-element inverse as a campaign's evaluator (evaluation/evaluator.hpp), fidelity
// shell_fe: per sample one invert_indentation() (minutes of one core at the default mesh), so a
// campaign hands out its samples one by one (Campaign::chunk_size_of).
//   ShellFeTurgorModulus   reads k, d, d0, h   writes p, E [, h0: the unstressed thickness, on request]
// A sample the model cannot invert gets the finite-element status (sample_status.hpp), never
// an exception.
#pragma once

#include "growthuq/evaluation/evaluator.hpp"
#include "growthuq/fe/indentation.hpp"
#include "growthuq/mechanics/instrument.hpp"
#include "growthuq/mechanics/probe_radius_column.hpp"

namespace growthuq {

// Seconds of one core per inverse (one force curve and up to six inflations) at a mesh level:
// means with the failed samples in (a campaign's time is the sum, and a sample that does not
// converge costs several that do). Measured over campaigns with the penalty contact (coarse 8.9 s
// per sample over the first 270 samples of campaigns/published_scale.ini; default 55 s over the
// 245 training tubes of src/correction/training.csv) and scaled by the exact contact's speed-up
// measured side by side on one tube by tools/bench/bench-fe-contact (2.5x coarse, 4.6x
// default): coarse 3.6 s, default 12 s. Fine and finer keep the penalty's figures (fine four
// times default's 55 s; finer fine's times 2.9, tools/bench/fe-mesh-convergence --finer): at the
// thick wall of the convergence test the exact contact is no faster there. A campaign's own
// tubes may differ by a factor of two either way: a stated model of the cost, not a bound.
double shell_fe_seconds_per_sample(ShellFeMesh mesh);

class ShellFeTurgorModulus final : public Evaluator {
 public:
  enum class Outputs { turgor_modulus, with_unstressed_thickness };
  // InputError (naming `location`) when the instrument or the options are invalid.
  ShellFeTurgorModulus(const Instrument& instrument, const ShellFeOptions& options, std::string_view location,
                       Outputs outputs = Outputs::turgor_modulus);
  std::string_view name() const override { return "shell_fe_turgor_modulus"; }
  std::vector<std::string> reads() const override { return reads_with_probe_radius({"k", "d", "d0", "h"}, instrument_); }
  std::vector<std::string> writes() const override;
  double seconds_per_sample() const override { return shell_fe_seconds_per_sample(options_.mesh); }
  void evaluate(SampleBlock& block) const override;

 private:
  Instrument instrument_;
  ShellFeOptions options_;
  Outputs outputs_;
};

}  // namespace growthuq
