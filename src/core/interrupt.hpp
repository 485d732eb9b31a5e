// Ctrl-C (SIGINT) and SIGTERM as a request to stop cleanly (issue 4, "Long runs"): while an
// InterruptHandlers object lives, the first of these signals only records itself; long work
// polls interrupt_signal() and winds down (Pool::stop_when). The handler then reverts to the
// default action, so a second signal ends the process at once, as users expect of Ctrl-C.
#pragma once

namespace growthuq {

class InterruptHandlers {
 public:
  // Clears any earlier request and installs the handlers for SIGINT and SIGTERM.
  InterruptHandlers();
  // Restores the handlers that were there before.
  ~InterruptHandlers();
  InterruptHandlers(const InterruptHandlers&) = delete;
  InterruptHandlers& operator=(const InterruptHandlers&) = delete;
};

// The signal that asked to stop (SIGINT or SIGTERM) since the handlers were installed; 0 when
// none arrived.
int interrupt_signal() noexcept;

// The conventional exit status of a process stopped by `signal`: 128 + its number (130 for
// SIGINT, 143 for SIGTERM).
int exit_status_of_signal(int signal) noexcept;

}  // namespace growthuq
