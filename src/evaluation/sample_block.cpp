#include "growthuq/evaluation/sample_block.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace growthuq {

SampleBlock::SampleBlock(std::size_t size) : size_(size), status_(size, SampleStatus::ok) {}

bool SampleBlock::has(std::string_view quantity) const noexcept {
  return std::any_of(columns_.begin(), columns_.end(),
                     [&](const auto& column) { return column.first == quantity; });
}

std::span<const double> SampleBlock::column(std::string_view quantity) const {
  for (const auto& [name, values] : columns_) {
    if (name == quantity) return values;
  }
  throw std::out_of_range("SampleBlock has no column '" + std::string(quantity) + "'");
}

std::span<double> SampleBlock::column(std::string_view quantity) {
  for (auto& [name, values] : columns_) {
    if (name == quantity) return values;
  }
  throw std::out_of_range("SampleBlock has no column '" + std::string(quantity) + "'");
}

std::span<double> SampleBlock::add_column(std::string_view quantity) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (auto& [name, values] : columns_) {
    if (name == quantity) {
      std::fill(values.begin(), values.end(), nan);
      return values;
    }
  }
  columns_.emplace_back(std::string(quantity), std::vector<double>(size_, nan));
  return columns_.back().second;
}

void SampleBlock::set_column(std::string_view quantity, std::span<const double> values) {
  if (values.size() != size_) {
    throw std::invalid_argument("SampleBlock::set_column: " + std::to_string(values.size()) +
                                " values for a block of " + std::to_string(size_));
  }
  std::span<double> target = add_column(quantity);
  std::copy(values.begin(), values.end(), target.begin());
}

std::vector<std::string> SampleBlock::quantities() const {
  std::vector<std::string> names;
  for (const auto& column : columns_) names.push_back(column.first);
  return names;
}

}  // namespace growthuq
