#include "stats/cross_products.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/avx2_clone.hpp"

namespace growthuq::detail {

namespace {

// The sums over rows first, first + 1, ... of the block loaded by load(a, first, count, out).
template <class Load>
Eigen::MatrixXd block_cross_products(std::size_t m, std::size_t n, const Load& load) {
  constexpr std::size_t lanes = 4;
  constexpr std::size_t block = 1024;
  std::vector<double> sums(m * m * lanes, 0.0);
  std::vector<double> loaded(m * block);
  for (std::size_t first = 0; first < n; first += block) {
    const std::size_t count = std::min(block, n - first);
    for (std::size_t a = 0; a < m; ++a) load(a, first, count, loaded.data() + a * block);
    for (std::size_t a = 0; a < m; ++a) {
      for (std::size_t b = a; b < m; ++b) {
        const double* x = loaded.data() + a * block;
        const double* y = loaded.data() + b * block;
        double* sum = sums.data() + (a * m + b) * lanes;
        double lane[lanes] = {sum[0], sum[1], sum[2], sum[3]};
        std::size_t i = 0;
        for (; i + lanes <= count; i += lanes) {
          for (std::size_t l = 0; l < lanes; ++l) lane[l] += x[i + l] * y[i + l];
        }
        for (; i < count; ++i) lane[0] += x[i] * y[i];
        for (std::size_t l = 0; l < lanes; ++l) sum[l] = lane[l];
      }
    }
  }
  Eigen::MatrixXd products(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t b = a; b < m; ++b) {
      const double* sum = sums.data() + (a * m + b) * lanes;
      const double total = (sum[0] + sum[1]) + (sum[2] + sum[3]);
      products(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) = total;
      products(static_cast<Eigen::Index>(b), static_cast<Eigen::Index>(a)) = total;
    }
  }
  return products;
}

void check_shift(std::span<const double> shift, std::size_t m) {
  if (!shift.empty() && shift.size() != m) throw std::invalid_argument("cross_products: one shift per column");
}

}  // namespace

GROWTHUQ_AVX2_CLONE
Eigen::MatrixXd cross_products(const std::vector<const double*>& columns, std::size_t n, std::span<const double> shift) {
  check_shift(shift, columns.size());
  return block_cross_products(columns.size(), n, [&](std::size_t a, std::size_t first, std::size_t count, double* out) {
    const double* x = columns[a] + first;
    const double s = shift.empty() ? 0.0 : shift[a];
    for (std::size_t i = 0; i < count; ++i) out[i] = x[i] - s;
  });
}

GROWTHUQ_AVX2_CLONE
Eigen::MatrixXd cross_products(const std::vector<const std::uint32_t*>& columns, std::size_t n,
                               std::span<const double> shift) {
  check_shift(shift, columns.size());
  return block_cross_products(columns.size(), n, [&](std::size_t a, std::size_t first, std::size_t count, double* out) {
    const std::uint32_t* x = columns[a] + first;
    const double s = shift.empty() ? 0.0 : shift[a];
    for (std::size_t i = 0; i < count; ++i) out[i] = static_cast<double>(x[i]) - s;
  });
}

GROWTHUQ_AVX2_CLONE
Eigen::MatrixXd cross_products(const std::vector<const double*>& columns, std::span<const std::uint32_t> rows,
                               std::span<const double> shift) {
  check_shift(shift, columns.size());
  return block_cross_products(columns.size(), rows.size(), [&](std::size_t a, std::size_t first, std::size_t count, double* out) {
    const double* x = columns[a];
    const std::uint32_t* row = rows.data() + first;
    const double s = shift.empty() ? 0.0 : shift[a];
    for (std::size_t i = 0; i < count; ++i) out[i] = x[row[i]] - s;
  });
}

}  // namespace growthuq::detail
