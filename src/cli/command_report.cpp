// growthuq report: one self-contained HTML file of a run's results (tables, figures, methods
// paragraph, references, warnings), made by the Python tool tools/report (tools/reporting/),
// which this command checks the arguments for and then runs with Debian's python3.
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "growthuq/core/error.hpp"
#include "options.hpp"
#include "result_output.hpp"

extern char** environ;

namespace growthuq::cli {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view location = "growthuq report";

// The tools/ folder of the source tree this program was built from, unless GROWTHUQ_TOOLS_DIR
// names another (an installed or moved copy): the report is Python, which is not installed.
std::string tools_directory() {
  const char* chosen = std::getenv("GROWTHUQ_TOOLS_DIR");
  return chosen != nullptr && *chosen != '\0' ? chosen : GROWTHUQ_TOOLS_DIR;
}

// The interpreter with numpy, matplotlib and h5py (tools/install-deps); GROWTHUQ_PYTHON
// overrides it.
std::string python() {
  const char* chosen = std::getenv("GROWTHUQ_PYTHON");
  return chosen != nullptr && *chosen != '\0' ? chosen : "/usr/bin/python3";
}

// A results directory is one `growthuq run` committed: summary.csv is moved in last
// (campaign_outputs.hpp), so it marks a complete set.
void check_results_directory(const std::string& directory) {
  std::error_code error;
  if (!fs::exists(directory, error)) {
    throw InputError(directory, "no such directory: expected the output directory of growthuq run");
  }
  if (!fs::is_directory(directory, error)) {
    throw InputError(directory, "is not a directory: expected the output directory of growthuq run");
  }
  if (!fs::is_regular_file(fs::path(directory) / "summary.csv", error)) {
    throw InputError(directory, "is not a results directory: it has no summary.csv (growthuq run writes one when "
                                "its results are complete)");
  }
}

// Runs `words` and returns its exit status; the child shares stdout and stderr.
int run_program(const std::vector<std::string>& words) {
  std::vector<char*> argv;
  for (const std::string& word : words) argv.push_back(const_cast<char*>(word.c_str()));
  argv.push_back(nullptr);
  pid_t child = 0;
  std::cout.flush();
  if (const int error = posix_spawn(&child, argv[0], nullptr, nullptr, argv.data(), environ); error != 0) {
    throw InputError(std::string(location), "cannot run " + words[0] + ": " + std::strerror(error) +
                                                " (the report needs Debian's python3 with numpy, matplotlib and "
                                                "h5py: tools/install-deps; GROWTHUQ_PYTHON names another)");
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  std::cerr << location << ": error: the report tool was stopped by signal " << WTERMSIG(status) << "\n";
  return 3;
}

}  // namespace

int run_report(const Arguments& arguments) {
  std::string directory, out;
  bool force = false;
  po::options_description described("options");
  described.add_options()
      ("results", po::value(&directory)->required(), "results directory (the output directory of growthuq run)")
      ("out", po::value(&out), "the HTML file to write (default RESULTS/report.html)")
      ("force", po::bool_switch(&force), "replace an existing report");
  po::positional_options_description positional;
  positional.add("results", 1);
  po::variables_map values;
  if (!parse_arguments(arguments, "report", "RESULTS_DIR [--out FILE] [--force]",
                       "Writes one self-contained HTML file (figures embedded as PNG, nothing fetched) of a run's "
                       "results: the data intervals and the summary of every line and quantity, the line "
                       "comparisons' letters, the sensitivity indices, the raw-data fit reports, the figures of "
                       "tools/plot, a methods paragraph made from the run's provenance.json (version, campaign "
                       "and its SHA-256, fidelity per line, probe radius, seed, samples, data-interval settings), "
                       "the references of every model used and warnings (each fidelity's measured error, "
                       "illustrative laws, flagged samples).\n\n"
                       "Made by tools/report (Python: Debian's python3 with numpy, matplotlib and h5py); "
                       "GROWTHUQ_TOOLS_DIR names another tools/ folder, GROWTHUQ_PYTHON another interpreter. "
                       "Refuses to replace an existing report without --force.",
                       described, positional, values)) {
    return 0;
  }
  check_results_directory(directory);
  if (out.empty()) out = (fs::path(directory) / "report.html").string();
  if (is_standard_output(out)) {
    throw InputError(out, "standard output cannot take a report: expected an HTML file name (./- for one named -)");
  }
  check_result_target(out, force ? Overwrite::allow : Overwrite::refuse);
  const std::string tool = (fs::path(tools_directory()) / "report").string();
  std::error_code error;
  if (!fs::is_regular_file(tool, error)) {
    throw InputError(tool, "the report tool is missing (it is in the source tree's tools/ folder; set "
                           "GROWTHUQ_TOOLS_DIR to that folder)");
  }
  // --force: the target was checked here, and the tool replaces it atomically.
  return run_program({python(), tool, directory, "--out", out, "--force", "--program", std::string(location)});
}

}  // namespace growthuq::cli
