// The thin-shell inverse and forward model against an independent high-precision solution,
// closed-form limits, the round trip forward(inverse(x)) == x and every status it can give.
#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "growthuq/core/error.hpp"
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
constexpr double MPa = 1e6;

double relative_error(double value, double reference) {
  return std::fabs(value - reference) / std::fabs(reference);
}

Instrument probe(double rho, double nu = 0.2,
                          double k_sys = std::numeric_limits<double>::infinity()) {
  Instrument parameters;
  parameters.probe_radius_m = rho;
  parameters.poisson_ratio = nu;
  parameters.sensor_stiffness_N_per_m = k_sys;
  return parameters;
}


}  // namespace

TEST_CASE("turgor and modulus match a 40-digit solution of the two original relations") {
  // Reference: /usr/bin/python3 with mpmath (dps 40) solving relation 2 for p by findroot,
  // with alpha from the ORIGINAL form alpha^2 = 3 p d^3 / (16 (2 E h/(1-nu^2) - p d)) and E from
  // relation 1, i.e. without the engine's closed-form substitution of q. The script:
  //   def alpha_of(p): E = p*d/(2*h*log(d/d0)); return sqrt(3*p*d**3/(16*(2*E*h/(1-nu**2)-p*d)))
  //   p = findroot(lambda p: 3*pi/4*p*d*phi(rho/alpha_of(p)) - k, 3e5)
  // Tolerance 1e-13: the closed form takes ~10 roundings and phi is good to ~1e-15.
  struct Case {
    double k, d, d0, h, rho, nu, p, E, alpha, phi;
  };
  const std::vector<Case> cases{
      {2.87, 6.56 * um, 5.35 * um, 145 * nm, 0.5 * um, 0.2, 252807.78711172389726, 28047344.773892977043,
       1.4013404578487845288e-6, 0.7344740803355327904},
      {1.95, 5.32 * um, 4.51 * um, 199 * nm, 0.25 * um, 0.2, 255998.12525987163096, 20716577.373515227364,
       1.0000283841157624243e-6, 0.60768016098400299617},
      {1.95, 5.32 * um, 4.51 * um, 199 * nm, 1.0 * um, 0.2, 108817.46094516496272, 8806022.8838455198253,
       1.0000283841157624243e-6, 1.4295957709205666354},
      {2.87, 6.56 * um, 5.35 * um, 145 * nm, 0.5 * um, 0.3, 248141.45545668866455, 27529646.271590654741,
       1.3557933935405963249e-6, 0.74828595890521740361},
  };
  for (const Case& c : cases) {
    CAPTURE(c.rho);
    CAPTURE(c.nu);
    const TurgorResult turgor = invert_turgor(c.k, c.d, c.d0, probe(c.rho, c.nu));
    REQUIRE(turgor.status == SampleStatus::ok);
    CHECK(relative_error(turgor.p, c.p) < 1e-13);
    CHECK(relative_error(turgor.alpha, c.alpha) < 1e-13);
    CHECK(relative_error(turgor.phi, c.phi) < 1e-13);
    CHECK(relative_error(turgor.lambda, c.d / c.d0) < 2 * DBL_EPSILON);
    const ModulusResult modulus = invert_modulus(turgor.p, c.d, c.d0, c.h);
    REQUIRE(modulus.status == SampleStatus::ok);
    CHECK(relative_error(modulus.E, c.E) < 1e-13);
    CHECK(relative_error(modulus.hoop_stress, c.p * c.d / (2 * c.h)) < 1e-13);
    CHECK(relative_error(modulus.wall_stiffness, c.E * c.h) < 1e-13);
  }
  // The probe radius dominates (src/mechanics/README.md: p falls roughly 2x from rho = 0.25
  // to 1 um): 255998.1 / 108817.5 = 2.35 for the pme48 medians above.
  CHECK(cases[1].p / cases[2].p == doctest::Approx(2.3525).epsilon(1e-4));
}

TEST_CASE("the sensor correction is 1/k_m = 1/k + 1/k_sys") {
  // mpmath, same script with k replaced by k k_sys/(k_sys - k), k_sys = 50 N/m:
  // p = 268202.6173474685952 Pa, E = 29755298.932625691816 Pa.
  const TurgorResult corrected = invert_turgor(2.87, 6.56 * um, 5.35 * um, probe(0.5 * um, 0.2, 50.0));
  REQUIRE(corrected.status == SampleStatus::ok);
  CHECK(relative_error(corrected.p, 268202.6173474685952) < 1e-13);
  CHECK(relative_error(invert_modulus(corrected.p, 6.56 * um, 5.35 * um, 145 * nm).E, 29755298.932625691816) <
        1e-13);
  // p is proportional to the tube stiffness k = k_m / (1 - k_m / k_sys): here 1/(1 - 1e-6).
  const double ideal = invert_turgor(2.87, 6.56 * um, 5.35 * um, probe(0.5 * um)).p;
  const double stiff = invert_turgor(2.87, 6.56 * um, 5.35 * um, probe(0.5 * um, 0.2, 2.87e6)).p;
  CHECK(relative_error(stiff, ideal / (1 - 1e-6)) < 4 * DBL_EPSILON);
}

