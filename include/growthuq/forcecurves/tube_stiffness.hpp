// A tube's stiffness from its repeated curves (Eq. (C10), src/forcecurves/README.md): the mean
// over its ok curves, their spread, and an uncertainty of the mean.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "growthuq/forcecurves/curve_processing.hpp"

namespace growthuq {

struct TubeStiffness {
  std::string tube;
  std::size_t curves = 0;            // every curve of the tube
  std::size_t ok = 0;                // the ones with status ok (the others are not used)
  std::string statuses;              // "ok 4, slip 1": how the curves were rated
  double stiffness = 0.0;            // mean k of the ok curves (N/m)
  double spread = 0.0;               // sd of the ok curves' k (n - 1), 0 for one curve
  double uncertainty_spread = 0.0;   // spread / sqrt(ok)
  double uncertainty_measurement = 0.0;  // sqrt(sum u_i^2) / ok, u_i the curves' uncertainty
  double uncertainty = 0.0;          // the larger of the two
};

// One entry per tube, in order of first appearance; a tube without ok curves has ok = 0 and
// zero numbers.
std::vector<TubeStiffness> tube_stiffness(const std::vector<CurveResult>& curves);

}  // namespace growthuq
