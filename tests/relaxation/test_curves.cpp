// Curve files (strict validation with file:line messages) and `growthuq relax` run as a
// program on simulated curves written here and on bad files.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/distributions/fit.hpp"
#include "growthuq/evaluation/sample_block.hpp"
#include "growthuq/growth/viscosity.hpp"
#include "growthuq/io/csv.hpp"
#include "io/ini.hpp"
#include "growthuq/relaxation/curves.hpp"
#include "growthuq/relaxation/simulator.hpp"

using namespace growthuq;
namespace fs = std::filesystem;

namespace {

class Folder {
 public:
  Folder() : path_(fs::temp_directory_path() / ("growthuq_relax_" + std::to_string(std::rand()) + "_" +
                                                 std::to_string(reinterpret_cast<std::uintptr_t>(this)))) {
    fs::create_directories(path_);
  }
  ~Folder() { fs::remove_all(path_); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name) << text;
    return (path_ / name).string();
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string read(const std::string& name) const {
    std::ifstream in(path_ / name);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

 private:
  fs::path path_;
};

// A curve of n samples: t = 0.01 j, F = 5 - 0.01 j uN (a fake but valid record).
std::string rows(const std::string& name, int n, double t0 = 0.0) {
  std::string text;
  for (int j = 0; j < n; ++j) {
    text += name + "," + format_double(t0 + 0.01 * j) + "," + format_double(5.0 - 0.01 * j) + "\n";
  }
  return text;
}

const std::string meta_header = "curve,delta_um,p_MPa,d_um,h_nm,rho_um\n";

std::string error_of(const std::string& curves, const std::string& meta,
                     std::optional<double> probe_radius = std::nullopt) {
  try {
    read_relaxation_curves(curves, meta, probe_radius);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

struct Run {
  int status;
  std::string out, err;
};

Run relax(const Folder& folder, const std::string& arguments) {
  const std::string command = "cd '" + folder.file("") + "' && '" + GROWTHUQ_CLI + "' relax " + arguments +
                              " >stdout.txt 2>stderr.txt";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, folder.read("stdout.txt"), folder.read("stderr.txt")};
}

}  // namespace

TEST_CASE("curves: long format with a metadata file, curves interleaved") {
  Folder folder;
  // Rows of a and b interleaved: each curve keeps its own order.
  std::string text = "curve,t_s,F_uN\n";
  for (int j = 0; j < 25; ++j) {
    text += "a," + format_double(0.01 * j) + ",1\n";
    text += "b," + format_double(0.02 * j) + ",2\n";
  }
  const auto curves = folder.write("c.csv", text);
  const auto meta = folder.write("m.csv", meta_header + "b,2,0.4,7,150,0.5\na,1.5,0.3,6.5,145,0.25\n");
  const auto read = read_relaxation_curves(curves, meta, std::nullopt);
  REQUIRE(read.size() == 2);
  CHECK(read[0].name == "a");
  CHECK(read[0].t.size() == 25);
  CHECK(read[1].t[3] == doctest::Approx(0.06));
  CHECK(read[0].force[0] == doctest::Approx(1e-6));
  CHECK(read[0].indentation == doctest::Approx(1.5e-6));
  CHECK(read[0].turgor == doctest::Approx(0.3e6));
  CHECK(read[0].diameter == doctest::Approx(6.5e-6));
  CHECK(read[0].thickness == doctest::Approx(145e-9));
  CHECK(read[0].probe_radius_m == doctest::Approx(0.25e-6));
  CHECK(read[1].probe_radius_m == doctest::Approx(0.5e-6));
}

TEST_CASE("curves: metadata repeated on every row, probe radius from the option") {
  Folder folder;
  std::string text = "curve,t_s,F_uN,delta_um,p_MPa,d_um,h_nm\n";
  for (int j = 0; j < 20; ++j) text += "a," + format_double(0.01 * j) + ",3,1.5,0.3,6.5,145\n";
  const auto curves = folder.write("c.csv", text);
  const auto read = read_relaxation_curves(curves, "", 0.5e-6);
  REQUIRE(read.size() == 1);
  CHECK(read[0].probe_radius_m == 0.5e-6);
  CHECK(error_of(curves, "").find("no rho_um column and no --rho-um") != std::string::npos);
  const auto changing = folder.write("d.csv", text + "a,0.2,3,1.5,0.31,6.5,145\n");
  CHECK(error_of(changing, "", 0.5e-6).find("d.csv:22: metadata of curve 'a' differ") != std::string::npos);
}

TEST_CASE("curves: every bad file is one InputError naming file, line and what was expected") {
  Folder folder;
  const auto meta = folder.write("m.csv", meta_header + "a,1.5,0.3,6.5,145,0.5\n");
  const auto good = rows("a", 20);
  CHECK(error_of(folder.write("t.csv", "curve,t_s,F_uN\n" + rows("a", 10) + "a,0.05,4\n" + rows("a", 10, 0.2)), meta)
            .find("t.csv:12: t_s = '0.05': expected a time after the previous sample") != std::string::npos);
  CHECK(error_of(folder.write("f.csv", "curve,t_s,F_uN\n" + rows("a", 5) + "a,0.07,-0.2\n" + rows("a", 20, 0.1)), meta)
            .find("f.csv:7: F_uN = '-0.2': expected a force >= 0") != std::string::npos);
  CHECK(error_of(folder.write("n.csv", "curve,t_s,F_uN\n" + rows("a", 5) + "a,0.07,x\n"), meta).find("n.csv:7") !=
        std::string::npos);
  CHECK(error_of(folder.write("s.csv", "curve,t_s,F_uN\n" + rows("a", 7)), meta)
            .find("s.csv:2: curve 'a' has 7 samples: expected at least 20") != std::string::npos);
  CHECK(error_of(folder.write("x.csv", "curve,t_s,F_uN\n" + good + rows("b", 20)), meta)
            .find("x.csv:22: curve 'b' has no row in") != std::string::npos);
  CHECK(error_of(folder.write("c.csv", "curve,t_s,F_uN\n" + good), folder.write("m2.csv", meta_header + "a,1.5,0.3,6.5,145,0.5\nz,1,1,1,1,1\n"))
            .find("m2.csv:3: curve = 'z': expected a curve of") != std::string::npos);
  CHECK(error_of(folder.file("c.csv"), folder.write("m3.csv", meta_header + "a,1.5,0.3,6.5,145,0.5\na,1.5,0.3,6.5,145,0.5\n"))
            .find("m3.csv:3: curve = 'a': expected one row per curve") != std::string::npos);
  CHECK(error_of(folder.file("c.csv"), folder.write("m4.csv", meta_header + "a,1.5,0,6.5,145,0.5\n"))
            .find("m4.csv:2: p_MPa = '0': expected a positive number") != std::string::npos);
  CHECK(error_of(folder.file("c.csv"), folder.write("m5.csv", "curve,delta_um,p_MPa,d_um,rho_um\na,1.5,0.3,6.5,0.5\n"))
            .find("h_nm") != std::string::npos);
  CHECK(error_of(folder.write("h.csv", "curve,time,F_uN\n" + good), meta).find("t_s") != std::string::npos);
}

TEST_CASE("growthuq relax: fits simulated curves, writes fits and distribution entries") {
  Folder folder;
  // Three tubes with different slow times, 100 Hz, 0.2 % noise, 10 um/s ramps.
  std::string curves = "# simulated by test_curves.cpp\ncurve,t_s,F_uN\n";
  std::string meta = meta_header;
  const double slow[] = {2.0, 3.0, 4.5};
  for (int c = 0; c < 3; ++c) {
    const MaxwellModel wall{1.95, {0.45, 0.6}, {0.2, slow[c]}};
    const SimulatedCurve sim = simulate_ramp_hold(wall, RampHoldProtocol{}, {0.002, 0.0, static_cast<std::uint64_t>(c + 1)});
    const std::string name = "tube" + std::to_string(c + 1);
    for (std::size_t j = 0; j < sim.t.size(); ++j) {
      curves += name + "," + format_double(sim.t[j]) + "," + format_double(std::max(sim.force[j], 0.0) * 1e6) + "\n";
    }
    meta += name + "," + format_double(sim.indentation * 1e6) + ",0.3,6.56,145,0.5\n";
  }
  folder.write("curves.csv", curves);
  folder.write("meta.csv", meta);

  const Run run = relax(folder, "curves.csv --meta meta.csv --out fits.csv --ramp-aware --fit-distributions wt.ini");
  CAPTURE(run.err);
  CAPTURE(run.out);
  REQUIRE(run.status == 0);
  CHECK(run.out.find("3 ok, 0 extrapolated (tau_slow beyond the hold), 0 failed") != std::string::npos);
  const CsvTable fits = read_csv(folder.file("fits.csv"));
  REQUIRE(fits.rows.size() == 3);
  const auto tau = fits.numeric_column("tau_slow_s");
  const auto eta = fits.numeric_column("eta_MPa_s");
  // E_r taus are shorter than the springs' (E_r ~ k^2), but ordered like them.
  CHECK(tau[0] < tau[1]);
  CHECK(tau[1] < tau[2]);
  for (double v : eta) CHECK(v > 0.0);
  // One viscosity (Eq. (R7), src/relaxation/README.md): each row's eta is what a distribution
  // campaign's evaluator computes from the row's own tau_slow, einf and E = E_r(0), and E0 is
  // the relaxing modulus (1 - einf) E_r(0).
  const auto einf_column = fits.numeric_column("einf_frac");
  const auto er0 = fits.numeric_column("Er0_MPa");
  const auto e0 = fits.numeric_column("E0_MPa");
  SampleBlock block(3);
  block.set_column("tau", tau);
  block.set_column("einf", einf_column);
  std::vector<double> modulus;
  for (double v : er0) modulus.push_back(v * 1e6);
  block.set_column("E", modulus);
  ViscosityEvaluator().evaluate(block);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(block.column("eta")[i] * 1e-6 == doctest::Approx(eta[i]).epsilon(1e-14));
    CHECK(e0[i] == doctest::Approx((1.0 - einf_column[i]) * er0[i]).epsilon(1e-14));
  }