TEST_CASE("forward model: closed-form stretch and the small-strain series") {
  const Instrument parameters = probe(0.5 * um);
  // Known lambda: choose lambda, get p from relation 1 at d = lambda d0, and the forward model
  // must return d (the Lambert W solve checked against the equation it solves).
  for (double lambda : {1.001, 1.02, 1.2, 1.4, 2.0, 2.5}) {
    CAPTURE(lambda);
    const double d0 = 5 * um;
    const double h = 150 * nm;
    const double E = 50 * MPa;
    const double p = 2 * h * E * std::log(lambda) / (lambda * d0);
    const ForwardResult forward = thin_shell_forward(p, E, h, d0, parameters);
    REQUIRE(forward.status == SampleStatus::ok);
    // Conditioning of W0 at -z: |z W0'/W0| = 1/(1 + W0), i.e. 1/(1 - ln lambda); below 12 here.
    CHECK(relative_error(forward.d, lambda * d0) < 1e-14);
    // k from relation 2 with alpha in its original (p, E, h) form, computed here independently.
    const double alpha = std::sqrt(3 * p * std::pow(forward.d, 3) /
                                   (16 * (2 * E * h / (1 - 0.04) - p * forward.d)));
    CHECK(relative_error(forward.alpha, alpha) < 1e-13);
    const double k = 0.75 * std::numbers::pi * p * forward.d * arnoldi_phi(0.5 * um / alpha);
    CHECK(relative_error(forward.k_measured, k) < 1e-13);
  }
  // Small strain: -W0(-z)/z = sum n^(n-1)/n! z^(n-1) = 1 + z + (3/2) z^2 + (8/3) z^3
  // + (125/24) z^4 + O(z^5) (the Taylor series of W0 about 0, Corless et al. 1996); the rest is
  // 1e-19 for z = 1e-4, so the tolerance is the rounding of lambda and of the series (4 ulp).
  const double z = 1e-4;
  const double d0 = 5 * um;
  const double h = 100 * nm;
  const double E = 100 * MPa;
  const double p = z * 2 * h * E / d0;
  const ForwardResult small = thin_shell_forward(p, E, h, d0, parameters);
  REQUIRE(small.status == SampleStatus::ok);
  CHECK(relative_error(small.lambda, 1 + z * (1 + z * (1.5 + z * (8.0 / 3.0 + z * 125.0 / 24.0)))) < 4 * DBL_EPSILON);
}

TEST_CASE("forward model at the burst limit c d0 = 1/e") {
  const Instrument parameters = probe(0.5 * um);
  const double d0 = 5 * um;
  const double h = 150 * nm;
  const double E = 50 * MPa;
  const double p_burst = 2 * h * E / (std::numbers::e * d0);  // c d0 = 1/e: lambda = e, the largest stable stretch
  const ForwardResult at = thin_shell_forward(p_burst * (1 - 4 * DBL_EPSILON), E, h, d0, parameters);
  REQUIRE(at.status == SampleStatus::ok);
  // Near the branch point W0 has a square-root singularity: 1e-8 relative is what double allows.
  CHECK(relative_error(at.lambda, std::numbers::e) < 1e-7);
  CHECK(std::isfinite(at.k_measured));
  CHECK(thin_shell_forward(p_burst * (1 + 4 * DBL_EPSILON), E, h, d0, parameters).status == SampleStatus::burst);
  CHECK(thin_shell_forward(p_burst * 2, E, h, d0, parameters).status == SampleStatus::burst);
  // With nu = 0 the membrane limit q = ln(lambda) < 1 is reached exactly at lambda = e.
  const ForwardResult membrane = thin_shell_forward(p_burst * (1 - 1e-10), E, h, d0, probe(0.5 * um, 0.0));
  CHECK(membrane.status == SampleStatus::ok);
  CHECK(membrane.lambda < std::numbers::e);
}

