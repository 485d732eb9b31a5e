// The unstable branch of the hoop relation: p = (2 h E / d0) ln(lambda) / lambda peaks at
// lambda = e, so a measured e < lambda < exp(1/(1 - nu^2)) has a (p, E) for which the forward
// model (principal branch W0) returns the other, smaller diameter. The inverse flags it
// unstable_branch; lambda = e itself and everything below stays ok and round-trips.
#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_lambert.h>

#include "growthuq/mechanics/arnoldi.hpp"
#include "growthuq/mechanics/thin_shell.hpp"
#include "growthuq/mechanics/thin_shell_evaluators.hpp"
#include "support/random_draws.hpp"

using namespace growthuq;
using growthuq::testing::log_uniform;
using growthuq::testing::unit_uniform;

namespace {

constexpr double um = 1e-6;
constexpr double nm = 1e-9;
constexpr double e = std::numbers::e;

double relative_error(double value, double reference) {
  return std::fabs(value - reference) / std::fabs(reference);
}

Instrument probe(double rho, double nu) {
  Instrument parameters;
  parameters.probe_radius_m = rho;
  parameters.poisson_ratio = nu;
  return parameters;
}


// What the closed-form inverse returned for a window sample before it had a status: p from
// relation 2 with alpha = d sqrt(3q / (16 (1 - q))) (q < 1 still holds), E from relation 1.
struct Unflagged {
  double p, E;
};
Unflagged closed_form(double k, double d, double d0, double h, double rho, double nu) {
  const double ln_lambda = std::log(d / d0);
  const double q = (1 - nu * nu) * ln_lambda;
  const double alpha = d * std::sqrt(3 * q / (16 * (1 - q)));
  const double p = 4 * k / (3 * std::numbers::pi * d * arnoldi_phi(rho / alpha));
  return {p, p * d / (2 * h * ln_lambda)};
}

}  // namespace

TEST_CASE("e < d/d0 < exp(1/(1 - nu^2)) is unstable_branch; d/d0 = e and below are ok") {
  const Instrument parameters = probe(0.5 * um, 0.2);
  const double d0 = 5 * um;
  const double top = std::exp(1 / 0.96);  // 2.8339363076941687 (mpmath): q = 1
  for (double lambda : {e * (1 + 1e-9), 2.72, 2.78, 2.8, top * (1 - 1e-12)}) {
    CAPTURE(lambda);
    const TurgorResult turgor = invert_turgor(2.87, lambda * d0, d0, parameters);
    CHECK(to_string(turgor.status) == "unstable_branch");
    CHECK(turgor.q < 1);  // the membrane limit does not catch it
    CHECK(relative_error(turgor.lambda, lambda) < 2 * DBL_EPSILON);
    CHECK(std::isnan(turgor.alpha));
    CHECK(std::isnan(turgor.x));
    CHECK(std::isnan(turgor.phi));
    CHECK(std::isnan(turgor.p));
    const ModulusResult modulus = invert_modulus(0.3e6, lambda * d0, d0, 145 * nm);
    CHECK(modulus.status == SampleStatus::unstable_branch);
    CHECK(std::isnan(modulus.E));
    CHECK(std::isnan(modulus.hoop_stress));
    CHECK(std::isnan(modulus.wall_stiffness));
  }
  // Above the window q >= 1 comes first, as before.
  CHECK(invert_turgor(2.87, top * (1 + 1e-12) * d0, d0, parameters).status == SampleStatus::beyond_membrane_limit);
  // Just below e, and e itself: d0 = 2^-18 m makes d = e d0 exact, d - d0 = (e - 1) d0 exact, and
  // ln(lambda) = log1p(e - 1) is the logarithm of the double nearest e (1 - 5.3e-17), which
  // rounds to 1 or the double below: not above 1, so the marginal point is ok.
  const double d0_exact = 0x1p-18;
  for (double lambda : {e * (1 - 1e-9), e}) {
    CAPTURE(lambda);
    const TurgorResult turgor = invert_turgor(2.87, lambda * d0_exact, d0_exact, parameters);
    CHECK(turgor.status == SampleStatus::ok);
    CHECK(std::isfinite(turgor.p));
    CHECK(invert_modulus(turgor.p, lambda * d0_exact, d0_exact, 145 * nm).status == SampleStatus::ok);
  }
}

