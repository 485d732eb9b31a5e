// Per-line analyses: input x output Spearman over the ok samples, PCA of inputs and outputs
// together, and the documented results for degenerate lines.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <span>
#include <vector>

#include "growthuq/core/units.hpp"
#include "growthuq/stats/line_analysis.hpp"
#include "growthuq/stats/pca.hpp"
#include "growthuq/stats/rank_correlation.hpp"

using namespace growthuq;

namespace {

constexpr double missing = std::numeric_limits<double>::quiet_NaN();

ResultColumn column_of(const char* quantity, const char* unit, bool is_input) {
  ResultColumn column;
  column.quantity = quantity;
  column.unit = &find_unit(unit, "test", "unit");
  column.is_input = is_input;
  return column;
}

// A line of n samples: inputs k, d; outputs p (increasing in k, decreasing in d, plus noise) and
// E; every 7th sample is flagged with NaN outputs and wild inputs that must not enter the ranks.
LineResult make_line(std::size_t n) {
  LineResult line;
  line.name = "wild_type";
  // Columns deliberately interleaved (output first) to check the inputs-then-outputs order.
  line.columns = {column_of("p", "MPa", false), column_of("k", "N/m", true), column_of("E", "MPa", false),
                  column_of("d", "um", true)};
  std::mt19937_64 engine(3);
  std::lognormal_distribution<double> k_law(std::log(2.87), 0.2), d_law(std::log(6.56), 0.13);
  std::normal_distribution<double> noise(0.0, 0.05);
  for (std::size_t i = 0; i < n; ++i) {
    const double k = k_law(engine), d = d_law(engine);
    const bool flagged = i % 7 == 3;
    line.columns[1].values.push_back(flagged ? 1e6 * static_cast<double>(i) : k);
    line.columns[3].values.push_back(flagged ? -1.0 : d);
    line.columns[0].values.push_back(flagged ? missing : k / d + noise(engine));
    line.columns[2].values.push_back(flagged ? missing : 100 * k * d);
    line.status.push_back(flagged ? SampleStatus::burst : SampleStatus::ok);
  }
  return line;
}

std::vector<double> ok_values(const LineResult& line, std::size_t column) {
  std::vector<double> values;
  for (std::size_t i = 0; i < line.status.size(); ++i) {
    if (line.status[i] == SampleStatus::ok) values.push_back(line.columns[column].values[i]);
  }
  return values;
}

}  // namespace

TEST_CASE("input x output Spearman equals spearman_matrix over the ok samples") {
  const LineResult line = make_line(700);
  const LineAnalysis analysis = analyze_line(line);
  CHECK(analysis.line == "wild_type");
  CHECK(analysis.samples_used == 600);
  CHECK(analysis.inputs == std::vector<std::string>{"k_N_per_m", "d_um"});
  CHECK(analysis.outputs == std::vector<std::string>{"p_MPa", "E_MPa"});
  CHECK(analysis.pca_names == std::vector<std::string>{"k_N_per_m", "d_um", "p_MPa", "E_MPa"});
  CHECK(analysis.notes.empty());

  const std::vector<double> k = ok_values(line, 1), d = ok_values(line, 3), p = ok_values(line, 0), e = ok_values(line, 2);
  const Eigen::MatrixXd reference = spearman_matrix({k, d, p, e});
  REQUIRE(analysis.input_output_spearman.rows() == 2);
  REQUIRE(analysis.input_output_spearman.cols() == 2);
  // Same ranks, same arithmetic: equal to rounding.
  CHECK(analysis.input_output_spearman(0, 0) == doctest::Approx(reference(0, 2)).epsilon(1e-14));
  CHECK(analysis.input_output_spearman(0, 1) == doctest::Approx(reference(0, 3)).epsilon(1e-14));
  CHECK(analysis.input_output_spearman(1, 0) == doctest::Approx(reference(1, 2)).epsilon(1e-14));
  CHECK(analysis.input_output_spearman(1, 1) == doctest::Approx(reference(1, 3)).epsilon(1e-14));
  // And the physics reads right: p rises with k and falls with d.
  CHECK(analysis.input_output_spearman(0, 0) > 0.5);
  CHECK(analysis.input_output_spearman(1, 0) < -0.2);

  // PCA over the same ok samples, columns in pca_names order.
  Eigen::MatrixXd data(600, 4);
  for (Eigen::Index i = 0; i < 600; ++i) data.row(i) << k[i], d[i], p[i], e[i];
  const PcaResult pca = correlation_pca(data);
  CHECK((analysis.explained_variance_ratio - pca.explained_variance_ratio).cwiseAbs().maxCoeff() < 1e-14);
  CHECK((analysis.loadings - pca.loadings).cwiseAbs().maxCoeff() < 1e-13);
  CHECK(analysis.explained_variance_ratio.sum() == doctest::Approx(1.0).epsilon(1e-14));

  const std::string text = format_line_analysis(analysis);
  CHECK(text.find("line 'wild_type': 600 samples with status ok") != std::string::npos);
  CHECK(text.find("p_MPa") != std::string::npos);
  CHECK(text.find("PC4") != std::string::npos);
  CHECK(text.find("nan") == std::string::npos);
}

