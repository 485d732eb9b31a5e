// Keeping the worst of an error over rows, shared by the per-fidelity verdict (tradeoff.cpp) and
// the choice against the finite-element reference (tradeoff_choice.cpp).
#pragma once

#include <cmath>
#include <string>

#include "growthuq/campaign/tradeoff.hpp"

namespace growthuq {

// NaN (undefined) ranks above every number so that the worst case is never hidden.
inline bool worse_error(double candidate, double current) {
  if (std::isnan(current)) return false;
  if (std::isnan(candidate)) return true;
  return candidate > current;
}

// Replaces `worst` by (value, line, quantity) when it is the first value seen or a worse one.
inline void keep_worst_error(TradeoffWorst& worst, double value, const std::string& line, const std::string& quantity,
                             bool first) {
  if (first || worse_error(value, worst.value)) worst = {value, line, quantity};
}

}  // namespace growthuq
