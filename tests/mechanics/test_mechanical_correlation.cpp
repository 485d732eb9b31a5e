// The mechanical rank correlation: a valid correlation matrix, equal to one computed by a
// second algorithm, with the exact structure monotone mechanics imposes.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include <Eigen/Eigenvalues>

#include "growthuq/core/error.hpp"
#include "growthuq/mechanics/mechanical_correlation.hpp"

using namespace growthuq;

namespace {

Instrument probe(double rho) {
  Instrument parameters;
  parameters.probe_radius_m = rho;
  return parameters;
}

// Ordinal ranks by sorting (continuous draws have no ties).
std::vector<double> ranks(const std::vector<double>& values) {
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::vector<double> rank(values.size());
  for (std::size_t r = 0; r < order.size(); ++r) rank[order[r]] = static_cast<double>(r);
  return rank;
}

// Spearman's formula 1 - 6 sum d^2 / (n (n^2 - 1)) for untied ranks: a second algorithm.
double spearman(const std::vector<double>& a, const std::vector<double>& b) {
  const std::vector<double> ra = ranks(a);
  const std::vector<double> rb = ranks(b);
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (ra[i] - rb[i]) * (ra[i] - rb[i]);
  const double n = static_cast<double>(a.size());
  return 1 - 6 * sum / (n * (n * n - 1));
}

}  // namespace

TEST_CASE("the matrix is a valid correlation matrix and matches a second algorithm") {
  MechanicalDrawOptions options;
  options.samples = 5000;
  options.seed = 7;
  const MechanicalCorrelation result = mechanical_rank_correlation(options, probe(0.5e-6), "test");
  REQUIRE(result.spearman.rows() == 4);
  REQUIRE(result.spearman.cols() == 4);
  CHECK(result.drawn == 5000);
  CHECK(result.kept + result.burst + result.other_dropped == result.drawn);
  for (Eigen::Index a = 0; a < 4; ++a) {
    CHECK(result.spearman(a, a) == 1.0);
    for (Eigen::Index b = 0; b < 4; ++b) {
      CHECK(result.spearman(a, b) == result.spearman(b, a));  // exactly
      CHECK(std::fabs(result.spearman(a, b)) <= 1.0);
    }
  }
  // A rank correlation matrix is a Pearson matrix of rank vectors: positive semidefinite.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(result.spearman);
  CHECK(eigen.eigenvalues().minCoeff() > -1e-12);

  // Second algorithm: redraw, run the per-sample forward model, rank by sorting, Spearman's
  // closed form. Agreement to 1e-12 (both are sums of ~1e4 exact integers, then one division).
  SampleBlock block = draw_mechanical_samples(options);
  std::vector<std::vector<double>> kept(4);
  std::size_t burst = 0;
  for (std::size_t i = 0; i < block.size(); ++i) {
    const double p = block.column("p")[i];
    const double E = block.column("E")[i];
    const double h = block.column("h")[i];
    const double d0 = block.column("d0")[i];
    // Independent burst criterion, Eq. (M9), src/mechanics/README.md.
    if (p / (2 * h * E) * d0 > 1 / std::numbers::e) {
      ++burst;
      continue;
    }
    const ForwardResult forward = thin_shell_forward(p, E, h, d0, probe(0.5e-6));
    REQUIRE(forward.status == SampleStatus::ok);
    kept[0].push_back(forward.k_measured);
    kept[1].push_back(h);
    kept[2].push_back(forward.d);
    kept[3].push_back(d0);
  }
  CHECK(burst == result.burst);
  CHECK(burst > 0);  // the default ranges reach c d0 > 1/e at low E, high p
  for (Eigen::Index a = 0; a < 4; ++a) {
    for (Eigen::Index b = a + 1; b < 4; ++b) {
      CAPTURE(a);
      CAPTURE(b);
      CHECK(std::fabs(result.spearman(a, b) - spearman(kept[static_cast<std::size_t>(a)],
                                                         kept[static_cast<std::size_t>(b)])) < 1e-12);
    }
  }
  // The turgid diameter follows the plasmolysed one (d = lambda d0, lambda varies little).
  CHECK(result.spearman(2, 3) > 0.8);
}