TEST_CASE("round trip forward(inverse(k, d, d0, h)) over 10^4 random points of the envelope") {
  // Envelope of src/mechanics/README.md: k 0.01-100 N/m, d0 1-50 um, lambda 1.001 to 2.7 (the
  // forward model's stable branch ends at lambda = e: above it, W0 returns the other root),
  // h 0.02-2 um, rho 0.01-10 um, nu 0-0.45, k_sys infinite or 10^1-10^4 times k. 1e-10: the
  // worst conditioning of the chain is W0 near lambda = 2.7 (|1/(1 - ln lambda)| ~ 150).
  std::mt19937_64 engine(20240611);
  int compared = 0;
  for (int i = 0; i < 10000; ++i) {
    const double k = log_uniform(engine, 0.01, 100);
    const double d0 = log_uniform(engine, 1 * um, 50 * um);
    const double lambda = log_uniform(engine, 1.001, 2.7);
    const double d = lambda * d0;
    const double h = log_uniform(engine, 20 * nm, 2 * um);
    const double rho = log_uniform(engine, 0.01 * um, 10 * um);
    const double nu = 0.45 * unit_uniform(engine);
    const double k_sys = i % 2 == 0 ? std::numeric_limits<double>::infinity() : k * log_uniform(engine, 10, 1e4);
    const Instrument parameters = probe(rho, nu, k_sys);
    CAPTURE(i);
    const TurgorResult turgor = invert_turgor(k, d, d0, parameters);
    REQUIRE(turgor.status == SampleStatus::ok);
    const ModulusResult modulus = invert_modulus(turgor.p, d, d0, h);
    REQUIRE(modulus.status == SampleStatus::ok);
    const ForwardResult forward = thin_shell_forward(turgor.p, modulus.E, h, d0, parameters);
    REQUIRE(forward.status == SampleStatus::ok);
    CHECK(relative_error(forward.d, d) < 1e-10);
    CHECK(relative_error(forward.k_measured, k) < 1e-10);
    ++compared;
  }
  CHECK(compared == 10000);
}

