#include "jobs/progress_meter.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace rollspin::jobs {

ProgressMeter::ProgressMeter(long long totalFrames, bool quiet)
    : total_(totalFrames), terminal_(!quiet && ::isatty(STDERR_FILENO) == 1) {}

double ProgressMeter::elapsedSeconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

void ProgressMeter::frameDone() {
  const long long done = ++done_;
  if (!terminal_) return;
  std::lock_guard lock(drawMutex_);
  // A thread that took the lock late holds an older count than the bar
  // shows: redrawing it would move the bar back (even after the full one).
  if (done <= shownDone_) return;
  const auto now = Clock::now();
  // A terminal redrawn hundreds of times a second slows the render it shows.
  if (done != total_ && now - lastDraw_ < std::chrono::milliseconds(200)) return;
  lastDraw_ = now;
  shownDone_ = done;
  const double seconds = elapsedSeconds();
  const double rate = seconds > 0.0 ? double(done) / seconds : 0.0;
  const long long eta = rate > 0.0 ? static_cast<long long>(double(std::max(total_ - done, 0LL)) / rate + 0.5) : 0;
  constexpr int kWidth = 30;
  // A count past the total (a caller's miscount) shows a full bar, not a
  // negative remainder.
  const int filled = total_ > 0 ? static_cast<int>(kWidth * std::min(done, total_) / total_) : kWidth;
  const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '-');
  std::fputs(fmt::format("\r[{}] {}/{} frames  {:.1f} fps  ETA {}:{:02d} ", bar, done, total_, rate, eta / 60, eta % 60)
                 .c_str(),
             stderr);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressMeter::clear() {
  std::lock_guard lock(drawMutex_);
  if (!drawn_) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace rollspin::jobs
