// Ctrl-C and SIGTERM as a stop request: the first signal is recorded and the process lives on;
// the handler then reverts to the default action (a second signal ends the process); leaving
// the scope restores what was installed before.
#include <doctest/doctest.h>

#include <csignal>
#include <initializer_list>

#include "core/interrupt.hpp"

using namespace growthuq;

namespace {

void (*current_handler(int signal))(int) {
  struct sigaction action {};
  sigaction(signal, nullptr, &action);
  return action.sa_handler;
}

}  // namespace

TEST_CASE("the first SIGTERM or SIGINT is recorded, not fatal, and re-arms the default action") {
  for (const int signal : {SIGTERM, SIGINT}) {
    CAPTURE(signal);
    const auto before = current_handler(signal);
    {
      const InterruptHandlers handlers;
      CHECK(interrupt_signal() == 0);
      CHECK((current_handler(signal) != SIG_DFL));
      std::raise(signal);  // would end the test process without the handler
      CHECK(interrupt_signal() == signal);
      CHECK((current_handler(signal) == SIG_DFL));  // the next one would end the process
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
