// `growthuq run` writes the first-order indices of every line (sensitivity.csv, results.h5's
// /sensitivity, the report's table), and they agree with a second, independent estimator of
// Var(E[Y | X_i]) / Var(Y) computed here from samples.csv: the between-bin variance of Y over
// equal-count bins of X_i, corrected for the bins' own noise.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "growthuq/io/csv.hpp"
#include "growthuq/sensitivity/shapley.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;

namespace {

// Var(E[Y | X]) / Var(Y) by bins: the samples sorted by x in B bins of (nearly) equal count m;
// the between-bin sum (1/n) sum_b m_b (ybar_b - ybar)^2 overestimates Var(E[Y | bin]) by the
// bins' sampling noise, about (B / n) times the mean within-bin variance, which is removed.
// With E[Y | X] smooth, 40 bins of 100 leave a discretization bias well below the tolerance.
double binned_index(const std::vector<double>& x, const std::vector<double>& y, std::size_t bins) {
  const std::size_t n = x.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  const double mean = std::accumulate(y.begin(), y.end(), 0.0) / static_cast<double>(n);
  double total = 0, between = 0, within = 0;
  for (const double v : y) total += (v - mean) * (v - mean);
  for (std::size_t b = 0; b < bins; ++b) {
    const std::size_t begin = b * n / bins, end = (b + 1) * n / bins;
    double bin_mean = 0;
    for (std::size_t k = begin; k < end; ++k) bin_mean += y[order[k]];
    bin_mean /= static_cast<double>(end - begin);
    double squares = 0;
    for (std::size_t k = begin; k < end; ++k) squares += (y[order[k]] - bin_mean) * (y[order[k]] - bin_mean);
    between += static_cast<double>(end - begin) * (bin_mean - mean) * (bin_mean - mean);
    within += squares / static_cast<double>(end - begin - 1) / static_cast<double>(bins);
  }
  return (between / static_cast<double>(n) - static_cast<double>(bins) / static_cast<double>(n) * within) /
         (total / static_cast<double>(n));
}

}  // namespace

TEST_CASE("campaign sensitivity: sensitivity.csv, results.h5 and the report, checked against binned estimates") {
  ScratchDirectory scratch("campaign_sensitivity");
  const std::string source = GROWTHUQ_SOURCE_DIR;
  // One line of the shipped pme48 law, correlated by the physics, 4000 samples; turgor and modulus.
  spit(scratch.root / "sensitivity.ini", "[campaign]\nname = sensitivity\nseed = 28\nsamples = 4000\noutputs = p, E\n"
                                         "output_dir = out\nformats = csv, hdf5\n\n[instrument]\nprobe_radius_um = 0.25\n"
                                         "poisson_ratio = 0.2\n\n[physics_correlation]\nsamples = 2000\n\n[line pme48]\n"
                                         "distributions = " + source + "/distributions/pme48.ini\nrank_correlation = physics\n");
  const CliOutcome run = run_cli("run sensitivity.ini --quiet", scratch.root);
  REQUIRE_MESSAGE(run.exit_code == 0, run.err);
  CHECK(run.out.find("First-order sensitivity S = Var(E[output | input]) / Var(output)") != std::string::npos);

  const CsvTable table = read_csv((scratch.root / "out" / "sensitivity.csv").string());
  CHECK(table.header == std::vector<std::string>{"line", "output", "input", "method", "index", "ci_low", "ci_high",
                                                  "samples_used", "sections"});
  const CsvTable samples = read_csv((scratch.root / "out" / "samples.csv").string());
  // status ok rows only (the indices use those, Eq. (T3) of src/stats/README.md).
  const std::size_t status = samples.column_index("status");
  std::map<std::string, std::vector<double>> columns;
  for (std::size_t r = 0; r < samples.rows.size(); ++r) {
    if (samples.rows[r][status] != "ok") continue;
    for (std::size_t c = 0; c < samples.header.size(); ++c) {
      if (c != status && c != 0) columns[samples.header[c]].push_back(std::stod(samples.rows[r][c]));
    }
  }
  std::size_t checked = 0;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const auto& row = table.rows[r];
    CAPTURE(row[1]);
    CAPTURE(row[2]);
    CHECK(row[0] == "pme48");
    CHECK(row[3] == "first_order_rank");
    const double index = std::stod(row[4]), low = std::stod(row[5]), high = std::stod(row[6]);
    CHECK(low < index);
    CHECK(index < high);
    CHECK(std::stoul(row[7]) == columns.at(row[1]).size());
    CHECK(row[8] == "20");
    const double binned = binned_index(columns.at(row[2]), columns.at(row[1]), 40);
    MESSAGE(row[1] << " on " << row[2] << ": rank " << index << " [" << low << ", " << high << "], binned " << binned);
    // Two estimators of one number from one sample of 4000: each has a standard error of about
    // 0.01 here (the interval's half width / 2); 0.04 is about 3 of their difference's.
    CHECK(std::abs(index - binned) < 0.04);
    ++checked;
  }
  CHECK(checked == 2 * 4);  // p and E, each on k, h, d and d0 (pme48.ini)
}

