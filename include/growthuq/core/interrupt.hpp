// Signals and the files a process is writing.
//
// Ctrl-C (SIGINT) and SIGTERM as a request to stop cleanly (issue 4, "Long runs"): while an
// InterruptHandlers object lives, the first of these signals only records itself; long work
// polls interrupt_signal() and winds down (Pool::stop_when). A second one ends the process at
// once, as users expect of Ctrl-C.
//
// A signal that ends the process (SIGINT, SIGTERM, SIGHUP outside an InterruptHandlers scope,
// or the second one inside) first removes every partial file still registered
// (RemovedOnSignal): a killed command leaves no "<result>.partial" of its own behind.
#pragma once

#include <string>

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

// The handler of a signal that ends the process: removes the registered partial files, then
// ends the process by the signal's default action (so the shell sees 128 + signal).
extern "C" void remove_partial_files_and_end(int signal);

// Installs remove_partial_files_and_end for SIGINT, SIGTERM and SIGHUP where their action is
// still the default one (an ignored signal stays ignored: nohup). Called once by main().
void remove_partial_files_on_fatal_signals();

// Registers a partial file for removal by remove_partial_files_and_end while this object
// lives (PartialFile, results.h5 and field output hold one from creating the partial file
// until it is renamed or removed). Up to 64 at a time; beyond that a file is not registered
// (it is then left by a kill as before). The registry is lock-free: the handler may run at any
// moment, also on another thread.
class RemovedOnSignal {
 public:
  explicit RemovedOnSignal(const std::string& path);
  ~RemovedOnSignal();
  RemovedOnSignal(const RemovedOnSignal&) = delete;
  RemovedOnSignal& operator=(const RemovedOnSignal&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace growthuq
