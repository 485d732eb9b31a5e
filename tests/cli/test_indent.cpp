// `growthuq indent` and `growthuq eval --fidelity shell_fe` end to end (coarse mesh): outputs
// read back and compared with the library, the inverse of the forward, one-line errors.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "fe/force_window.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/fe/indentation.hpp"
#include "growthuq/io/csv.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

// The `name = value` lines of a run.
std::map<std::string, std::string> values_of(const std::string& out) {
  std::map<std::string, std::string> values;
  std::size_t start = 0;
  while (start < out.size()) {
    const std::size_t end = out.find('\n', start);
    const std::string line = out.substr(start, end - start);
    const std::size_t equals = line.find(" = ");
    if (equals != std::string::npos && line[0] != '#') values[line.substr(0, equals)] = line.substr(equals + 3);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return values;
}

// k about 1.9 N/m: the curve reaches the window's top (4 uN) inside the automatic depth (see
// tests/fe/test_shell_fe_model.cpp).
constexpr const char* tube = "--p-MPa 0.45 --E-MPa 45 --h-nm 200 --d0-um 5.35 --rho-um 0.25 --mesh coarse";
constexpr const char* tube_any_mesh = "--p-MPa 0.45 --E-MPa 45 --h-nm 200 --d0-um 5.35 --rho-um 0.25";

}  // namespace

TEST_CASE("indent: the curve and the name = value lines, as the library computes them") {
  const ScratchDirectory scratch("indent_run");
  const CliOutcome run = run_cli(std::string("indent ") + tube + " --out curve.csv --field wall.xdmf", scratch.root);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  auto values = values_of(run.out);
  REQUIRE(values["status"] == "ok");
  for (const char* name : {"k_N_per_m", "d_um", "newton_iterations", "seconds"}) CHECK(values.count(name) == 1);

  // The library at the same input gives the same k and diameter (the CLI only converts units).
  // Not to the last bit: the CLI's conversions (0.45 * 1e6, L = 100 * 1e-6, ...) differ from
  // the library's defaults in the last bit, and such a change moves k by about 1e-4 (measured:
  // 6e-5), because the mesh and the load path make discrete choices (ring positions, step cuts,
  // penalty raises) that move with it; d, from the inflation alone (solved to 1e-8 of the force
  // scale), by about 1e-8. 1e-3 and 1e-6 still catch any wrong unit or option.
  IndentationInput input;
  input.pressure = 0.45 * 1e6;
  input.young = 45 * 1e6;
  input.thickness = 200 * 1e-9;
  input.plasmolysed_diameter = 5.35 * 1e-6;
  input.instrument.probe_radius_m = from_um(0.25);
  ShellFeOptions options;
  options.mesh = ShellFeMesh::coarse;
  const IndentationCurve curve = indent(input, options);
  REQUIRE(curve.status == SampleStatus::ok);
  const double k = parse_double(values["k_N_per_m"], "test", "k");
  CHECK(k == doctest::Approx(curve.stiffness).epsilon(1e-3));
  CHECK(parse_double(values["d_um"], "test", "d") == doctest::Approx(curve.turgid_diameter * 1e6).epsilon(1e-6));

  // The CSV's curve gives that k through the window fit (0.4-4 uN).
  const CsvTable table = read_csv((scratch.root / "curve.csv").string());
  REQUIRE(table.header.at(0) == "delta_um");
  REQUIRE(table.header.at(1) == "F_uN");
  const std::vector<double> delta = table.numeric_column("delta_um"), force = table.numeric_column("F_uN");
  const fe::WindowFit fit = fe::fit_force_window(delta, force, 0.4, 4.0);
  REQUIRE(fit.status == fe::WindowFitStatus::ok);
  CHECK(fit.slope == doctest::Approx(k).epsilon(1e-12));  // uN/um = N/m, the CLI's own k
  CHECK(fs::exists(scratch.root / "wall.xdmf"));
  CHECK(fs::exists(scratch.root / "wall.h5"));

  // Progress on stderr (not a terminal here: a line every 5 s, how many depends on the machine's
  // speed): "indent: nm of depth A/B, T s[, about L s left]", A rising towards B, the deepest an
  // automatic curve may go (0.6 d0 = 3210 nm), which it stops short of at the window's top.
  std::size_t previous = 0, lines = 0;
  for (std::size_t start = 0; (start = run.err.find("indent: nm of depth ", start)) != std::string::npos; ++start) {
    std::size_t reached = 0, total = 0;
    REQUIRE(std::sscanf(run.err.c_str() + start, "indent: nm of depth %zu/%zu,", &reached, &total) == 2);
    CHECK(total == 3210);
    CHECK(reached >= previous);
    CHECK(reached <= static_cast<std::size_t>(std::lround(delta.back() * 1e3)));
    previous = reached, ++lines;
  }
  MESSAGE(lines << " progress lines");

  // eval --fidelity shell_fe on the forward's k and d recovers p and E (tolerance as in
  // tests/fe/test_shell_fe_model.cpp: the load steps of two curves, 2e-3).
  const std::string eval = "eval --fidelity shell_fe --mesh coarse --rho-um 0.25 --h-nm 200 --d0-um 5.35 --k " +
                           values["k_N_per_m"] + " --d-um " + values["d_um"];
  const CliOutcome inverse = run_cli(eval, scratch.root);
  INFO(inverse.err);
  REQUIRE(inverse.exit_code == 0);
  CHECK(inverse.out.find("status: ok") != std::string::npos);
  // Not a silent wait: a line on stderr before the inverse starts.
  CHECK(inverse.err.starts_with("eval: inverting the tube with the finite-element shell inverse ("));
  const auto p_at = inverse.out.find("  p  ");
  REQUIRE(p_at != std::string::npos);
  const double p = parse_double(inverse.out.substr(p_at + 2 + 16, 22), "test", "p");
  CHECK(p == doctest::Approx(0.45).epsilon(2e-3));
}

