// The subcommands of the `growthuq` executable. Each lives in its own command_<name>.cpp,
// parses its options with Boost.Program_options (see options.hpp) into a typed struct, calls
// the library, and returns the process exit code. Bad input is thrown as InputError and
// reported by main().
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace growthuq::cli {

using Arguments = std::vector<std::string>;  // the words after the subcommand name

struct Command {
  std::string_view name;
  std::string_view summary;
  int (*run)(const Arguments& arguments);
};

int run_sample(const Arguments& arguments);
int run_fit(const Arguments& arguments);
int run_eval(const Arguments& arguments);
int run_correlate(const Arguments& arguments);
int run_relax(const Arguments& arguments);
int run_curves(const Arguments& arguments);
int run_run(const Arguments& arguments);
int run_check(const Arguments& arguments);
int run_tradeoff(const Arguments& arguments);
int run_synth(const Arguments& arguments);
int run_fit_line(const Arguments& arguments);
int run_indent(const Arguments& arguments);
int run_fit_correction(const Arguments& arguments);
int run_report(const Arguments& arguments);

}  // namespace growthuq::cli
