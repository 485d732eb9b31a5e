// Digits at the smallest stretch of the envelope, lambda - 1 = 1e-12: the inverse's p and E
// from diameters given in um, against an independent computation in long double from the same
// numbers in um. Converting d and d0 to metres before forming d - d0 would cost about 1e-4 of
// p and E there (each conversion rounds a diameter by up to half an ulp, and d - d0 is 1e-12 of
// it); the library, the evaluators, `growthuq eval` (flags and files) and a campaign all form
// the stretch in the unit the diameters were given in.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/mechanics/thin_shell.hpp"
#include "growthuq/mechanics/thin_shell_evaluators.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;

namespace {

struct Tube {
  double k;      // N/m
  double d_um;
  double d0_um;
  double h_nm;
};

constexpr double rho_um = 0.5;
constexpr double nu = 0.2;

// phi(x) = x K1(x)/K0(x) for large x from the asymptotic series of K0 and K1 (Abramowitz &
// Stegun 9.7.2: K_v(x) ~ sqrt(pi/(2x)) e^-x sum_k a_k(v) / x^k, a_k(v) = prod_{j=1..k}
// (4v^2 - (2j-1)^2) / (k! 8^k)); at x > 1e4 the terms after x^-5 are below 1e-24.
long double phi_large_x(long double x) {
  long double k0 = 1, k1 = 1, a0 = 1, a1 = 1;
  for (int k = 1; k <= 6; ++k) {
    const long double odd = 2.0L * k - 1;
    a0 *= (0.0L - odd * odd) / (k * 8.0L * x);
    a1 *= (4.0L - odd * odd) / (k * 8.0L * x);
    k0 += a0;
    k1 += a1;
  }
  return x * k1 / k0;
}

struct Reference {
  long double p;  // Pa
  long double E;  // Pa
};

// Relations 1 and 2 (src/mechanics/README.md, M1-M5) in long double from the numbers in um, nm.
Reference reference(const Tube& tube) {
  const long double strain = (static_cast<long double>(tube.d_um) - tube.d0_um) / tube.d0_um;
  const long double ln_lambda = std::log1p(strain);
  const long double q = (1.0L - static_cast<long double>(nu) * nu) * ln_lambda;
  const long double d = tube.d_um * 1e-6L;
  const long double alpha = d * std::sqrt(3.0L * q / (16.0L * (1.0L - q)));
  const long double x = rho_um * 1e-6L / alpha;
  REQUIRE(x > 1e4L);  // the series' range
  const long double p = 4.0L * tube.k / (3.0L * std::numbers::pi_v<long double> * d * phi_large_x(x));
  return {p, p * d / (2.0L * tube.h_nm * 1e-9L * ln_lambda)};
}

double relative_error(double value, long double reference) {
  return static_cast<double>(std::fabs((value - reference) / reference));
}

// Tubes at lambda - 1 = 1e-12 (to the double nearest d0 (1 + 1e-12)) with diameters whose
// conversion to metres rounds: the stretch formed in metres is off by 1e-5 to 1e-4 for each.
std::vector<Tube> tubes_at_the_edge() {
  std::vector<Tube> tubes;
  for (const double d0_um : {4.51, 5.35, 6.56, 7.13}) tubes.push_back({2.87, d0_um * (1 + 1e-12), d0_um, 145});
  return tubes;
}

// The stretch one rounding of each conversion loses, for the test's premise.
double strain_error_in_metres(const Tube& tube) {
  const double d = tube.d_um * 1e-6, d0 = tube.d0_um * 1e-6;
  const long double exact = (static_cast<long double>(tube.d_um) - tube.d0_um) / tube.d0_um;
  return static_cast<double>(std::fabs(((d - d0) / d0 - exact) / exact));
}

// The two places in `text` after "  <name> " (eval's table), read back.
double printed(const std::string& text, const std::string& name) {
  const std::size_t at = text.find("\n  " + name + " ");
  REQUIRE(at != std::string::npos);
  std::istringstream line(text.substr(at + 3 + name.size()));
  double value = 0;
  line >> value;
  return value;
}

}  // namespace

TEST_CASE("stretch 1e-12: p and E from diameters in um agree with long double to 1e-14") {
  Instrument instrument;
  instrument.probe_radius_m = rho_um * 1e-6;
  instrument.poisson_ratio = nu;
  for (const Tube& tube : tubes_at_the_edge()) {
    CAPTURE(tube.d0_um);
    const Reference expected = reference(tube);
    CHECK(strain_error_in_metres(tube) > 1e-6);  // the conversion does lose digits here

    const TubeDiameters diameters = measured_diameters(tube.d_um, unit_factor::um, tube.d0_um, unit_factor::um);
    const TurgorResult turgor = invert_turgor(tube.k, diameters, instrument);
    REQUIRE(turgor.status == SampleStatus::ok);
    const ModulusResult modulus = invert_modulus(turgor.p, diameters, tube.h_nm * 1e-9);
    REQUIRE(modulus.status == SampleStatus::ok);
    CHECK(relative_error(turgor.p, expected.p) < 1e-14);
    CHECK(relative_error(modulus.E, expected.E) < 1e-14);

    // The evaluators, given the strain formed where the diameters came in.
    SampleBlock block(1);
    block.set_column("k", std::vector<double>{tube.k});
    block.set_column("d", std::vector<double>{from_um(tube.d_um)});
    block.set_column("d0", std::vector<double>{from_um(tube.d0_um)});
    block.set_column("h", std::vector<double>{from_nm(tube.h_nm)});
    add_hoop_strain(block, std::vector<double>{tube.d_um}, unit_factor::um, std::vector<double>{tube.d0_um}, unit_factor::um);
    const ThinShellTurgor turgor_model(instrument, "test");
    const ThinShellModulus modulus_model;
    evaluate_checked(turgor_model, block);
    evaluate_checked(modulus_model, block);
    REQUIRE(block.status()[0] == SampleStatus::ok);
    CHECK(relative_error(block.column("p")[0], expected.p) < 1e-14);
    CHECK(relative_error(block.column("E")[0], expected.E) < 1e-14);
    CHECK(block.column("lambda")[0] == 1.0 + diameters.strain);
  }
}

