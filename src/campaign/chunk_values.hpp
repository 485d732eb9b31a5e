// The numbers of one evaluated chunk as the pool carries them and the checkpoint keeps them:
// each computed output's column (SI), output after output, then each sample's status as a
// double. One packer (PreparedCampaign::evaluate_chunk) and one reader for every user.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "growthuq/evaluation/sample_block.hpp"
#include "growthuq/evaluation/sample_status.hpp"

namespace growthuq {

class ChunkValues {
 public:
  static constexpr std::size_t values_per_sample(std::size_t outputs) noexcept { return outputs + 1; }

  // The columns `outputs` of `block`, then its statuses.
  static std::vector<double> pack(const SampleBlock& block, const std::vector<std::string>& outputs);

  // A view of packed `values` with `outputs` outputs; std::logic_error unless their number is a
  // multiple of values_per_sample(outputs).
  ChunkValues(std::span<const double> values, std::size_t outputs);

  std::size_t samples() const noexcept { return samples_; }
  // Output o's values, SI.
  std::span<const double> output(std::size_t o) const { return values_.subspan(o * samples_, samples_); }
  SampleStatus status(std::size_t i) const {
    return static_cast<SampleStatus>(static_cast<int>(values_[outputs_ * samples_ + i]));
  }

 private:
  std::span<const double> values_;
  std::size_t outputs_;
  std::size_t samples_;
};

}  // namespace growthuq
