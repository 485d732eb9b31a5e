// The probe radius as an uncertain input: where a campaign gives a law of rho rather than one
// value (the study's probe radius is not known: campaigns/README.md, "An unknown probe radius"),
// each sample carries its own rho in the block's column "rho" [m], and the models that use rho
// read it through these, so a model's declaration (Evaluator::reads) and its loop agree.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "growthuq/evaluation/sample_block.hpp"
#include "growthuq/mechanics/instrument.hpp"

namespace growthuq {

inline constexpr std::string_view probe_radius_column = "rho";

// `reads` and, when `instrument` takes rho per sample, the probe radius column.
std::vector<std::string> reads_with_probe_radius(std::vector<std::string> reads, const Instrument& instrument);

// The instrument of each sample of a block: `instrument` itself, or with the sample's rho.
class SampleInstruments {
 public:
  // Reads the block's rho column when `instrument` takes rho per sample (std::out_of_range from
  // SampleBlock::column when the block lacks it: the planner gives every model its reads).
  SampleInstruments(const SampleBlock& block, const Instrument& instrument);
  Instrument operator[](std::size_t sample) const;

 private:
  Instrument instrument_;
  std::span<const double> rho_;
};

}  // namespace growthuq