TEST_CASE("just below e the inverse is ok and forward(inverse(k, d, d0, h)) reproduces d and k") {
  // Independent check: the forward model solves ln(d/d0) = c d with W0. Near lambda = e its
  // condition number |z W0'/W0| = 1/(1 + W0) = 1/(1 - ln lambda) grows, so the tolerance is
  // 64 roundings amplified by it (1/(1 - ln lambda) ~ 1e3..1e6 here). A relative error w in
  // ln(lambda) moves d by w, q by w q, alpha = d sqrt(3q / (16 (1 - q))) by w (3/2 + q/(2(1 - q)))
  // and phi by at most as much as alpha (x phi'/phi = 1 - x^2/phi^2 in [0, 1]), so k gets
  // w (3 + q/(2(1 - q))): large for nu = 0, where q = ln(lambda) -> 1 at e too.
  for (double nu : {0.0, 0.2, 0.45}) {
    for (double below : {1e-3, 1e-4, 1e-5, 1e-6}) {
      const double lambda = e * (1 - below);
      CAPTURE(nu);
      CAPTURE(lambda);
      const Instrument parameters = probe(0.5 * um, nu);
      const double d0 = 5.35 * um;
      const double d = lambda * d0;
      const double h = 145 * nm;
      const TurgorResult turgor = invert_turgor(2.87, d, d0, parameters);
      REQUIRE(turgor.status == SampleStatus::ok);
      const ModulusResult modulus = invert_modulus(turgor.p, d, d0, h);
      REQUIRE(modulus.status == SampleStatus::ok);
      const ForwardResult forward = thin_shell_forward(turgor.p, modulus.E, h, d0, parameters);
      REQUIRE(forward.status == SampleStatus::ok);
      const double tolerance = 64 * DBL_EPSILON / (1 - std::log(lambda));
      CHECK(relative_error(forward.d, d) < tolerance);
      const double q = (1 - nu * nu) * std::log(lambda);
      CHECK(relative_error(forward.k_measured, 2.87) < tolerance * (3 + q / (2 * (1 - q))));
    }
  }
}

TEST_CASE("nu = 0 has no unstable window: above e it is beyond_membrane_limit") {
  // q = (1 - 0) ln(lambda) = ln(lambda) exactly, and q >= 1 is checked before ln(lambda) > 1.
  const Instrument parameters = probe(0.5 * um, 0.0);
  const double d0 = 5 * um;
  std::size_t ok = 0;
  std::size_t beyond = 0;
  for (int i = -2000; i <= 2000; ++i) {
    // lambda = e (1 + i 1e-15) (a few ulp apart near e), then wider steps up to e (1 + 0.3).
    const double step = std::abs(i) <= 1000 ? 1e-15 * i : (i > 0 ? 1 : -1) * 3e-4 * (std::abs(i) - 1000);
    const double lambda = e * (1 + step);
    const SampleStatus status = invert_turgor(2.87, lambda * d0, d0, parameters).status;
    CAPTURE(lambda);
    CHECK(status != SampleStatus::unstable_branch);
    if (status == SampleStatus::ok) {
      ++ok;
      CHECK(std::log1p((lambda * d0 - d0) / d0) < 1);
    } else {
      CHECK(status == SampleStatus::beyond_membrane_limit);
      ++beyond;
    }
    if (lambda < e * (1 - 4 * DBL_EPSILON)) CHECK(status == SampleStatus::ok);
    if (lambda > e * (1 + 4 * DBL_EPSILON)) CHECK(status == SampleStatus::beyond_membrane_limit);
  }
  CHECK(ok > 1900);
  CHECK(beyond > 1900);
}

