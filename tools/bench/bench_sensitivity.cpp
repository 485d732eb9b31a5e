// What the first-order sensitivity indices cost a campaign (src/sensitivity/README.md): the
// rank estimator with its sectioning interval, as `growthuq run` computes it per line
// (line_sensitivity: one sort per input, one pass per input and output plus the sections'),
// timed on the samples.csv of a run. The columns with role input and output are named on the
// command line; rows of status ok only, grouped by line.
//   bench_sensitivity SAMPLES_CSV --inputs k_N_per_m,... --outputs p_MPa,... [--repetitions R]
// Prints per line the samples, the thread-CPU seconds (median of R) and the sum over lines.
#include <cstdio>
#include <cstdlib>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/sensitivity/rank_first_order.hpp"

using namespace growthuq;

namespace {

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return parts;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: bench_sensitivity SAMPLES_CSV --inputs A,B --outputs C,D [--repetitions R]\n");
    return 2;
  }
  const CsvTable table = read_csv(argv[1]);
  std::vector<std::string> inputs, outputs;
  std::size_t repetitions = 5;
  for (int a = 2; a + 1 < argc; a += 2) {
    const std::string flag = argv[a];
    if (flag == "--inputs") inputs = split(argv[a + 1]);
    if (flag == "--outputs") outputs = split(argv[a + 1]);
    if (flag == "--repetitions") repetitions = std::strtoul(argv[a + 1], nullptr, 10);
  }
  const std::size_t line = table.column_index("line"), status = table.column_index("status");
  // line -> column name -> values (status ok rows)
  std::map<std::string, std::map<std::string, std::vector<double>>> lines;
  for (const auto& row : table.rows) {
    if (row[status] != "ok") continue;
    for (const auto& name : inputs) lines[row[line]][name].push_back(std::stod(row[table.column_index(name)]));
    for (const auto& name : outputs) lines[row[line]][name].push_back(std::stod(row[table.column_index(name)]));
  }
  double total = 0;
  for (const auto& [name, columns] : lines) {
    std::vector<std::span<const double>> x, y;
    for (const auto& input : inputs) x.emplace_back(columns.at(input));
    for (const auto& output : outputs) y.emplace_back(columns.at(output));
    std::vector<double> seconds;
    for (std::size_t r = 0; r < repetitions; ++r) {
      const double start = bench::thread_cpu_seconds();
      const auto result = rank_first_order_indices(x, y, {.sections = 20, .key = r});
      seconds.push_back(bench::thread_cpu_seconds() - start);
      if (result.empty()) return 1;
    }
    const double median = bench::median(seconds);
    total += median;
    std::printf("line %s: %zu samples, %zu inputs x %zu outputs: %.3g s\n", name.c_str(), x.front().size(), x.size(),
                y.size(), median);
  }
  std::printf("all lines: %.3g s (thread CPU, median of %zu)\n", total, repetitions);
  return 0;
}
