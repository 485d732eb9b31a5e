// growthuq: the command-line front end. It only dispatches to a subcommand and turns
// errors into one line on stderr and a non-zero exit.
#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <string>

#include "commands.hpp"
#include "growthuq/core/interrupt.hpp"
#include "growthuq/io/hdf5_exit.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/printable.hpp"
#include "options.hpp"

namespace {

using growthuq::cli::Command;

constexpr std::array commands{
    Command{"sample", "correlated Latin hypercube design of a plant line", growthuq::cli::run_sample},
    Command{"fit", "fit distribution families to raw per-tube measurements", growthuq::cli::run_fit},
    Command{"eval", "invert measured tubes to turgor, modulus and more (no Monte Carlo)", growthuq::cli::run_eval},
    Command{"correlate", "rank correlation of (k, h, d, d0) from the forward mechanics", growthuq::cli::run_correlate},
    Command{"relax", "fit generalized Maxwell series to force-relaxation curves", growthuq::cli::run_relax},
    Command{"curves", "stiffness k per curve and per tube from raw force-indentation curves", growthuq::cli::run_curves},
    Command{"run", "run a campaign: plant lines through the models, summaries and result files", growthuq::cli::run_run},
    Command{"check", "validate a campaign as run does and print its plan, without running it", growthuq::cli::run_check},
    Command{"tradeoff", "measured speed/accuracy trade of a campaign over sample counts", growthuq::cli::run_tradeoff},
    Command{"synth", "draw a SYNTHETIC raw data set (tables, curves) from true line distributions", growthuq::cli::run_synth},
    Command{"fit-line", "fit a plant line's distributions from its raw data (raw.ini) to a line file", growthuq::cli::run_fit_line},
    Command{"indent", "finite-element tube under the probe: force curve, k, d (minutes per curve)", growthuq::cli::run_indent},
    Command{"report", "one self-contained HTML report of a run: tables, figures, methods paragraph, references", growthuq::cli::run_report},
    Command{"fit-correction", "fit fidelity corrected to finite-element training data (writes its C++ text)", growthuq::cli::run_fit_correction},
};

// What a command printed on stdout is a result too (eval's values, fit's table): a stdout that
// could not take it all (a full disk, /dev/full) makes the command fail, as a file that could
// not be written does. stdout is block-buffered when it is not a terminal, so a write error
// shows only when the buffer is flushed: here, before exit. Returns the exit status.
int finish_stdout(const std::string& command, int status) {
  errno = 0;
  std::cout.flush();
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (flushed && std::cout && !std::ferror(stdout)) return status;
  std::cerr << "growthuq" << (command.empty() ? "" : " " + command) << ": error: standard output: write failed"
            << (error != 0 ? std::string(": ") + std::strerror(error) : std::string())
            << " (what was printed there is incomplete)\n";
  return status == 0 ? 2 : status;
}

void print_usage(std::ostream& out) {
  out << "usage: growthuq <command> [options]   (growthuq help <command> for its options)\n\n"
         "Monte Carlo uncertainty quantification of pollen tube mechanics and growth.\n\ncommands:\n";
  std::size_t width = 0;  // the longest name, plus two spaces
  for (const Command& command : commands) width = std::max(width, command.name.size() + 2);
  for (const Command& command : commands) {
    const std::string start = "  " + std::string(command.name) + std::string(width - command.name.size(), ' ');
    out << growthuq::cli::wrapped_help(command.summary, start, std::string(start.size(), ' ')) << "\n";
  }
}

int dispatch(int argc, char** argv) {
  // A command killed by a signal leaves none of its partial files (core/interrupt.hpp).
  growthuq::remove_partial_files_on_fatal_signals();
  if (argc < 2) {
    print_usage(std::cerr);
    return 2;
  }
  std::string name = argv[1];
  growthuq::cli::Arguments arguments(argv + 2, argv + argc);
  if (name == "--help" || name == "-h" || (name == "help" && arguments.empty())) {
    print_usage(std::cout);
    return finish_stdout("", 0);
  }
  if (name == "--version") {
    growthuq::cli::print_version(std::cout);
    return finish_stdout("", 0);
  }
  if (name == "help") {
    // `growthuq help CMD` is `growthuq CMD --help`.
    if (arguments.size() > 1) {
      std::cerr << "growthuq help: error: expected one command, got " << arguments.size()
                << ": growthuq help <command>\n";
      return 2;
    }
    name = arguments.front();
    arguments = {"--help"};
  }
  for (const Command& command : commands) {
    if (command.name != name) continue;
    try {
      return finish_stdout(name, command.run(arguments));
    } catch (const growthuq::InputError& error) {
      // Errors located at the command line itself carry "growthuq <name>" as their location;
      // print it once.
      const bool at_command_line = error.location() == "growthuq " + name;
      std::cerr << "growthuq " << name << ": error: " << (at_command_line ? error.problem() : error.what()) << "\n";
      return 2;
    } catch (const std::bad_alloc&) {
      // What the up-front estimate (campaign/run_footprint.hpp) did not foresee: say so plainly.
      std::cerr << "growthuq " << name << ": error: out of memory: this machine could not provide the memory the "
                   "command needed (fewer samples need less)\n";
      return 3;
    } catch (const std::exception& error) {
      std::cerr << "growthuq " << name << ": internal error: " << growthuq::printable(error.what()) << "\n";
      return 3;
    }
  }
  std::cerr << "growthuq: unknown command '" << growthuq::printable(name) << "'\n\n";
  print_usage(std::cerr);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  const int status = dispatch(argc, argv);
  // An HDF5 file that could not be closed (a full disk during its last flush) would crash
  // HDF5's clean-up at exit (SIGSEGV after the message): the process ends without it, its
  // streams flushed, its status kept (io/hdf5_errors.hpp).
  if (growthuq::hdf5::file_left_half_closed()) {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    std::_Exit(status);
  }
  return status;
}
