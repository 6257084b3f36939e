#include "jobs/interrupt_guard.hpp"

#include <time.h>

#include <atomic>

#include "core/temp_files.hpp"

namespace rollspin::jobs {

namespace {

// Lock-free, so touching it from a signal handler is safe.
std::atomic<int> receivedSignal{0};
static_assert(std::atomic<int>::is_always_lock_free);

// When the first signal came (CLOCK_MONOTONIC, nanoseconds).
std::atomic<long long> firstSignalNanoseconds{0};
static_assert(std::atomic<long long>::is_always_lock_free);

long long monotonicNanoseconds() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe (POSIX)
  return static_cast<long long>(now.tv_sec) * 1'000'000'000LL + now.tv_nsec;
}

// A second signal does not wait: the shared clean-up removes the temporary
// files and ends the process. Unless it follows the first within
// kSameInterruptionNanoseconds: `timeout -s INT`, a terminal's Ctrl-C or a
// job controller sends one signal to the process and then to its group, so
// one interruption arrives twice, microseconds apart when sent, up to tens
// of milliseconds apart when handled on a busy machine; a person's
// deliberate second Ctrl-C comes seconds later.
extern "C" void onInterrupt(int signal) {
  const long long now = monotonicNanoseconds();
  long long expected = 0;
  if (firstSignalNanoseconds.compare_exchange_strong(expected, now)) {
    receivedSignal.store(signal);
    return;
  }
  if (now - expected < InterruptGuard::kSameInterruptionNanoseconds) return;
  interruptCleanupAndExit(signal);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  receivedSignal.store(0);
  firstSignalNanoseconds.store(0);
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, &previousInt_);
  sigaction(SIGTERM, &action, &previousTerm_);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &previousInt_, nullptr);
  sigaction(SIGTERM, &previousTerm_, nullptr);
}

int InterruptGuard::received() { return receivedSignal.load(); }

}  // namespace rollspin::jobs
