// InterruptGuard — while one is alive, SIGINT and SIGTERM only raise a flag,
// so a long render can stop between frames and still finish its output
// cleanly (flush the encoder, write the trailer). A second Ctrl-C ends the
// process through the shared clean-up (core/temp_files.hpp: temporaries
// removed, never a corrupt file at a final name), unless it comes within
// 250 ms of the first: that is the same interruption delivered twice (to the
// process and to its process group, as `timeout` does), the two deliveries
// apart by however long a loaded machine takes to schedule the process. The previous handlers are
// restored when the guard goes.
#pragma once

#include <csignal>

namespace rollspin::jobs {

class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // The signal received (SIGINT, SIGTERM) or 0.
  [[nodiscard]] static int received();

  // A second signal this soon after the first is the same interruption.
  static constexpr long long kSameInterruptionNanoseconds = 250'000'000;

 private:
  struct sigaction previousInt_ {
  }, previousTerm_{};
};

}  // namespace rollspin::jobs
