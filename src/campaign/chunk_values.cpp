#include "campaign/chunk_values.hpp"

#include <stdexcept>

namespace growthuq {

std::vector<double> ChunkValues::pack(const SampleBlock& block, const std::vector<std::string>& outputs) {
  std::vector<double> values;
  values.reserve(values_per_sample(outputs.size()) * block.size());
  for (const std::string& output : outputs) {
    const std::span<const double> column = block.column(output);
    values.insert(values.end(), column.begin(), column.end());
  }
  for (const SampleStatus status : block.status()) values.push_back(static_cast<double>(status));
  return values;
}

ChunkValues::ChunkValues(std::span<const double> values, std::size_t outputs)
    : values_(values), outputs_(outputs), samples_(values.size() / values_per_sample(outputs)) {
  if (values.size() != values_per_sample(outputs) * samples_) throw std::logic_error("chunk of unexpected size");
}

}  // namespace growthuq