TEST_CASE("eval --fidelity shell_fe: every tube of a file, a flagged tube with empty cells") {
  const ScratchDirectory scratch("indent_eval_file");
  std::ofstream(scratch.root / "tubes.csv") << "k_N_per_m,h_nm,d_um,d0_um\n2.0,200,6.4,5.35\n2.0,200,5.0,5.35\n";
  const CliOutcome run = run_cli("eval --fidelity shell_fe --mesh coarse --rho-um 0.25 --in tubes.csv --out results.csv", scratch.root);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  // The progress over the tubes ends with their count and time (stderr is no terminal here).
  CHECK(run.err.find("eval: 2 tubes in ") != std::string::npos);
  const CsvTable table = read_csv((scratch.root / "results.csv").string());
  REQUIRE(table.rows.size() == 2);
  const auto column = [&](const std::string& name) {
    for (std::size_t c = 0; c < table.header.size(); ++c) {
      if (table.header[c] == name) return c;
    }
    FAIL("no column " << name);
    return std::size_t{0};
  };
  CHECK(table.rows[0][column("status")] == "ok");
  CHECK(parse_double(table.rows[0][column("p_MPa")], "test", "p") > 0);
  CHECK(table.rows[1][column("status")] == "invalid_input");
  CHECK(table.rows[1][column("p_MPa")].empty());
  CHECK(table.rows[1][column("E_MPa")].empty());
}