TEST_CASE("a constant column is left out with a note, never a NaN correlation") {
  LineResult line = make_line(50);
  for (double& value : line.columns[2].values) value = std::isnan(value) ? value : 12.5;  // E constant over ok samples
  const LineAnalysis analysis = analyze_line(line);
  CHECK(analysis.outputs == std::vector<std::string>{"p_MPa"});
  CHECK(analysis.pca_names.size() == 3);
  REQUIRE(analysis.notes.size() == 1);
  CHECK(analysis.notes[0] == "E_MPa left out: constant over the samples used, so its correlations are undefined");
  CHECK(analysis.input_output_spearman.allFinite());
  CHECK(analysis.loadings.allFinite());
  CHECK(format_line_analysis(analysis).find("note: E_MPa left out") != std::string::npos);
}

TEST_CASE("a column whose spread overflows when squared is left out, not turned into NaN") {
  LineResult line = make_line(30);
  for (std::size_t i = 0; i < line.columns[2].values.size(); ++i) {
    if (!std::isnan(line.columns[2].values[i])) line.columns[2].values[i] = 1e200 * static_cast<double>(i % 5 + 1);
  }
  const LineAnalysis analysis = analyze_line(line);
  REQUIRE(analysis.notes.size() == 1);
  CHECK(analysis.notes[0] == "E_MPa left out: its spread is beyond double precision range for standardizing");
  CHECK(analysis.loadings.allFinite());
  CHECK(analysis.explained_variance_ratio.size() == 3);
}

TEST_CASE("fewer than 3 ok samples: no analysis, a note, empty matrices") {
  LineResult line = make_line(10);
  for (std::size_t i = 2; i < line.status.size(); ++i) line.status[i] = SampleStatus::burst;
  const LineAnalysis analysis = analyze_line(line);
  CHECK(analysis.samples_used == 2);
  CHECK(analysis.inputs.empty());
  CHECK(analysis.input_output_spearman.size() == 0);
  CHECK(analysis.explained_variance_ratio.size() == 0);
  CHECK(analysis.loadings.size() == 0);
  REQUIRE(analysis.notes.size() == 1);
  CHECK(analysis.notes[0].find("only 2 samples have status ok") == 0);
  const std::string text = format_line_analysis(analysis);
  CHECK(text == "line 'wild_type': 2 samples with status ok\n  note: " + analysis.notes[0] + "\n");
}

TEST_CASE("a line with inputs only still gets its PCA") {
  LineResult line = make_line(40);
  line.columns.erase(line.columns.begin() + 2);
  line.columns.erase(line.columns.begin());
  const LineAnalysis analysis = analyze_line(line);
  CHECK(analysis.outputs.empty());
  CHECK(analysis.input_output_spearman.rows() == 2);
  CHECK(analysis.input_output_spearman.cols() == 0);
  CHECK(analysis.explained_variance_ratio.size() == 2);
}
