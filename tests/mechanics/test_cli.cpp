// `growthuq eval` and `growthuq correlate` end to end: the built executable run on files in a
// scratch folder, outputs read back and compared with the library and with reference values;
// eval's refusals name the flag typed.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include "growthuq/core/numbers.hpp"
#include "growthuq/correction/corrected_closed_form.hpp"
#include "growthuq/correlation/matrix_file.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/mechanics/mechanical_correlation.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

// A fresh scratch folder per test case, removed at the end, where the CLI runs on files put there.
class Scratch {
 public:
  explicit Scratch(const std::string& name) : directory_("mechanics_" + name) {}
  fs::path file(const std::string& name, const std::string& content = "") const {
    if (!content.empty()) std::ofstream(directory_.root / name) << content;
    return directory_.root / name;
  }
  CliOutcome run(const std::string& arguments) const { return run_cli(arguments, directory_.root); }

 private:
  ScratchDirectory directory_;
};

double relative_error(double value, double reference) { return std::fabs(value - reference) / std::fabs(reference); }

// One tube inside the correction's envelope, through eval --fidelity corrected.
constexpr const char* corrected_tube = "eval --fidelity corrected --rho-um 0.25 --k 2 --d-um 6.4 --d0-um 5.35 --h-nm 200";

struct Refusal {
  std::string flags, message;
};

// `corrected_tube` with each refusal's flags added: exit code 2 and one line, the message
// right after the command.
void check_corrected_refusals(const Scratch& scratch, std::initializer_list<Refusal> refusals) {
  for (const Refusal& refusal : refusals) {
    CAPTURE(refusal.flags);
    const CliOutcome run = scratch.run(std::string(corrected_tube) + " " + refusal.flags);
    CAPTURE(run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.err.rfind("growthuq eval: error: " + refusal.message, 0) == 0);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  }
}

}  // namespace

TEST_CASE("eval: one tube from flags prints every output with its unit") {
  const Scratch scratch("eval_point");
  const CliOutcome run = scratch.run("eval --rho-um 0.5 --k 2.87 --d-um 6.56 --d0-um 5.35 --h-nm 145");
  REQUIRE(run.exit_code == 0);
  // Values: the 40-digit reference of test_thin_shell.cpp, in MPa and um.
  CHECK(run.out.find("  p               0.2528077871117") != std::string::npos);
  CHECK(run.out.find("MPa   turgor pressure") != std::string::npos);
  CHECK(run.out.find("  E               28.047344773892") != std::string::npos);
  CHECK(run.out.find("  alpha           1.401340457848") != std::string::npos);
  CHECK(run.out.find("um    Arnoldi decay length") != std::string::npos);
  CHECK(run.out.find("wall_stiffness") != std::string::npos);
  CHECK(run.out.find("status: ok") != std::string::npos);

  const CliOutcome no_stretch = scratch.run("eval --rho-um 0.5 --k 2.87 --d-um 5 --d0-um 5.35");
  CHECK(no_stretch.exit_code == 0);
  CHECK(no_stretch.out.find("status: lambda_not_above_one") != std::string::npos);
  CHECK(no_stretch.out.find("nan") == std::string::npos);
  CHECK(no_stretch.out.find("E  ") == std::string::npos);  // no thickness, no modulus
}

TEST_CASE("eval: bad flags are one-line errors with exit code 2") {
  const Scratch scratch("eval_flags");
  const CliOutcome no_rho = scratch.run("eval --k 2.87 --d-um 6.56 --d0-um 5.35");
  CHECK(no_rho.exit_code == 2);
  CHECK(no_rho.err.find("--rho-um is required") != std::string::npos);
  const CliOutcome text = scratch.run("eval --rho-um 0.5 --k abc --d-um 6.56 --d0-um 5.35");
  CHECK(text.exit_code == 2);
  CHECK(text.err.find("--k = 'abc': expected a finite number") != std::string::npos);
  const CliOutcome negative = scratch.run("eval --rho-um 0.5 --k 2 --d-um -6 --d0-um 5.35");
  CHECK(negative.exit_code == 2);
  CHECK(negative.err.find("--d-um = '-6': expected a positive diameter in um") != std::string::npos);
  const CliOutcome nu = scratch.run("eval --rho-um 0.5 --k 2 --d-um 6 --d0-um 5 --nu 1.5");
  CHECK(nu.exit_code == 2);
  CHECK(nu.err.find("--nu = '1.5'") != std::string::npos);
  const CliOutcome mixed = scratch.run("eval --rho-um 0.5 --k 2 --in tubes.csv --out r.csv");
  CHECK(mixed.exit_code == 2);
  CHECK(mixed.err.find("--k cannot be combined with --in") != std::string::npos);
}