TEST_CASE("indent and eval --fidelity: bad input is one line naming the flag, nothing written") {
  const ScratchDirectory scratch("indent_errors");
  const struct {
    std::string arguments, expected;
  } cases[] = {
      {"indent --p-MPa -1 --E-MPa 30 --h-nm 200 --d0-um 5.35 --rho-um 0.25 --out c.csv", "--p-MPa = '-1': expected a positive turgor in MPa"},
      {"indent --p-MPa 0.3 --E-MPa 30 --h-nm 200 --d0-um 5.35 --out c.csv", "--rho-um is required"},
      {"indent --p-MPa 0.3 --E-MPa 30 --h-nm 200 --h0-nm 180 --d0-um 5.35 --rho-um 0.25 --out c.csv", "give the wall thickness once"},
      {std::string("indent ") + tube + " --law cauchy --out c.csv", "--law = 'cauchy': expected log"},
      {std::string("indent ") + tube_any_mesh + " --mesh medium --out c.csv", "--mesh = 'medium': expected coarse, default, fine or finer"},
      {std::string("indent ") + tube + " --substrate yes --out c.csv", "--substrate = 'yes': expected on or off"},
      {std::string("indent ") + tube + " --window-uN 4,0.4 --out c.csv", "--window-uN = '4,0.4'"},
      {std::string("indent ") + tube + " --nu 0.6 --out c.csv", "--nu = '0.6': expected a Poisson ratio in [0, 0.5)"},
      {std::string("indent ") + tube + " --depth-um 9 --out c.csv", "--depth-um = '9': expected a depth in [0, d0]"},
      {std::string("indent ") + tube + " --field wall.vtk --out c.csv", "--field = 'wall.vtk': expected a file name ending in .xdmf"},
      {std::string("indent ") + tube, "missing --out"},
      {std::string("indent ") + tube + " --stabilisation-fraction -0.1 --out c.csv",
       "--stabilisation-fraction = '-0.1': expected a non-negative dissipated-energy fraction"},
      {std::string("indent ") + tube + " --stabilisation-fraction 2e-4 --stabilisation-ratio 1.5 --out c.csv",
       "--stabilisation-ratio = '1.5': expected an adaptive damping ratio in [0, 1)"},
      {std::string("indent ") + tube + " --stabilisation-ratio 0.05 --out c.csv",
       "--stabilisation-ratio = '0.05': expected 0 unless a stabilisation fraction above 0 is given"},
      {std::string("indent ") + tube + " --stabilisation-fraction 2e-4 --stabilisation-energy total --out c.csv",
       "--stabilisation-energy = 'total': expected model"},
      {"eval --fidelity fast --rho-um 0.25 --k 2 --d-um 6.4 --d0-um 5.35 --h-nm 200", "--fidelity = 'fast': expected closed_form (the thin shell's closed forms"},
      {"eval --law stvk --rho-um 0.25 --k 2 --d-um 6.4 --d0-um 5.35", "--law needs --fidelity shell_fe"},
      {"eval --fidelity shell_fe --rho-um 0.25 --k 2 --d-um 6.4 --d0-um 5.35", "--h-nm is required with --fidelity shell_fe"},
  };
  for (const auto& c : cases) {
    INFO(c.arguments);
    const CliOutcome run = run_cli(c.arguments, scratch.root);
    CHECK(run.exit_code == 2);
    CHECK(run.err.find(c.expected) != std::string::npos);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
    CHECK(!fs::exists(scratch.root / "c.csv"));
  }
  // An existing curve is not replaced without --force.
  std::ofstream(scratch.root / "c.csv") << "keep\n";
  const CliOutcome refused = run_cli(std::string("indent ") + tube + " --out c.csv", scratch.root);
  CHECK(refused.exit_code == 2);
  CHECK(refused.err.find("--force") != std::string::npos);
}

