// Sums of products of columns, sum_i (x_a[i] - shift_a)(x_b[i] - shift_b) for every pair: the
// Gram matrix behind a correlation matrix, from the columns where they are (no n x m copy).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace growthuq::detail {

// columns[a] points to n values; `shift` is empty (no shift) or has one entry per column. The
// result is the full symmetric m x m matrix. A block of rows at a time, so the block's columns
// stay in cache while every pair uses them; each sum in 4 lanes added in a fixed order, so the
// result does not depend on anything but the data.
Eigen::MatrixXd cross_products(const std::vector<const double*>& columns, std::size_t n,
                               std::span<const double> shift = {});

// The same for columns of whole numbers (ranks).
Eigen::MatrixXd cross_products(const std::vector<const std::uint32_t*>& columns, std::size_t n,
                               std::span<const double> shift = {});

// The same over rows rows[0], rows[1], ... (n = rows.size()) of the columns.
Eigen::MatrixXd cross_products(const std::vector<const double*>& columns, std::span<const std::uint32_t> rows,
                               std::span<const double> shift = {});

}  // namespace growthuq::detail
