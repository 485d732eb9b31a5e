#include "campaign/sensitivity_outputs.hpp"

#include <filesystem>
#include <tuple>

#include "growthuq/core/numbers.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/io/output_file.hpp"

namespace growthuq {
namespace {

const std::vector<std::string> columns{"line",    "output",  "input",        "method",  "index",
                                       "ci_low", "ci_high", "samples_used", "sections"};

constexpr const char* method_text =
    "first_order_rank: full first-order index S = Var(E[output | input]) / Var(output) from the campaign's samples with "
    "status ok, rank (nearest neighbour in rank) estimator (Chatterjee 2021; Gamboa et al. 2022); ci_low/ci_high: 95 % "
    "interval by sectioning into `sections` random parts (Asmussen and Glynn 2007). shapley_share: Shapley effect over "
    "Var(output) (Song, Nelson and Staum 2016), summing to 1 over the inputs, from samples_used new model runs, inputs "
    "joined by a Gaussian copula of the line's rank correlation. sobol_first, sobol_total: Sobol' first-order (Saltelli "
    "et al. 2010) and total (Jansen 1999) indices of a line with independent inputs, from samples_used model runs; "
    "src/sensitivity/README.md";

struct Row {
  std::string line, output, input, method;
  double index, low, high;
  std::size_t used, sections;
};

// Every row of the table, in its order.
std::vector<Row> rows_of(const std::vector<LineSensitivity>& lines, const std::vector<LineShapley>& shapley,
                         const std::vector<LineSobol>& sobol) {
  std::vector<Row> rows;
  for (const LineSensitivity& line : lines) {
    for (std::size_t o = 0; o < line.outputs.size(); ++o) {
      for (std::size_t i = 0; i < line.inputs.size() && !line.first_order.empty(); ++i) {
        const RankIndexEstimate& e = line.first_order[i][o];
        rows.push_back({line.line, line.outputs[o], line.inputs[i], "first_order_rank", e.index, e.low, e.high,
                        line.samples_used, line.sections});
      }
    }
    for (const LineShapley& s : shapley) {
      if (s.line != line.line || !s.computed) continue;
      for (std::size_t o = 0; o < s.outputs.size(); ++o) {
        for (std::size_t i = 0; i < s.inputs.size(); ++i) {
          const auto r = static_cast<Eigen::Index>(i), c = static_cast<Eigen::Index>(o);
          rows.push_back({s.line, s.outputs[o], s.inputs[i], "shapley_share", s.effects.share(r, c), s.effects.share_low(r, c),
                          s.effects.share_high(r, c), s.effects.model_runs,
                          static_cast<std::size_t>(ShapleySettings{}.sections)});
        }
      }
    }
    for (const LineSobol& s : sobol) {
      if (s.line != line.line || !s.computed) continue;
      const SobolIndices& x = s.indices;
      for (const auto& [method, value, low, high] :
           {std::tuple{"sobol_first", &x.first, &x.first_low, &x.first_high}, std::tuple{"sobol_total", &x.total, &x.total_low, &x.total_high}}) {
        for (std::size_t o = 0; o < s.outputs.size(); ++o) {
          for (std::size_t i = 0; i < s.inputs.size(); ++i) {
            const auto r = static_cast<Eigen::Index>(i), c = static_cast<Eigen::Index>(o);
            rows.push_back({s.line, s.outputs[o], s.inputs[i], method, (*value)(r, c), (*low)(r, c), (*high)(r, c), x.model_runs,
                            static_cast<std::size_t>(SobolSettings{}.sections)});
          }
        }
      }
    }
  }
  return rows;
}

}  // namespace

std::string sensitivity_csv_text(const std::vector<LineSensitivity>& lines, const std::vector<LineShapley>& shapley,
                                 const std::vector<LineSobol>& sobol) {
  CsvWriter writer(columns);
  for (const Row& row : rows_of(lines, shapley, sobol)) {
    writer.add_row({row.line, row.output, row.input, row.method, format_double(row.index), format_double(row.low),
                    format_double(row.high), std::to_string(row.used), std::to_string(row.sections)});
  }
  return writer.text();
}

void write_sensitivity(const std::vector<LineSensitivity>& lines, const std::vector<LineShapley>& shapley,
                       const std::vector<LineSobol>& sobol, ResultsH5Writer* h5, const std::string& directory) {
  write_file_atomically((std::filesystem::path(directory) / sensitivity_csv_name).string(),
                        sensitivity_csv_text(lines, shapley, sobol), Overwrite::allow);
  if (h5 == nullptr) return;
  ExtraColumn line{"line"}, output{"output"}, input{"input"}, method{"method"};
  ExtraColumn index{.name = "index", .unit = "1"}, low{.name = "ci_low", .unit = "1"}, high{.name = "ci_high", .unit = "1"};
  ExtraColumn used{.name = "samples_used", .unit = "1"}, sections{.name = "sections", .unit = "1"};
  for (const Row& row : rows_of(lines, shapley, sobol)) {
    line.text.push_back(row.line);
    output.text.push_back(row.output);
    input.text.push_back(row.input);
    method.text.push_back(row.method);
    index.real.push_back(row.index);
    low.real.push_back(row.low);
    high.real.push_back(row.high);
    used.integer.push_back(static_cast<std::int64_t>(row.used));
    sections.integer.push_back(static_cast<std::int64_t>(row.sections));
  }
  if (line.text.empty()) return;
  h5->write_table("sensitivity", {line, output, input, method, index, low, high, used, sections});
  h5->write_attribute("sensitivity", "method", method_text);
}

}  // namespace growthuq