TEST_CASE("campaign sensitivity: Shapley shares of turgor against the log-linear closed form") {
  // Turgor of the closed form is nearly a power law of k, d and d0 (the hoop and Arnoldi
  // relations, src/mechanics/README.md), and the line's laws are lognormal: ln k, ln d, ln d0 are
  // then jointly Gaussian under the Gaussian copula (the normal scores are the standardized logs),
  // so the Shapley shares of ln p are those of a linear Gaussian model (Owen and Prieur 2017),
  // with the exponents fitted by least squares on the campaign's own samples and the covariance
  // of the logs estimated from them. The run's shares are of p itself: the two differ by the
  // curvature of exp over p's spread (IQR / median about 0.3) and by what the power law misses:
  // measured 0.043 (k), 0.003 (d), 0.046 (d0), against interval half widths of 0.01-0.02, so
  // this is a physical check of the order of the shares, with a tolerance of 0.06.
  ScratchDirectory scratch("campaign_shapley");
  const std::string source = GROWTHUQ_SOURCE_DIR;
  spit(scratch.root / "shapley.ini", "[campaign]\nname = shapley\nseed = 28\nsamples = 4000\noutputs = p\n"
                                     "output_dir = out\nformats = csv\n\n[instrument]\nprobe_radius_um = 0.25\n"
                                     "poisson_ratio = 0.2\n\n[physics_correlation]\nsamples = 2000\n\n[sensitivity]\n"
                                     "method = shapley\nouter = 2000\nvariance_samples = 20000\n\n[line pme48]\n"
                                     "distributions = " + source + "/distributions/pme48.ini\nrank_correlation = physics\n");
  const CliOutcome run = run_cli("run shapley.ini --quiet", scratch.root);
  REQUIRE_MESSAGE(run.exit_code == 0, run.err);
  CHECK(run.out.find("Shapley effects as shares of Var(output) (each column sums to 1)") != std::string::npos);
  CHECK(run.out.find("Gaussian copula") != std::string::npos);

  const CsvTable samples = read_csv((scratch.root / "out" / "samples.csv").string());
  const std::vector<std::string> inputs{"k_N_per_m", "d_um", "d0_um"};
  const std::size_t status = samples.column_index("status"), p = samples.column_index("p_MPa");
  std::vector<std::vector<double>> logs(4);
  for (const auto& row : samples.rows) {
    if (row[status] != "ok") continue;
    for (std::size_t i = 0; i < 3; ++i) logs[i].push_back(std::log(std::stod(row[samples.column_index(inputs[i])])));
    logs[3].push_back(std::log(std::stod(row[p])));
  }
  const auto n = static_cast<Eigen::Index>(logs[0].size());
  Eigen::MatrixXd x(n, 4);
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index i = 0; i < 3; ++i) x(j, i) = logs[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    x(j, 3) = 1.0;
  }
  Eigen::VectorXd y(n);
  for (Eigen::Index j = 0; j < n; ++j) y(j) = logs[3][static_cast<std::size_t>(j)];
  const Eigen::VectorXd exponents = (x.transpose() * x).ldlt().solve(x.transpose() * y).head(3);
  const Eigen::MatrixXd centred = x.leftCols(3).rowwise() - x.leftCols(3).colwise().mean();
  const Eigen::MatrixXd covariance = centred.transpose() * centred / static_cast<double>(n - 1);
  const Eigen::VectorXd reference = linear_gaussian_shapley(covariance, exponents) / exponents.dot(covariance * exponents);

  const CsvTable table = read_csv((scratch.root / "out" / "sensitivity.csv").string());
  double sum = 0;
  std::size_t found = 0;
  for (const auto& row : table.rows) {
    if (row[3] != "shapley_share") continue;
    const auto i = static_cast<Eigen::Index>(std::find(inputs.begin(), inputs.end(), row[2]) - inputs.begin());
    REQUIRE(i < 3);
    const double share = std::stod(row[4]);
    sum += share;
    ++found;
    MESSAGE("p on " << row[2] << ": Shapley share " << share << " [" << row[5] << ", " << row[6] << "], log-linear "
                    << reference(i) << " (exponent " << exponents(i) << ")");
    CHECK(std::abs(share - reference(i)) < 0.06);
  }
  CHECK(found == 3);
  CHECK(sum == doctest::Approx(1.0).epsilon(1e-12));
}

