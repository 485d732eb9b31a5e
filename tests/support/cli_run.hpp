// Running the built `growthuq` executable (GROWTHUQ_CLI, defined by tests/CMakeLists.txt) as a
// user does and capturing what it printed, for the end-to-end tests of the commands.
#pragma once

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

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

// Starts `program arguments...` in `directory` with stdout and stderr to stdout.txt and
// stderr.txt there, without waiting (to stop it part way); `environment` holds extra NAME=VALUE
// settings. Returns its process id.
inline pid_t start(const std::vector<std::string>& command, const std::filesystem::path& directory,
                   const std::vector<std::string>& environment = {}) {
  const pid_t pid = fork();
  if (pid == 0) {
    // Only async-signal-safe calls here in principle; chdir/open/dup2/putenv/execv are.
    if (chdir(directory.c_str()) != 0) _exit(126);
    const int out = open("stdout.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open("stderr.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(out, 1);
    dup2(err, 2);
    for (const std::string& setting : environment) putenv(const_cast<char*>(setting.c_str()));
    std::vector<char*> argv;
    for (const std::string& word : command) argv.push_back(const_cast<char*>(word.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

// The wait status of the started process `pid`, once it has ended.
inline int wait_for(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

// Runs `command` (start()) in `directory` to its end.
inline CliOutcome run_in(const std::filesystem::path& directory, const std::vector<std::string>& command,
                         const std::vector<std::string>& environment = {}) {
  return outcome_in(directory, wait_for(start(command, directory, environment)));
}

// `growthuq <arguments>` as a command for start().
inline std::vector<std::string> cli(std::vector<std::string> arguments) {
  arguments.insert(arguments.begin(), GROWTHUQ_CLI);
  return arguments;
}

}  // namespace growthuq::testing
