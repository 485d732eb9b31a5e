// The sensitivity indices of a campaign's lines (sensitivity/line_sensitivity.hpp) as files:
// sensitivity.csv, one row per line, output and input, and the same table in results.h5.
//
// results.h5:
//   /sensitivity   one row per line, output and input: the columns of sensitivity.csv
//                  (attribute `method`: what the numbers are)
#pragma once

#include <string>
#include <vector>

#include "campaign/line_shapley.hpp"
#include "campaign/line_sobol.hpp"
#include "growthuq/io/results_h5.hpp"
#include "growthuq/sensitivity/line_sensitivity.hpp"

namespace growthuq {

inline constexpr const char* sensitivity_csv_name = "sensitivity.csv";

// Columns: line, output, input, method, index, ci_low, ci_high, samples_used, sections. Per line
// (in the order given) the first-order rows (method first_order_rank; samples_used: the samples
// with status ok), then, where computed, the Shapley rows (method shapley_share: Sh_i / Var;
// samples_used: the model runs), then the Sobol rows (methods sobol_first and sobol_total);
// outputs and inputs in the line's order.
std::string sensitivity_csv_text(const std::vector<LineSensitivity>& lines, const std::vector<LineShapley>& shapley = {},
                                 const std::vector<LineSobol>& sobol = {});

// Writes sensitivity.csv to `directory` and the table to `h5` (may be null).
void write_sensitivity(const std::vector<LineSensitivity>& lines, const std::vector<LineShapley>& shapley,
                       const std::vector<LineSobol>& sobol, ResultsH5Writer* h5, const std::string& directory);

}  // namespace growthuq