  // The distribution entries are the lognormal ML fit of the columns just written.
  const IniDocument ini = read_ini(folder.file("wt.ini"));
  const IniSection* section = ini.find("tau");
  REQUIRE(section != nullptr);
  double mu = 0.0;
  for (double v : tau) mu += std::log(v) / 3.0;
  CHECK(parse_double(section->find("mu")->value, "", "mu") == doctest::Approx(mu).epsilon(1e-12));
  CHECK(section->find("law")->value == "lognormal");
  CHECK(section->find("unit")->value == "s");
  CHECK(section->find("source")->value == "fitted from curves.csv, 3 curves");
  REQUIRE(ini.find("einf") != nullptr);
  CHECK(ini.find("einf")->find("unit")->value == "frac");
  // einf, a fraction, gets the bounded beta law: the beta ML fit of the einf column just written.
  CHECK(ini.find("einf")->find("law")->value == "beta");
  const FitResult einf = fit_distribution(FitFamily::beta, fits.numeric_column("einf_frac"));
  CHECK(parse_double(ini.find("einf")->find("alpha")->value, "", "alpha") ==
        doctest::Approx(std::get<Beta>(einf.distribution).alpha()).epsilon(1e-9));
  CHECK(parse_double(ini.find("einf")->find("beta")->value, "", "beta") ==
        doctest::Approx(std::get<Beta>(einf.distribution).beta()).epsilon(1e-9));