TEST_CASE("stretch 1e-12: growthuq eval, from flags and from a file, and a campaign keep the digits") {
  const ScratchDirectory scratch("mechanics_digits");
  std::string tubes_csv = "k_N_per_m,d_um,d0_um,h_nm\n";
  for (const Tube& tube : tubes_at_the_edge()) {
    CAPTURE(tube.d0_um);
    const Reference expected = reference(tube);
    const CliOutcome point =
        run_cli("eval --rho-um 0.5 --nu 0.2 --k " + format_double(tube.k) + " --d-um " + format_double(tube.d_um) +
                    " --d0-um " + format_double(tube.d0_um) + " --h-nm " + format_double(tube.h_nm),
                scratch.root);
    REQUIRE(point.exit_code == 0);
    // Printed in MPa, shortest round trip: one more rounding.
    CHECK(relative_error(printed(point.out, "p") * 1e6, expected.p) < 1e-14);
    CHECK(relative_error(printed(point.out, "E") * 1e6, expected.E) < 1e-14);
    tubes_csv += format_double(tube.k) + "," + format_double(tube.d_um) + "," + format_double(tube.d0_um) + "," +
                 format_double(tube.h_nm) + "\n";
  }
  spit(scratch.root / "tubes.csv", tubes_csv);
  REQUIRE(run_cli("eval --rho-um 0.5 --nu 0.2 --in tubes.csv --out results.csv", scratch.root).exit_code == 0);
  const CsvTable results = read_csv((scratch.root / "results.csv").string());
  const std::vector<Tube> tubes = tubes_at_the_edge();
  for (std::size_t i = 0; i < tubes.size(); ++i) {
    const Reference expected = reference(tubes[i]);
    CHECK(relative_error(results.numeric_column("p_MPa")[i] * 1e6, expected.p) < 1e-14);
    CHECK(relative_error(results.numeric_column("E_MPa")[i] * 1e6, expected.E) < 1e-14);
  }

  // A campaign whose d and d0 are drawn from narrow ranges 1e-12 apart: every sample's p and E
  // against the reference from its own d_um, d0_um (samples.csv writes them exactly).
  spit(scratch.root / "edge.ini",
       "[line]\nname = edge\n\n"
       "[k]\nlaw = uniform\nlower = 2\nupper = 3\nunit = N/m\nsource = illustrative\nnote = test\n\n"
       "[h]\nlaw = uniform\nlower = 140\nupper = 150\nunit = nm\nsource = illustrative\nnote = test\n\n"
       "[d]\nlaw = uniform\nlower = 5.35000000001\nupper = 5.35000000002\nunit = um\nsource = illustrative\nnote = test\n\n"
       "[d0]\nlaw = uniform\nlower = 5.35\nupper = 5.350000000005\nunit = um\nsource = illustrative\nnote = test\n");
  spit(scratch.root / "edge_campaign.ini",
       "[campaign]\nname = edge\nseed = 7\nsamples = 40\noutputs = p, E\noutput_dir = out\nformats = csv\n\n"
       "[instrument]\nprobe_radius_um = 0.5\npoisson_ratio = 0.2\n\n[line edge]\ndistributions = edge.ini\n");
  const CliOutcome run = run_cli("run edge_campaign.ini --quiet", scratch.root);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const CsvTable samples = read_csv((scratch.root / "out" / "samples.csv").string());
  const std::vector<double> k = samples.numeric_column("k_N_per_m"), h = samples.numeric_column("h_nm");
  const std::vector<double> d = samples.numeric_column("d_um"), d0 = samples.numeric_column("d0_um");
  const std::vector<double> p = samples.numeric_column("p_MPa"), E = samples.numeric_column("E_MPa");
  REQUIRE(p.size() == 40);
  double worst_p = 0, worst_E = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Reference expected = reference({k[i], d[i], d0[i], h[i]});
    worst_p = std::max(worst_p, relative_error(p[i] * 1e6, expected.p));
    worst_E = std::max(worst_E, relative_error(E[i] * 1e6, expected.E));
  }
  CHECK(worst_p < 1e-14);
  CHECK(worst_E < 1e-14);
}