TEST_CASE("campaign sensitivity: Sobol indices only for a line of independent inputs, refused otherwise") {
  // Two lines of one law: wt_free without a rank correlation gets Sobol indices from N (d + 2)
  // new runs; pme48, with the physics correlation, is refused with one line saying why. Their
  // accuracy is tested on Ishigami (test_sobol.cpp): this thin-shell line drawn without its
  // correlation puts d below d0 in many samples (flagged) and its turgor's variance in a few
  // samples of stretch near 1, so its numbers are no reference for anything.
  ScratchDirectory scratch("campaign_sobol");
  const std::string source = GROWTHUQ_SOURCE_DIR;
  spit(scratch.root / "sobol.ini", "[campaign]\nname = sobol\nseed = 28\nsamples = 1000\noutputs = p\n"
                                   "output_dir = out\nformats = csv\n\n[instrument]\nprobe_radius_um = 0.25\n"
                                   "poisson_ratio = 0.2\n\n[physics_correlation]\nsamples = 2000\n\n[sensitivity]\n"
                                   "method = sobol\nsobol_samples = 2000\n\n[line wt_free]\n"
                                   "distributions = " + source + "/distributions/pme48.ini\n\n[line pme48]\n"
                                   "distributions = " + source + "/distributions/pme48.ini\nrank_correlation = physics\n");
  const CliOutcome run = run_cli("run sobol.ini --quiet", scratch.root);
  REQUIRE_MESSAGE(run.exit_code == 0, run.err);
  CHECK(run.out.find("  note: no Sobol indices: the inputs of line 'pme48' are rank-correlated (rank_correlation = physics), "
                     "and the Saltelli/Jansen estimators assume independent inputs; use [sensitivity] method = shapley\n") !=
        std::string::npos);
  CHECK(run.out.find("Sobol first-order indices (Saltelli et al. 2010; independent inputs), 10000 model runs") != std::string::npos);
  const CsvTable table = read_csv((scratch.root / "out" / "sensitivity.csv").string());
  std::size_t first = 0, total = 0;
  for (const auto& row : table.rows) {
    CHECK_FALSE((row[0] == "pme48" && row[3].starts_with("sobol")));
    if (row[0] == "wt_free" && row[3] == "sobol_first") ++first;
    if (row[0] == "wt_free" && row[3] == "sobol_total") {
      ++total;
      CHECK(row[7] == "10000");  // N (d + 2) = 2000 x 5 runs for k, d, d0
    }
  }
  CHECK(first == 3);
  CHECK(total == 3);
}