  // Results are never overwritten without --force.
  const Run again = relax(folder, "curves.csv --meta meta.csv --out fits.csv");
  CHECK(again.status == 2);
  CHECK(again.err.find("fits.csv") != std::string::npos);
  CHECK(relax(folder, "curves.csv --meta meta.csv --out fits.csv --force --terms 1").status == 0);
  CHECK(read_csv(folder.file("fits.csv")).rows[0][read_csv(folder.file("fits.csv")).column_index("terms")] == "1");
}

TEST_CASE("growthuq relax: bad options and files give one line and exit status 2") {
  Folder folder;
  folder.write("curves.csv", "curve,t_s,F_uN\n" + rows("a", 20));
  folder.write("meta.csv", meta_header + "a,1.5,0.3,6.5,145,0.5\n");
  const struct {
    std::string arguments, expected;
  } cases[] = {
      {"curves.csv --meta meta.csv --out f.csv --terms 4", "--terms = '4': expected 1, 2 or 3"},
      {"curves.csv --meta meta.csv --out f.csv --nu 0.7", "--nu = '0.7'"},
      {"curves.csv --meta meta.csv --out f.csv --rho-um -1", "--rho-um = '-1'"},
      {"curves.csv --meta meta.csv --out f.csv --ramp-aware --drop-ramp-multiple 10", "step fit only"},
      {"curves.csv --out f.csv", "no rho_um column and no --rho-um"},
      {"missing.csv --meta meta.csv --out f.csv", "missing.csv"},
      {"curves.csv --meta meta.csv", "--out"},
      // --quiet: this one fails after the fits, whose progress line would come first.
      {"curves.csv --meta meta.csv --out f.csv --fit-distributions d.ini --quiet", "at least 2"},
  };
  for (const auto& c : cases) {
    const Run run = relax(folder, c.arguments);
    CAPTURE(c.arguments);
    CAPTURE(run.err);
    CHECK(run.status == 2);
    CHECK(run.err.find(c.expected) != std::string::npos);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  }
  CHECK_FALSE(fs::exists(folder.file("d.ini")));
}

TEST_CASE("curves: a probe radius given for every curve and a different one in the sheet is an error, not overridden") {
  Folder folder;
  const auto curves = folder.write("c.csv", "curve,t_s,F_uN\n" + rows("a", 20) + rows("b", 20));
  const auto meta = folder.write("m.csv", meta_header + "a,1.5,0.3,6.5,145,0.5\nb,1.5,0.3,6.5,145,0.25\n");
  // The sheet alone decides, per curve.
  CHECK(read_relaxation_curves(curves, meta, std::nullopt)[1].probe_radius_m == doctest::Approx(0.25e-6));
  // --rho-um 0.5 given too: curve a agrees, curve b does not (the sheet silently won before).
  CHECK(error_of(curves, meta, 0.5e-6) ==
        meta + ":3: rho_um = '0.25': expected the probe radius given for every curve, 0.5 um (--rho-um, or the "
               "campaign's probe_radius_um): give the radius in one place, or the same in both");
  // The same radius in both places is no conflict.
  const auto same = folder.write("s.csv", meta_header + "a,1.5,0.3,6.5,145,0.5\nb,1.5,0.3,6.5,145,0.5\n");
  CHECK(read_relaxation_curves(curves, same, 0.5e-6)[1].probe_radius_m == doctest::Approx(0.5e-6));
}
