#include "core/interrupt.hpp"

#include <csignal>

namespace growthuq {
namespace {

// Written by the handler: only a volatile sig_atomic_t may be (C++20 [support.signal]).
volatile std::sig_atomic_t requested_signal = 0;

struct sigaction previous_interrupt;
struct sigaction previous_terminate;

extern "C" void record_signal(int signal) { requested_signal = signal; }

}  // namespace

InterruptHandlers::InterruptHandlers() {
  requested_signal = 0;
  struct sigaction action {};
  action.sa_handler = record_signal;
  sigemptyset(&action.sa_mask);
  // SA_RESETHAND: the next signal gets the default action (ends the process); SA_RESTART: a
  // system call the signal interrupts (a write, MPI's polling) resumes instead of failing.
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, &previous_interrupt);
  sigaction(SIGTERM, &action, &previous_terminate);
}

InterruptHandlers::~InterruptHandlers() {
  sigaction(SIGINT, &previous_interrupt, nullptr);
  sigaction(SIGTERM, &previous_terminate, nullptr);
}

int interrupt_signal() noexcept { return requested_signal; }

int exit_status_of_signal(int signal) noexcept { return 128 + signal; }

}  // namespace growthuq
