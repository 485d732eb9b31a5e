#include "growthuq/fe/shell_fe_evaluator.hpp"

#include <utility>

namespace growthuq {

double shell_fe_seconds_per_sample(ShellFeMesh mesh) {
  switch (mesh) {
    case ShellFeMesh::coarse: return 3.6;
    case ShellFeMesh::standard: return 12.0;
    case ShellFeMesh::fine: return 220.0;
    case ShellFeMesh::finer: return 640.0;
  }
  return 12.0;
}

ShellFeTurgorModulus::ShellFeTurgorModulus(const Instrument& instrument, const ShellFeOptions& options,
                                           std::string_view location, Outputs outputs)
    : instrument_(instrument), options_(options), outputs_(outputs) {
  validate(instrument_, location);
  options_.validate(location);
}

std::vector<std::string> ShellFeTurgorModulus::writes() const {
  if (outputs_ == Outputs::with_unstressed_thickness) return {"p", "E", "h0"};
  return {"p", "E"};
}

void ShellFeTurgorModulus::evaluate(SampleBlock& block) const {
  const std::span<const double> k = std::as_const(block).column("k");
  const std::span<const double> d = std::as_const(block).column("d");
  const std::span<const double> d0 = std::as_const(block).column("d0");
  const std::span<const double> h = std::as_const(block).column("h");
  const SampleInstruments instruments(block, instrument_);
  const std::span<double> p = block.add_column("p");
  const std::span<double> E = block.add_column("E");
  const std::span<double> h0 =
      outputs_ == Outputs::with_unstressed_thickness ? block.add_column("h0") : std::span<double>();
  const std::span<SampleStatus> status = block.status();
  for (std::size_t i = 0; i < block.size(); ++i) {
    if (status[i] != SampleStatus::ok) continue;
    const ShellFeInverse inverse = invert_indentation({k[i], h[i], d[i], d0[i]}, instruments[i], options_);
    if (inverse.status != SampleStatus::ok) {
      status[i] = inverse.status;
      continue;
    }
    p[i] = inverse.pressure;
    E[i] = inverse.young;
    if (!h0.empty()) h0[i] = inverse.unstressed_thickness;
  }
}

}  // namespace growthuq
