// How a line's design, made whole by one process, reaches every other: its columns as they are
// (ranks, values, the strictly-increasing flags), then a DesignOutline message with what the
// coordinator's report needs of the rest (the target Spearman matrix and the warnings).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "growthuq/pool/pool.hpp"
#include "growthuq/sampling/line_design.hpp"

namespace growthuq {

// The part of a LineDesign past its columns that is used after the design: the target
// Spearman matrix (empty when no correlation was requested) and the warnings.
struct DesignOutline {
  Eigen::MatrixXd target_spearman;
  std::vector<std::string> warnings;

  // Bytes: m (uint64), the m x m matrix's doubles (column by column), then each warning's length
  // (uint64) and text. decode(encode()) gives the same matrix bits and warnings; std::logic_error
  // for a message cut short.
  std::string encode() const;
  static DesignOutline decode(std::string_view message);
};

// The outline of `design` (its target's target_spearman, its warnings).
DesignOutline outline_of(const LineDesign& design);

// Every process calls it: on process `designer`, `design` is the line's design and is sent; on
// the others it becomes the same columns, named `names`, with the outline's target and
// warnings (the rest of the design is not used past the design step). `samples` per column.
void share_design(LineDesign& design, const std::vector<std::string>& names, std::size_t samples, int designer,
                  Pool& pool);

}  // namespace growthuq
