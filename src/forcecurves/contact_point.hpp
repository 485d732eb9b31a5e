// The two contact-point methods of Eqs. (C3) and (C4), src/forcecurves/README.md, on the
// baseline-corrected force y of the approach.
#pragma once

#include <cstddef>

namespace growthuq::detail {

// Deviation from the baseline (C3): from the force maximum at `peak` back to the last sample at
// or below `threshold`, then on back to the last sample at or below the baseline (zero, give or
// take `rounding`, the size of rounding errors of the corrected force). Needs y[peak] > threshold.
std::size_t deviation_contact(const double* y, std::size_t peak, double threshold, double rounding);

// Piecewise-linear fit (C4): the sample j in [0, peak) whose hinge y = m (z - z_j)+ fits y over
// [0, peak] with the least squares.
std::size_t piecewise_contact(const double* z, const double* y, std::size_t peak);

}  // namespace growthuq::detail
