// Ctrl-C and SIGTERM as a stop request: the first signal is recorded and the process lives on;
// the handler then becomes the one that ends the process (a second signal ends it, removing the
// registered partial files first); leaving the scope restores what was installed before.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include "growthuq/core/interrupt.hpp"

using namespace growthuq;

namespace {

void (*current_handler(int signal))(int) {
  struct sigaction action {};
  sigaction(signal, nullptr, &action);
  return action.sa_handler;
}

}  // namespace

TEST_CASE("the first SIGTERM or SIGINT is recorded, not fatal, and arms the ending action") {
  for (const int signal : {SIGTERM, SIGINT}) {
    CAPTURE(signal);
    const auto before = current_handler(signal);
    {
      const InterruptHandlers handlers;
      CHECK(interrupt_signal() == 0);
      CHECK((current_handler(signal) != SIG_DFL));
      std::raise(signal);  // would end the test process without the handler
      CHECK(interrupt_signal() == signal);
      CHECK((current_handler(signal) == remove_partial_files_and_end));  // the next one would end the process
    }
    CHECK((current_handler(signal) == before));
  }
  {
    const InterruptHandlers handlers;
    CHECK(interrupt_signal() == 0);  // a new scope starts without a request
  }
}

TEST_CASE("exit status of a signalled stop follows the shell convention 128 + signal") {
  CHECK(exit_status_of_signal(SIGINT) == 130);
  CHECK(exit_status_of_signal(SIGTERM) == 143);
}

TEST_CASE("a signal that ends the process removes the registered partial files, and only those") {
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / ("growthuq_test_signal_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  const fs::path partial = folder / "design.csv.partial", released = folder / "old.csv.partial", other = folder / "keep.csv";
  for (const fs::path& path : {partial, released, other}) std::ofstream(path) << "x\n";
  for (const int signal : {SIGTERM, SIGINT, SIGHUP}) {
    CAPTURE(signal);
    std::ofstream(partial) << "x\n";
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      // As main() and a writer do: the handler (over the default action, not doctest's own),
      // one file registered, one registered and released.
      std::signal(signal, SIG_DFL);
      remove_partial_files_on_fatal_signals();
      const RemovedOnSignal writing(partial.string());
      { const RemovedOnSignal done(released.string()); }
      ::raise(signal);
      ::_exit(0);  // not reached: the signal ends the process
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFSIGNALED(status));  // ended by the signal itself: the shell sees 128 + signal
    CHECK(WTERMSIG(status) == signal);
    CHECK(!fs::exists(partial));
    CHECK(fs::exists(released));
    CHECK(fs::exists(other));
  }
  fs::remove_all(folder);
}
