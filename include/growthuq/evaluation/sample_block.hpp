// A batch of samples held as contiguous columns (struct of arrays), values in SI units, with a
// status per sample. Evaluators read and add whole columns; nothing is done sample by sample
// through virtual calls.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "growthuq/evaluation/sample_status.hpp"

namespace growthuq {

class SampleBlock {
 public:
  explicit SampleBlock(std::size_t size);

  std::size_t size() const noexcept { return size_; }

  bool has(std::string_view quantity) const noexcept;

  // The values of `quantity` (SI); std::out_of_range naming it when absent (a planning bug).
  std::span<const double> column(std::string_view quantity) const;
  std::span<double> column(std::string_view quantity);

  // A new column of `quantity`, or the existing one, filled with NaN for every sample.
  std::span<double> add_column(std::string_view quantity);

  // Copies `values` (size() of them) into the column `quantity`, creating it if needed.
  void set_column(std::string_view quantity, std::span<const double> values);

  std::span<SampleStatus> status() noexcept { return status_; }
  std::span<const SampleStatus> status() const noexcept { return status_; }

  // Sets status of sample i to `status` unless it already carries a non-ok one.
  void flag(std::size_t i, SampleStatus status) noexcept {
    if (status_[i] == SampleStatus::ok) status_[i] = status;
  }

  // Column names in the order they were added.
  std::vector<std::string> quantities() const;

 private:
  std::size_t size_;
  std::vector<std::pair<std::string, std::vector<double>>> columns_;
  std::vector<SampleStatus> status_;
};

}  // namespace growthuq