TEST_CASE("eval --fidelity corrected runs the campaign's evaluator: its p and E, and the wall stresses from them") {
  const Scratch scratch("eval_corrected_values");
  const CliOutcome run = scratch.run(corrected_tube);
  CAPTURE(run.err);
  REQUIRE(run.exit_code == 0);
  const auto value = [&](const std::string& quantity) {
    const auto at = run.out.find("  " + quantity + " ");
    REQUIRE(at != std::string::npos);
    return parse_double(run.out.substr(at + 2 + 16, 22), "test", quantity);
  };
  // The library's corrected inverse of the same tube (corrected_closed_form.hpp).
  Instrument instrument;
  instrument.probe_radius_m = 0.25e-6;
  const CorrectedInverse reference =
      corrected_inverse(2.0, diameters_in_si(6.4e-6, 5.35e-6), 200e-9, instrument, {0.4e-6, 4e-6}, shipped_correction());
  REQUIRE(reference.status == SampleStatus::ok);
  CHECK(value("p") == doctest::Approx(reference.p * 1e-6).epsilon(1e-10));
  CHECK(value("E") == doctest::Approx(reference.E * 1e-6).epsilon(1e-10));
  // Hoop equilibrium p d / (2 h) and E h from the corrected p and E, not the closed form's.
  CHECK(value("hoop_stress") == doctest::Approx(value("p") * 6.4e3 / (2 * 200)).epsilon(1e-10));
  CHECK(value("wall_stiffness") == doctest::Approx(value("E") * 1e6 * 200e-9).epsilon(1e-10));
  CHECK(value("lambda") == doctest::Approx(6.4 / 5.35).epsilon(1e-10));
  CHECK(run.out.find("  alpha") == std::string::npos);  // the closed form's own
  // The campaign's old name of the closed form is eval's too.
  const CliOutcome old_name = scratch.run("eval --fidelity thin_shell --rho-um 0.5 --k 2.87 --d-um 6.56 --d0-um 5.35");
  CHECK(old_name.exit_code == 0);
  CHECK(old_name.out.find("  p               0.2528077871117") != std::string::npos);
}

TEST_CASE("eval --fidelity corrected: a model option the correction was not fitted for is refused by its flag") {
  const Scratch scratch("eval_corrected_flags");
  // The flag right after the command, as typed: not the campaign key (law, poisson_ratio, ...).
  check_corrected_refusals(scratch, {
      {"--law stvk", "--law = 'stvk': expected log, the value fidelity corrected was fitted for"},
      {"--geometry sphere", "--geometry = 'sphere': expected tube"},
      {"--substrate off", "--substrate = 'off': expected on,"},
      {"--bending off", "--bending = 'off': expected on,"},
      {"--tube-length-um 80", "--tube-length-um = '80': expected 100,"},
      {"--probe-distance-um 20", "--probe-distance-um = '20': expected 10,"},
      {"--window-uN 2,3", "--window-uN = '2,3': expected a force window whose bottom is 0.05 to 0.5 of its top"},
      {"--nu 0.3", "--nu = '0.3': expected 0.2,"},
  });
  // The options it was fitted for, stated or not, give a value.
  const CliOutcome fitted = scratch.run(std::string(corrected_tube) + " --law log --substrate on --window-uN 0.4,4 --nu 0.2");
  CAPTURE(fitted.err);
  CHECK(fitted.exit_code == 0);
}

TEST_CASE("eval's model flags: the [shell_fe] section's parsers and messages, by the flag's name") {
  const Scratch scratch("eval_model_flags");
  check_corrected_refusals(scratch, {
      {"--half-model maybe", "--half-model = 'maybe': expected on or off"},
      {"--tube-length-um 4", "--tube-length-um = '4': expected a tube length in [5, 1e6] um (default 100)"},
      {"--tube-length-um 20 --probe-distance-um 30",
       "--probe-distance-um = '30': expected the probe's distance behind the apex in [0, tube_length) um (default 10)"},
      {"--window-uN 4", "--window-uN = '4': expected two forces 'LOW,HIGH' in uN with 0 <= LOW < HIGH (default 0.4,4)"},
      {"--window-uN 4,0.4", "--window-uN = '4,0.4': expected two forces 'LOW,HIGH'"},
      {"--window-uN 0.4,x", "--window-uN = '0.4,x': expected two forces 'LOW,HIGH'"},
  });
}

