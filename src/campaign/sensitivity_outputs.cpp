#include "campaign/sensitivity_outputs.hpp"

#include <filesystem>

#include "growthuq/core/numbers.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/io/output_file.hpp"

namespace growthuq {
namespace {

const std::vector<std::string> columns{"line",    "output",  "input",        "method",  "index",
                                       "ci_low", "ci_high", "samples_used", "sections"};

constexpr const char* method_name = "first_order_rank";

constexpr const char* method_text =
    "first_order_rank: full first-order index S = Var(E[output | input]) / Var(output) from the campaign's samples with "
    "status ok, rank (nearest neighbour in rank) estimator (Chatterjee 2021; Gamboa et al. 2022); ci_low/ci_high: 95 % "
    "interval by sectioning into `sections` random parts (Asmussen and Glynn 2007); src/sensitivity/README.md";

// Each (line, output, input) once, in the order of the table.
template <typename Row>
void for_each_row(const std::vector<LineSensitivity>& lines, Row row) {
  for (const LineSensitivity& line : lines) {
    for (std::size_t o = 0; o < line.outputs.size(); ++o) {
      for (std::size_t i = 0; i < line.inputs.size() && !line.first_order.empty(); ++i) row(line, o, i);
    }
  }
}

}  // namespace

std::string sensitivity_csv_text(const std::vector<LineSensitivity>& lines) {
  CsvWriter writer(columns);
  for_each_row(lines, [&](const LineSensitivity& line, std::size_t o, std::size_t i) {
    const RankIndexEstimate& e = line.first_order[i][o];
    writer.add_row({line.line, line.outputs[o], line.inputs[i], method_name, format_double(e.index), format_double(e.low),
                    format_double(e.high), std::to_string(line.samples_used), std::to_string(line.sections)});
  });
  return writer.text();
}

void write_sensitivity(const std::vector<LineSensitivity>& lines, ResultsH5Writer* h5, const std::string& directory) {
  write_file_atomically((std::filesystem::path(directory) / sensitivity_csv_name).string(), sensitivity_csv_text(lines),
                        Overwrite::allow);
  if (h5 == nullptr) return;
  ExtraColumn line{"line"}, output{"output"}, input{"input"}, method{"method"};
  ExtraColumn index{.name = "index", .unit = "1"}, low{.name = "ci_low", .unit = "1"}, high{.name = "ci_high", .unit = "1"};
  ExtraColumn used{.name = "samples_used", .unit = "1"}, sections{.name = "sections", .unit = "1"};
  for_each_row(lines, [&](const LineSensitivity& l, std::size_t o, std::size_t i) {
    const RankIndexEstimate& e = l.first_order[i][o];
    line.text.push_back(l.line);
    output.text.push_back(l.outputs[o]);
    input.text.push_back(l.inputs[i]);
    method.text.push_back(method_name);
    index.real.push_back(e.index);
    low.real.push_back(e.low);
    high.real.push_back(e.high);
    used.integer.push_back(static_cast<std::int64_t>(l.samples_used));
    sections.integer.push_back(static_cast<std::int64_t>(l.sections));
  });
  if (line.text.empty()) return;
  h5->write_table("sensitivity", {line, output, input, method, index, low, high, used, sections});
  h5->write_attribute("sensitivity", "method", method_text);
}

}  // namespace growthuq
