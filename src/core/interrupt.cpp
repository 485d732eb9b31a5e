#include "growthuq/core/interrupt.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>

namespace growthuq {
namespace {

// Written by the handler: only a volatile sig_atomic_t may be (C++20 [support.signal]).
volatile std::sig_atomic_t requested_signal = 0;

struct sigaction previous_interrupt;
struct sigaction previous_terminate;

// The partial files a signal removes. A slot is free (0), being filled (1) or registered (2);
// the handler reads only registered slots, whose path is complete before the state says so.
constexpr int slot_count = 64;
constexpr std::size_t longest_path = 4096;
struct Slot {
  std::atomic<int> state{0};
  std::array<char, longest_path> path{};
};
std::array<Slot, slot_count> slots;
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the registry");

void install(int signal, void (*handler)(int), int flags, struct sigaction* previous) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  action.sa_flags = flags;
  sigaction(signal, &action, previous);
}

// The first SIGINT or SIGTERM of an InterruptHandlers scope: recorded; the next one removes the
// partial files and ends the process (sigaction is async-signal-safe).
extern "C" void record_signal(int signal) {
  requested_signal = signal;
  install(signal, remove_partial_files_and_end, 0, nullptr);
}

}  // namespace

extern "C" void remove_partial_files_and_end(int signal) {
  for (Slot& slot : slots) {
    if (slot.state.load(std::memory_order_acquire) == 2) ::unlink(slot.path.data());
  }
  install(signal, SIG_DFL, 0, nullptr);
  ::raise(signal);
}

void remove_partial_files_on_fatal_signals() {
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction current {};
    sigaction(signal, nullptr, &current);
    if (current.sa_handler == SIG_DFL) install(signal, remove_partial_files_and_end, SA_RESTART, nullptr);
  }
}

RemovedOnSignal::RemovedOnSignal(const std::string& path) {
  if (path.size() >= longest_path) return;
  for (int i = 0; i < slot_count; ++i) {
    int free = 0;
    Slot& slot = slots[static_cast<std::size_t>(i)];
    if (!slot.state.compare_exchange_strong(free, 1, std::memory_order_acquire)) continue;
    std::memcpy(slot.path.data(), path.c_str(), path.size() + 1);
    slot.state.store(2, std::memory_order_release);
    slot_ = i;
    return;
  }
}

RemovedOnSignal::~RemovedOnSignal() {
  if (slot_ >= 0) slots[static_cast<std::size_t>(slot_)].state.store(0, std::memory_order_release);
}

InterruptHandlers::InterruptHandlers() {
  requested_signal = 0;
  // SA_RESTART: a system call the signal interrupts (a write, MPI's polling) resumes instead
  // of failing.
  install(SIGINT, record_signal, SA_RESTART, &previous_interrupt);
  install(SIGTERM, record_signal, SA_RESTART, &previous_terminate);
}

InterruptHandlers::~InterruptHandlers() {
  sigaction(SIGINT, &previous_interrupt, nullptr);
  sigaction(SIGTERM, &previous_terminate, nullptr);
}

int interrupt_signal() noexcept { return requested_signal; }

int exit_status_of_signal(int signal) noexcept { return 128 + signal; }

}  // namespace growthuq