TEST_CASE("indent --stabilisation-fraction: the energies the library records, printed at the deepest point") {
  const ScratchDirectory scratch("indent_stabilised");
  const std::string flags = " --stabilisation-fraction 2e-2 --stabilisation-ratio 0.05";
  const CliOutcome run = run_cli(std::string("indent ") + tube + flags + " --depth-um 1.5 --quiet --out curve.csv", scratch.root);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(run.out.find("viscous stabilisation: fraction 0.02 of the model strain energy, capped at 0.05") != std::string::npos);
  auto values = values_of(run.out);
  IndentationInput input;
  input.pressure = 0.45 * 1e6;
  input.young = 45 * 1e6;
  input.thickness = 200 * 1e-9;
  input.plasmolysed_diameter = 5.35 * 1e-6;
  input.depth = 1.5e-6;
  input.instrument.probe_radius_m = from_um(0.25);
  ShellFeOptions options;
  options.mesh = ShellFeMesh::coarse;
  options.stabilisation = {.fraction = 2e-2, .ratio = 0.05};
  // Short of the window's top (so no k), still a curve to 1.5 um with its energies.
  const IndentationCurve curve = indent(input, options);
  REQUIRE(curve.strain_energy.size() == curve.depth.size());
  REQUIRE(curve.depth.back() == doctest::Approx(1.5e-6).epsilon(1e-12));
  // The library's energies in pJ, to the unit conversions' last bits (see the first case), which
  // move the model's strain energy by 1e-5, what the indentation stores (a difference of terms
  // a hundred times larger) by 6e-4 and the dissipated energy by 2e-3 (measured; c comes from
  // the first 0.5 nm increment, where the contact's first node is decided by such bits). Any
  // wrong unit (1e3, 1e6) or missing factor (the half model's 2) misses by far more.
  const double stored = curve.strain_energy.back() + curve.pressure_energy.back() - curve.strain_energy.front() -
                        curve.pressure_energy.front();
  const auto relative = [&](const char* name, double library_J) {
    return std::fabs(parse_double(values[name], "test", name) / (library_J * 1e12) - 1.0);
  };
  std::printf("stabilised indent: strain %.3e stored %.3e dissipated %.3e relative to the library (dissipated %.4g pJ "
              "of %.4g stored)\n", relative("strain_energy_pJ", curve.strain_energy.back()),
              relative("stored_by_indentation_pJ", stored), relative("dissipated_energy_pJ", curve.dissipated_energy.back()),
              curve.dissipated_energy.back() * 1e12, stored * 1e12);
  REQUIRE(curve.dissipated_energy.back() > 1e-3 * stored);
  CHECK(relative("strain_energy_pJ", curve.strain_energy.back()) < 1e-4);
  CHECK(relative("stored_by_indentation_pJ", stored) < 3e-3);
  CHECK(relative("dissipated_energy_pJ", curve.dissipated_energy.back()) < 1e-2);
}

TEST_CASE("indent --field: the curve and the field commit together, so a field that fails leaves no curve") {
  const ScratchDirectory scratch("indent_field_together");
  // The field's temporary file cannot be made (a folder in its place): found only after the
  // simulation, when the curve is already written.
  std::filesystem::create_directories(scratch.root / "wall.h5.partial");
  const CliOutcome run = run_cli(std::string("indent ") + tube + " --out curve.csv --field wall.xdmf --quiet", scratch.root);
  CHECK(run.exit_code == 2);
  CHECK(run.err == "growthuq indent: error: wall.h5.partial: is a directory: expected no file there (the temporary file a "
                   "result is written to before it is renamed into place)\n");
  CHECK(!std::filesystem::exists(scratch.root / "curve.csv"));  // it was kept without its field
  CHECK(!std::filesystem::exists(scratch.root / "curve.csv.partial"));
  CHECK(!std::filesystem::exists(scratch.root / "wall.xdmf"));
}

TEST_CASE("indent --help tells the defaults and what h means") {
  const ScratchDirectory scratch("indent_help");
  const CliOutcome help = run_cli("indent --help", scratch.root);
  REQUIRE(help.exit_code == 0);
  CHECK(help.out.rfind("usage: growthuq indent", 0) == 0);
  // The option descriptions are wrapped at 80 columns: compare with blanks collapsed.
  std::string text_of_help;
  for (char c : help.out) {
    const bool blank = c == ' ' || c == '\n';
    if (!blank || (!text_of_help.empty() && text_of_help.back() != ' ')) text_of_help += blank ? ' ' : c;
  }
  for (const char* text : {"TURGID", "(default 100;", "(default 10;", "0.4,4)", "coarse, default or fine (omitted: default", "(default 0.2"}) {
    INFO(text);
    CHECK(text_of_help.find(text) != std::string::npos);
  }
}