TEST_CASE("statuses instead of NaN") {
  const Instrument parameters = probe(0.5 * um, 0.2, 100.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(invert_turgor(nan, 6 * um, 5 * um, parameters).status == SampleStatus::invalid_input);
  CHECK(invert_turgor(-1, 6 * um, 5 * um, parameters).status == SampleStatus::invalid_input);
  CHECK(invert_turgor(2, inf, 5 * um, parameters).status == SampleStatus::invalid_input);
  CHECK(invert_turgor(2, 6 * um, 0, parameters).status == SampleStatus::invalid_input);
  CHECK(invert_turgor(100, 6 * um, 5 * um, parameters).status == SampleStatus::stiffness_at_sensor_limit);
  CHECK(invert_turgor(150, 6 * um, 5 * um, parameters).status == SampleStatus::stiffness_at_sensor_limit);
  CHECK(invert_turgor(2, 5 * um, 5 * um, parameters).status == SampleStatus::lambda_not_above_one);
  CHECK(invert_turgor(2, 4 * um, 5 * um, parameters).status == SampleStatus::lambda_not_above_one);
  // q = (1 - nu^2) ln(lambda) >= 1 from lambda = exp(1/0.96) = 2.8334...
  CHECK(invert_turgor(2, 2.84 * 5 * um, 5 * um, parameters).status == SampleStatus::beyond_membrane_limit);
  // e < lambda < 2.8334: past the pressure maximum of relation 1 (test_thin_shell_branch.cpp).
  CHECK(invert_turgor(2, 2.83 * 5 * um, 5 * um, parameters).status == SampleStatus::unstable_branch);
  CHECK(invert_turgor(2, 2.71 * 5 * um, 5 * um, parameters).status == SampleStatus::ok);
  CHECK(invert_modulus(0.3 * MPa, 2.83 * 5 * um, 5 * um, 100 * nm).status == SampleStatus::unstable_branch);

  CHECK(invert_modulus(0.3 * MPa, 6 * um, 5 * um, 0).status == SampleStatus::invalid_input);
  CHECK(invert_modulus(0.3 * MPa, 5 * um, 5 * um, 100 * nm).status == SampleStatus::lambda_not_above_one);
  CHECK(invert_modulus(1e300, 6 * um, 5 * um, 1e-300).status == SampleStatus::out_of_range);

  CHECK(thin_shell_forward(0.3 * MPa, 0, 100 * nm, 5 * um, parameters).status == SampleStatus::invalid_input);
  CHECK(thin_shell_forward(1e300, 1e-300, 100 * nm, 5 * um, parameters).status == SampleStatus::out_of_range);
}

TEST_CASE("parameters are validated with the key a user wrote") {
  Instrument missing_rho;
  CHECK_THROWS_WITH_AS(validate(missing_rho, "eval"),
                       "eval: probe_radius_um = '': expected a probe radius in um, > 0 and at most 1000", InputError);
  CHECK_THROWS_WITH_AS(validate(probe(0.5 * um, 0.5), "eval"),
                       "eval: poisson_ratio = '0.5': expected a Poisson ratio in [0, 0.5)", InputError);
  CHECK_THROWS_WITH_AS(validate(probe(0.5 * um, 0.2, 0.0), "eval"),
                       "eval: sensor_stiffness_N_per_m = '0': expected a sensor stiffness in N/m, a number > 0 or inf "
                       "(an ideal sensor)",
                       InputError);
  CHECK_THROWS_AS(ThinShellTurgor(missing_rho, "eval"), InputError);
  CHECK_NOTHROW(validate(probe(0.5 * um), "eval"));
}

TEST_CASE("evaluators: turgor needs no thickness, statuses flow through a plan") {
  const ThinShellTurgor turgor(probe(0.5 * um), "test");
  const ThinShellModulus modulus;
  const std::vector<const Evaluator*> available{&modulus, &turgor};

  const std::vector<std::string> measured{"k", "d", "d0"};
  const std::vector<std::string> want_p{"p"};
  const auto turgor_plan = plan_evaluation(available, measured, want_p);
  REQUIRE(turgor_plan.size() == 1);
  CHECK(turgor_plan[0] == &turgor);

  SampleBlock block(4);
  block.set_column("k", std::vector<double>{2.87, 2.87, -1.0, 2.87});
  block.set_column("d", std::vector<double>{6.56 * um, 5.0 * um, 6.56 * um, 6.56 * um});
  block.set_column("d0", std::vector<double>{5.35 * um, 5.35 * um, 5.35 * um, 5.35 * um});
  block.set_column("h", std::vector<double>{145 * nm, 145 * nm, 145 * nm, 0.0});
  const std::vector<std::string> with_h{"k", "d", "d0", "h"};
  const std::vector<std::string> want_E{"E", "p"};
  const auto plan = plan_evaluation(available, with_h, want_E);
  REQUIRE(plan.size() == 2);
  run_plan(plan, block);
  CHECK(block.status()[0] == SampleStatus::ok);
  CHECK(relative_error(block.column("p")[0], 252807.78711172389726) < 1e-13);
  CHECK(relative_error(block.column("E")[0], 28047344.773892977043) < 1e-13);
  CHECK(block.status()[1] == SampleStatus::lambda_not_above_one);
  CHECK(block.status()[2] == SampleStatus::invalid_input);
  CHECK(block.status()[3] == SampleStatus::invalid_input);  // h = 0 reaches the modulus only
  CHECK(std::isfinite(block.column("p")[3]));
  for (std::size_t i = 1; i < 4; ++i) CHECK(std::isnan(block.column("E")[i]));
}

TEST_CASE("WallStress: from the closed form's own p and E it gives ThinShellModulus's hoop stress and E h, and the turgor's lambda") {
  const ThinShellTurgor turgor(probe(0.5 * um), "test");
  const ThinShellModulus modulus;
  SampleBlock block(3);
  block.set_column("k", std::vector<double>{2.87, 1.2, 6.0});
  block.set_column("d", std::vector<double>{6.56 * um, 5.9 * um, 7.8 * um});
  block.set_column("d0", std::vector<double>{5.35 * um, 5.1 * um, 6.0 * um});
  block.set_column("h", std::vector<double>{145 * nm, 90 * nm, 300 * nm});
  const std::vector<const Evaluator*> closed_form{&turgor, &modulus};
  run_plan(closed_form, block);

  // A second block holding only the inputs and the closed form's p and E, through WallStress.
  SampleBlock wall(3);
  for (const char* name : {"k", "d", "d0", "h", "p", "E"}) wall.set_column(name, std::as_const(block).column(name));
  const WallStress stress;
  run_plan(std::vector<const Evaluator*>{&stress}, wall);
  for (std::size_t i = 0; i < 3; ++i) {
    CAPTURE(i);
    REQUIRE(block.status()[i] == SampleStatus::ok);
    CHECK(wall.status()[i] == SampleStatus::ok);
    CHECK(wall.column("hoop_stress")[i] == doctest::Approx(block.column("hoop_stress")[i]).epsilon(1e-15));
    CHECK(wall.column("wall_stiffness")[i] == doctest::Approx(block.column("wall_stiffness")[i]).epsilon(1e-14));
    CHECK(wall.column("lambda")[i] == doctest::Approx(block.column("lambda")[i]).epsilon(1e-15));
  }
}
