// ProgressMeter — an animation's progress on stderr: a bar redrawn in place
// on a terminal (frames, frames per second, ETA), throttled to a few updates
// a second; nothing while running when stderr is not a terminal (the job
// prints one summary line at the end); nothing at all when quiet.
// frameDone() may be called from another thread than the rest.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>

namespace rollspin::jobs {

class ProgressMeter {
 public:
  ProgressMeter(long long totalFrames, bool quiet);

  void frameDone();
  // Erases the bar so that the next line starts clean.
  void clear();
  [[nodiscard]] double elapsedSeconds() const;
  [[nodiscard]] long long framesDone() const { return done_.load(); }
  [[nodiscard]] bool onTerminal() const { return terminal_; }

 private:
  using Clock = std::chrono::steady_clock;
  long long total_;
  bool terminal_;
  std::atomic<long long> done_{0};
  Clock::time_point start_ = Clock::now();
  Clock::time_point lastDraw_{};
  long long shownDone_ = 0;  // the count the bar on screen shows
  std::mutex drawMutex_;
  bool drawn_ = false;
};

}  // namespace rollspin::jobs
