#include "app/interrupt_guard.hpp"

#include <atomic>

#include "core/temp_files.hpp"

namespace rollspin::app {

namespace {

// Lock-free, so touching it from a signal handler is safe.
std::atomic<int> receivedSignal{0};
static_assert(std::atomic<int>::is_always_lock_free);

// A second signal does not wait: the shared clean-up removes the temporary
// files and ends the process.
extern "C" void onInterrupt(int signal) {
  if (receivedSignal.exchange(signal) != 0) interruptCleanupAndExit(signal);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  receivedSignal.store(0);
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

}  // namespace rollspin::app