TEST_CASE("eval: a file of tubes gets outputs, empty cells and a status per row") {
  const Scratch scratch("eval_file");
  scratch.file("tubes.csv",
               "# two wild-type-like tubes, one unstretched, one bad stiffness, one bad thickness, one\n"
               "# stretched past lambda = e (2.79, on the unstable branch)\n"
               "tube,k_N_per_m,h_nm,d_um,d0_um\n"
               "A,2.87,145,6.56,5.35\n"
               "\"B,2\",1.95,199,5.32,4.51\n"
               "C,2.0,150,5.0,5.35\n"
               "D,-1,150,6,5\n"
               "E,2,0,6,5\n"
               "F,2.87,145,14.5,5.2\n");
  const CliOutcome run = scratch.run("eval --in tubes.csv --out results.csv --rho-um 0.5");
  REQUIRE(run.exit_code == 0);
  CHECK(run.out.find("lambda_not_above_one        1") != std::string::npos);
  CHECK(run.out.find("unstable_branch             1") != std::string::npos);
  const CsvTable results = read_csv(scratch.file("results.csv").string());
  const std::vector<std::string> header{"tube", "k_N_per_m", "h_nm", "d_um", "d0_um", "p_MPa", "E_MPa", "alpha_um",
                                        "phi", "lambda", "hoop_stress_MPa", "wall_stiffness_N_per_m", "status"};
  CHECK(results.header == header);
  REQUIRE(results.rows.size() == 6);
  CHECK(results.rows[1][0] == "B,2");  // text columns pass through, quoted as needed
  CHECK(relative_error(parse_double(results.rows[0][5], "", ""), 0.25280778711172389726) < 1e-13);
  CHECK(relative_error(parse_double(results.rows[0][6], "", ""), 28.047344773892977043) < 1e-13);
  const std::vector<std::string> statuses{"ok",           "ok",           "lambda_not_above_one",
                                          "invalid_input", "invalid_input", "unstable_branch"};
  for (std::size_t row = 0; row < 6; ++row) {
    CHECK(results.rows[row][12] == statuses[row]);
    for (std::size_t column = 5; column < 12; ++column) {
      CHECK(results.rows[row][column].empty() == (statuses[row] != "ok"));
    }
  }
  CHECK(slurp(scratch.file("results.csv")).find("nan") == std::string::npos);

  // Existing output: refused without --force, replaced with it.
  const CliOutcome again = scratch.run("eval --in tubes.csv --out results.csv --rho-um 0.5");
  CHECK(again.exit_code == 2);
  CHECK(again.err.find("--force") != std::string::npos);
  CHECK(scratch.run("eval --in tubes.csv --out results.csv --rho-um 1 --force").exit_code == 0);
  const CsvTable replaced = read_csv(scratch.file("results.csv").string());
  CHECK(parse_double(replaced.rows[0][5], "", "") < parse_double(results.rows[0][5], "", ""));

  // Without h: turgor outputs only; other units of a column are converted.
  scratch.file("turgor.csv", "k_N_per_m,d_mm,d0_um\n2.87,0.00656,5.35\n");
  REQUIRE(scratch.run("eval --in turgor.csv --out turgor_results.csv --rho-um 0.5").exit_code == 0);
  const CsvTable turgor = read_csv(scratch.file("turgor_results.csv").string());
  const std::vector<std::string> turgor_header{"k_N_per_m", "d_mm", "d0_um", "p_MPa", "alpha_um", "phi", "lambda", "status"};
  CHECK(turgor.header == turgor_header);
  CHECK(relative_error(parse_double(turgor.rows[0][3], "", ""), 0.25280778711172389726) < 1e-13);
}

TEST_CASE("eval: bad files name the file, the line and the column") {
  const Scratch scratch("eval_bad");
  scratch.file("missing_column.csv", "k_N_per_m,d_um\n2.87,6.56\n");
  const CliOutcome missing = scratch.run("eval --in missing_column.csv --out r.csv --rho-um 0.5");
  CHECK(missing.exit_code == 2);
  CHECK(missing.err.find("missing_column.csv: no column for plasmolysed diameter: expected 'd0_um'") != std::string::npos);
  scratch.file("text_cell.csv", "k_N_per_m,d_um,d0_um\n2.87,6.56,5.35\n2.1,abc,5\n");
  const CliOutcome text = scratch.run("eval --in text_cell.csv --out r.csv --rho-um 0.5");
  CHECK(text.exit_code == 2);
  CHECK(text.err.find("text_cell.csv:3: column d_um = 'abc': expected a finite number") != std::string::npos);
  scratch.file("ragged.csv", "k_N_per_m,d_um,d0_um\n2.87,6.56\n");
  CHECK(scratch.run("eval --in ragged.csv --out r.csv --rho-um 0.5").exit_code == 2);
  scratch.file("clash.csv", "k_N_per_m,d_um,d0_um,p_MPa\n2.87,6.56,5.35,1\n");
  const CliOutcome clash = scratch.run("eval --in clash.csv --out r.csv --rho-um 0.5");
  CHECK(clash.exit_code == 2);
  CHECK(clash.err.find("already has a column 'p_MPa'") != std::string::npos);
  CHECK(!fs::exists(scratch.file("r.csv")));
}