TEST_CASE("in the window the forward model returns the W0 root, not d: W-1 gives d") {
  // The reason for the status. For (p, E) from the closed form at a window lambda, c = p/(2hE)
  // = ln(lambda)/d, so z = c d0 = ln(lambda)/lambda < 1/e and ln(x) = z x has two roots: the
  // forward model's -W0(-z)/z < e and -W-1(-z)/z = lambda > e (GSL's other branch, a second
  // algorithm). Window lambda from e (1 + 1e-6) up: nearer e, z rounds to 1/e. Tolerance for
  // W-1: 64 roundings times its condition number 1/|1 + W-1| = 1/(ln lambda - 1).
  gsl_error_handler_t* previous = gsl_set_error_handler_off();
  std::mt19937_64 engine(20261201);
  int compared = 0;
  for (int i = 0; i < 2000; ++i) {
    const double nu = 0.05 + 0.4 * unit_uniform(engine);
    const double top = std::exp(1 / (1 - nu * nu));
    const double lambda = e * (1 + 1e-6) + (top * (1 - 1e-9) - e * (1 + 1e-6)) * unit_uniform(engine);
    const double k = log_uniform(engine, 0.01, 100);
    const double d0 = log_uniform(engine, 1 * um, 50 * um);
    const double h = log_uniform(engine, 20 * nm, 2 * um);
    const double rho = log_uniform(engine, 0.01 * um, 10 * um);
    const double d = lambda * d0;
    const Instrument parameters = probe(rho, nu);
    CAPTURE(i);
    CAPTURE(nu);
    CAPTURE(lambda);
    REQUIRE(invert_turgor(k, d, d0, parameters).status == SampleStatus::unstable_branch);
    const Unflagged unflagged = closed_form(k, d, d0, h, rho, nu);
    REQUIRE(std::isfinite(unflagged.p));
    REQUIRE(std::isfinite(unflagged.E));
    const ForwardResult forward = thin_shell_forward(unflagged.p, unflagged.E, h, d0, parameters);
    REQUIRE(forward.status == SampleStatus::ok);
    CHECK(forward.lambda < e);
    CHECK(forward.d < e * d0);
    CHECK(relative_error(forward.d, d) > 1 - e / lambda);  // at least the distance from d to e d0
    const double c = unflagged.p / (2 * h * unflagged.E);
    gsl_sf_result other;
    REQUIRE(gsl_sf_lambert_Wm1_e(-c * d0, &other) == GSL_SUCCESS);
    CHECK(relative_error(-other.val / c, d) < 64 * DBL_EPSILON / (std::log(lambda) - 1));
    ++compared;
  }
  gsl_set_error_handler(previous);
  CHECK(compared == 2000);

  // A 40-digit reference (mpmath: -lambertw(-z, 0)/z, z = ln(2.78)/2.78): the forward model's
  // diameter for the unflagged (p, E) at lambda = 2.78 is 2.6588 d0, not 2.78 d0.
  const double d0 = 5 * um;
  const Unflagged at = closed_form(2.87, 2.78 * d0, d0, 145 * nm, 0.5 * um, 0.2);
  const ForwardResult forward = thin_shell_forward(at.p, at.E, 145 * nm, d0, probe(0.5 * um, 0.2));
  REQUIRE(forward.status == SampleStatus::ok);
  // Condition number 1/(1 - ln 2.6588) = 43: 1e-13.
  CHECK(relative_error(forward.lambda, 2.658813986566562764471519907504987908557) < 1e-13);
}

TEST_CASE("evaluators: unstable_branch flows like the other statuses, turgor-only plans included") {
  const ThinShellTurgor turgor(probe(0.5 * um, 0.2), "test");
  const ThinShellModulus modulus;
  const std::vector<const Evaluator*> available{&turgor, &modulus};
  const std::vector<double> lambdas{1.2, 2.78, e * (1 - 1e-6), e * (1 + 1e-9), 2.84};
  const std::vector<SampleStatus> expected{SampleStatus::ok, SampleStatus::unstable_branch, SampleStatus::ok,
                                           SampleStatus::unstable_branch, SampleStatus::beyond_membrane_limit};
  for (bool with_h : {false, true}) {
    CAPTURE(with_h);
    SampleBlock block(lambdas.size());
    std::vector<double> d;
    for (double lambda : lambdas) d.push_back(lambda * 5 * um);
    block.set_column("k", std::vector<double>(lambdas.size(), 2.87));
    block.set_column("d", d);
    block.set_column("d0", std::vector<double>(lambdas.size(), 5 * um));
    std::vector<std::string> inputs{"k", "d", "d0"};
    std::vector<std::string> wanted{"p"};
    if (with_h) {
      block.set_column("h", std::vector<double>(lambdas.size(), 145 * nm));
      inputs.emplace_back("h");
      wanted.emplace_back("E");
    }
    const auto plan = plan_evaluation(available, inputs, wanted);
    REQUIRE(plan.size() == (with_h ? 2u : 1u));
    run_plan(plan, block);
    std::vector<std::string> outputs{"lambda", "alpha", "phi", "p"};
    if (with_h) outputs.insert(outputs.end(), {"E", "hoop_stress", "wall_stiffness"});
    for (std::size_t i = 0; i < lambdas.size(); ++i) {
      CAPTURE(lambdas[i]);
      CHECK(to_string(block.status()[i]) == to_string(expected[i]));
      for (const std::string& name : outputs) {
        CAPTURE(name);
        if (expected[i] == SampleStatus::ok) {
          CHECK(std::isfinite(block.column(name)[i]));
        } else {
          CHECK(std::isnan(block.column(name)[i]));
        }
      }
    }
  }
}
