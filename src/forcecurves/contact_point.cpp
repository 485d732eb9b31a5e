#include "contact_point.hpp"

#include <vector>

namespace growthuq::detail {

std::size_t deviation_contact(const double* y, std::size_t peak, double threshold, double rounding) {
  std::size_t j = peak;
  while (j > 0 && y[j] > threshold) --j;
  while (j > 0 && y[j] > rounding) --j;
  return j;
}

// For a candidate j the best slope of the hinge h_i = (z_i - z_j)+ is m = sum h y / sum h^2 and
// the residual sum is sum y^2 - (sum h y)^2 / sum h^2; so the best j maximizes
// (sum h y)^2 / sum h^2 with sum h y > 0. Suffix sums over i > j make every candidate O(1):
//   sum h y = S_zy - z_j S_y,   sum h^2 = S_zz - 2 z_j S_z + c z_j^2.
// Positions are taken relative to z[peak], so the sums stay of the size of the differences.
std::size_t piecewise_contact(const double* z, const double* y, std::size_t peak) {
  const double origin = z[peak];
  double s_z = 0.0, s_zz = 0.0, s_y = 0.0, s_zy = 0.0, count = 0.0;
  std::size_t best = 0;
  double best_score = -1.0;
  for (std::size_t j = peak; j-- > 0;) {
    const double u = z[j + 1] - origin;  // sample j + 1 joins the part beyond candidate j
    s_z += u;
    s_zz += u * u;
    s_y += y[j + 1];
    s_zy += u * y[j + 1];
    count += 1.0;
    const double zj = z[j] - origin;
    const double hy = s_zy - zj * s_y;
    const double hh = s_zz - 2.0 * zj * s_z + count * zj * zj;
    if (hy <= 0.0 || hh <= 0.0) continue;
    const double score = hy * hy / hh;
    if (score > best_score) {
      best_score = score;
      best = j;
    }
  }
  return best;
}

}  // namespace growthuq::detail
