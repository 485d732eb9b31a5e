// Running the built `growthuq` executable (GROWTHUQ_CLI, defined by tests/CMakeLists.txt) as a
// user does and capturing what it printed, for the end-to-end tests of the commands.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/text_file.hpp"

namespace growthuq::testing {

struct CliOutcome {
  int exit_code = -1;  // -1 when the process did not exit normally (killed by a signal)
  std::string out;
  std::string err;
};

// The outcome of a finished process, from its wait status and the stdout.txt and stderr.txt it
// wrote in `directory`.
inline CliOutcome outcome_in(const std::filesystem::path& directory, int wait_status) {
  return {WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1, slurp(directory / "stdout.txt"),
          slurp(directory / "stderr.txt")};
}

// Runs `growthuq <arguments>` (shell words) in `directory`, stdout and stderr going to
// stdout.txt and stderr.txt there.
inline CliOutcome run_cli(const std::string& arguments, const std::filesystem::path& directory) {
  const std::string command = "cd '" + directory.string() + "' && '" + std::string(GROWTHUQ_CLI) + "' " + arguments +
                              " >stdout.txt 2>stderr.txt";
  return outcome_in(directory, std::system(command.c_str()));
}

}  // namespace growthuq::testing
