#include "growthuq/mechanics/probe_radius_column.hpp"

#include <utility>

namespace growthuq {

std::vector<std::string> reads_with_probe_radius(std::vector<std::string> reads, const Instrument& instrument) {
  if (instrument.probe_radius_per_sample) reads.emplace_back(probe_radius_column);
  return reads;
}

SampleInstruments::SampleInstruments(const SampleBlock& block, const Instrument& instrument) : instrument_(instrument) {
  if (instrument.probe_radius_per_sample) rho_ = block.column(probe_radius_column);
}

Instrument SampleInstruments::operator[](std::size_t sample) const {
  Instrument at = instrument_;
  if (!rho_.empty()) at.probe_radius_m = rho_[sample];
  return at;
}

}  // namespace growthuq