TEST_CASE("monotone mechanics gives exact rank correlations of +-1") {
  // With p, E and d0 confined to a relative width of 1e-12, only h varies. c = p/(2 h E)
  // decreases with h and lambda = -W0(-c d0)/(c d0) increases with c d0, so d = lambda d0 is
  // strictly decreasing in h: Spearman(h, d) = -1 exactly.
  MechanicalDrawOptions options;
  options.samples = 2000;
  options.p = {0.3e6, 0.3e6 * (1 + 1e-12)};
  options.E = {50e6, 50e6 * (1 + 1e-12)};
  options.d0 = {5e-6, 5e-6 * (1 + 1e-12)};
  const MechanicalCorrelation thickness_only = mechanical_rank_correlation(options, probe(0.5e-6), "test");
  CHECK(thickness_only.burst == 0);
  CHECK(thickness_only.spearman(1, 2) == -1.0);
  // Only d0 varies: c d0 grows with d0, so lambda and d = lambda d0 grow: Spearman(d, d0) = +1.
  options.h = {150e-9, 150e-9 * (1 + 1e-12)};
  options.d0 = {4e-6, 8e-6};
  const MechanicalCorrelation diameter_only = mechanical_rank_correlation(options, probe(0.5e-6), "test");
  CHECK(diameter_only.spearman(2, 3) == 1.0);
}

TEST_CASE("draws are reproducible, in range, and uniform or log-uniform as asked") {
  MechanicalDrawOptions options;
  options.samples = 20000;
  options.seed = 42;
  const SampleBlock first = draw_mechanical_samples(options);
  const SampleBlock again = draw_mechanical_samples(options);
  for (std::size_t i = 0; i < first.size(); ++i) CHECK(first.column("E")[i] == again.column("E")[i]);
  // Uniform on [5, 200] MPa: mean 102.5 MPa, standard error 56.3/sqrt(2e4) = 0.40 MPa; 5 sigma.
  const auto E = first.column("E");
  const double mean = std::accumulate(E.begin(), E.end(), 0.0) / static_cast<double>(E.size());
  CHECK(std::fabs(mean - 102.5e6) < 5 * 0.40e6);
  CHECK(*std::min_element(E.begin(), E.end()) >= 5e6);
  CHECK(*std::max_element(E.begin(), E.end()) <= 200e6);
  // Log-uniform: ln E uniform on [ln 5, ln 200] MPa, so the median is sqrt(5 * 200) = 31.6 MPa:
  // the fraction below it is 1/2 with standard error 0.0035; 5 sigma.
  options.scale = DrawScale::log_uniform;
  const SampleBlock logged = draw_mechanical_samples(options);
  const auto E_log = logged.column("E");
  const auto below = std::count_if(E_log.begin(), E_log.end(), [](double e) { return e < std::sqrt(5e6 * 200e6); });
  CHECK(std::fabs(static_cast<double>(below) / 20000.0 - 0.5) < 5 * 0.0035);
  options.seed = 43;
  CHECK(draw_mechanical_samples(options).column("E")[0] != E_log[0]);
}

TEST_CASE("bad ranges and hopeless draws are InputErrors") {
  MechanicalDrawOptions options;
  options.p = {0.8e6, 0.1e6};
  CHECK_THROWS_WITH_AS(validate(options, "correlate"),
                       "correlate: p_MPa = '0.8:0.1': expected LOW:HIGH with 0 < LOW < HIGH", InputError);
  options = MechanicalDrawOptions{};
  options.samples = 2;
  CHECK_THROWS_AS(validate(options, "correlate"), InputError);
  // Every tube bursts: p d0 / (2 h E) >= 1.5e6 * 4e-6 / (2 * 1e-7 * 2e6) = 15 > 1/e.
  options = MechanicalDrawOptions{};
  options.p = {1.5e6, 2e6};
  options.E = {1e6, 2e6};
  options.samples = 100;
  CHECK_THROWS_WITH_AS(mechanical_rank_correlation(options, probe(0.5e-6), "correlate"),
                       "correlate: 0 of 100 drawn tubes hold their turgor (100 burst: p d0 / (2 h E) > 1/e): "
                       "lower the turgor range or raise the modulus or thickness",
                       InputError);
}