TEST_CASE("correlate: writes the matrix `sample` reads, equal to the library's") {
  const Scratch scratch("correlate");
  const CliOutcome run = scratch.run("correlate --rho-um 0.5 --samples 4000 --seed 3 --out matrix.csv");
  REQUIRE(run.exit_code == 0);
  CHECK(run.out.find("burst (p d0 / (2 h E) > 1/e), dropped: ") != std::string::npos);
  const RankCorrelationFile file = read_rank_correlation_csv(scratch.file("matrix.csv").string());
  const std::vector<std::string> names{"k", "h", "d", "d0"};
  CHECK(file.names == names);
  MechanicalDrawOptions options;
  options.samples = 4000;
  options.seed = 3;
  Instrument shell;
  shell.probe_radius_m = 0.5e-6;
  const MechanicalCorrelation expected = mechanical_rank_correlation(options, shell, "test");
  CHECK((file.spearman - expected.spearman).cwiseAbs().maxCoeff() == 0.0);  // shortest round-trip text
  CHECK(run.out.find("burst (p d0 / (2 h E) > 1/e), dropped: " + std::to_string(expected.burst)) != std::string::npos);

  CHECK(scratch.run("correlate --rho-um 0.5 --samples 4000 --seed 3 --out matrix.csv").exit_code == 2);

  // The same settings from a config file give the same matrix; flags override the file.
  scratch.file("ranges.ini", "# physiological ranges\np-MPa = 0.1:0.8\nE-MPa = 5:200\nh-nm = 100:300\n"
                             "d0-um = 4:8\nsamples = 4000\nseed = 3\nrho-um = 0.5\n");
  REQUIRE(scratch.run("correlate --config ranges.ini --out from_config.csv").exit_code == 0);
  CHECK(slurp(scratch.file("from_config.csv")) == slurp(scratch.file("matrix.csv")));
  REQUIRE(scratch.run("correlate --config ranges.ini --seed 4 --out seed4.csv").exit_code == 0);
  CHECK(slurp(scratch.file("seed4.csv")) != slurp(scratch.file("matrix.csv")));
}

TEST_CASE("correlate: bad ranges and config files are one-line errors") {
  const Scratch scratch("correlate_bad");
  const CliOutcome reversed = scratch.run("correlate --rho-um 0.5 --p-MPa 0.8:0.1");
  CHECK(reversed.exit_code == 2);
  CHECK(reversed.err.find("p-MPa = '0.8:0.1': expected LOW:HIGH with numbers 0 < LOW < HIGH") != std::string::npos);
  const CliOutcome no_rho = scratch.run("correlate");
  CHECK(no_rho.exit_code == 2);
  CHECK(no_rho.err.find("--rho-um is required") != std::string::npos);
  scratch.file("bad_value.ini", "rho-um = 0.5\n\nE-MPa = 5-200\n");
  const CliOutcome bad_value = scratch.run("correlate --config bad_value.ini");
  CHECK(bad_value.exit_code == 2);
  CHECK(bad_value.err.find("bad_value.ini:3: E-MPa = '5-200': expected LOW:HIGH") != std::string::npos);
  scratch.file("unknown.ini", "rho-um = 0.5\nturgor = 0.3\n");
  const CliOutcome unknown = scratch.run("correlate --config unknown.ini");
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.err.find("unknown.ini") != std::string::npos);
  CHECK(unknown.err.find("turgor") != std::string::npos);
  const CliOutcome all_burst = scratch.run("correlate --rho-um 0.5 --p-MPa 1.5:2 --E-MPa 1:2 --samples 100");
  CHECK(all_burst.exit_code == 2);
  CHECK(all_burst.err.find("0 of 100 drawn tubes hold their turgor") != std::string::npos);
}
