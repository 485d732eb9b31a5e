// Benchmark of the finite-element shell model on one core: one forward curve and one inverse
// sample at an Arabidopsis-like tube (probe radius --rho-um, default 0.25), with the share of
// time in assembly, factorisation and contact. Run by tools/bench/bench-fe, bench-fe-contact and
// bench-fe-wide (which also compiles it against an earlier commit's library: public API only,
// as that commit has it); prints `name = value` lines.
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/fe/indentation.hpp"

using namespace growthuq;

namespace {

void print(const std::string& name, double value) { std::cout << name << " = " << format_double(value) << "\n"; }

ShellFeMesh mesh_from(const std::string& text) {
  return parse_shell_fe_mesh(text, "bench_fe", "--mesh");
}

}  // namespace

int main(int argc, char** argv) {
  ShellFeOptions options;
  int repetitions = 1;
  double rho_um = 0.25;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--mesh") options.mesh = mesh_from(value);
    else if (flag == "--repetitions") repetitions = std::atoi(value.c_str());
    else if (flag == "--contact") options.contact = parse_shell_fe_contact(value, "bench_fe", "--contact");
    else if (flag == "--rho-um") rho_um = std::atof(value.c_str());
    else {
      std::cerr << "bench_fe: unknown option " << flag << " (--mesh coarse|default|fine|finer, --contact active_set|penalty, --rho-um RHO, --repetitions N)\n";
      return 2;
    }
  }
  // p = 0.45 MPa, E = 45 MPa, turgid h = 200 nm, d0 = 5.35 um, rho = 0.25 um: p/E = 0.01, d/d0 ~ 1.2,
  // k about 1.9 N/m (the curve reaches the window's top at about 2.1 um).
  IndentationInput input;
  input.pressure = 0.45e6;
  input.young = 45e6;
  input.thickness = 200e-9;
  input.plasmolysed_diameter = 5.35e-6;
  input.instrument.probe_radius_m = rho_um * 1e-6;
  if (!(input.instrument.probe_radius_m > 0)) {
    std::cerr << "bench_fe: --rho-um " << rho_um << ": expected a positive probe radius in um\n";
    return 2;
  }

  std::vector<double> forward_cpu, inverse_cpu;
  IndentationCurve curve;
  ShellFeInverse inverse;
  for (int r = 0; r < repetitions; ++r) {
    const double start = bench::thread_cpu_seconds();
    curve = indent(input, options);
    forward_cpu.push_back(bench::thread_cpu_seconds() - start);
    if (curve.status != SampleStatus::ok) {
      std::cerr << "bench_fe: forward status " << to_string(curve.status) << ": " << curve.message << "\n";
      return 1;
    }
    const ShellFeMeasurement tube{curve.measured_stiffness, input.thickness, curve.turgid_diameter, input.plasmolysed_diameter};
    const double inverse_start = bench::thread_cpu_seconds();
    inverse = invert_indentation(tube, input.instrument, options);
    inverse_cpu.push_back(bench::thread_cpu_seconds() - inverse_start);
  }
  std::cout << "mesh = " << to_string(options.mesh) << "\n";
  std::cout << "contact = " << to_string(options.contact) << "\n";
  print("rho_um", rho_um);
  print("forward_cpu_seconds", bench::median(forward_cpu));
  print("forward_wall_seconds", curve.seconds);
  print("forward_points", static_cast<double>(curve.depth.size()));
  print("forward_newton_iterations", curve.newton_iterations);
  print("forward_load_steps", curve.indentation_load_steps);
  print("forward_iterations_per_load_step",
        curve.indentation_newton_iterations / std::max(1.0, static_cast<double>(curve.indentation_load_steps)));
  const double solver = curve.seconds;
  print("share_assembly", curve.seconds_assembly / solver);
  print("share_factorisation", curve.seconds_factorisation / solver);
  print("share_contact", curve.seconds_contact / solver);
  // The bound: what one factorisation costs at this mesh (the part no solver strategy avoids
  // for a Newton iteration), and the iterations the path took.
  print("forward_factorisations", curve.factorisations);
  print("seconds_per_factorisation", curve.seconds_factorisation / std::max(1, curve.factorisations));
  print("k_N_per_m", curve.stiffness);
  print("inverse_cpu_seconds", bench::median(inverse_cpu));
  print("inverse_wall_seconds", inverse.seconds);
  print("inverse_inflation_solves", inverse.inflation_solves);
  print("inverse_newton_iterations", inverse.newton_iterations);
  print("inverse_far_field_diameter_error", inverse.far_field_diameter_error);
  print("inverse_E_relative_error", inverse.young / input.young - 1);
  print("inverse_p_relative_error", inverse.pressure / input.pressure - 1);
  std::cout << "inverse_status = " << to_string(inverse.status) << "\n";
  return 0;
}
