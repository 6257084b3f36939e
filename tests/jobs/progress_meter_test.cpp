// jobs/progress_meter.hpp: the progress bar redrawn in place on a terminal (stderr a pseudo-terminal here),
// throttled, erased by clear(); nothing when stderr is no terminal or the job is quiet.
#include "jobs/progress_meter.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <regex>
#include <string>
#include <thread>
#include <vector>

namespace rollspin::jobs {
namespace {

// Marks the end of what the meter wrote (it never writes this byte).
constexpr char kMeterEnd = '\x01';

// stderr (fd 2) redirected for one test to a pseudo-terminal (`terminal`) or a pipe, drained as it is written
// (a bar redrawn without end would otherwise fill the buffer and block); what reached it read back.
class MeterStderr {
 public:
  explicit MeterStderr(bool terminal) {
    std::fflush(stderr);
    saved_ = ::dup(STDERR_FILENO);
    int writeEnd = -1;
    if (terminal) {
      read_ = ::posix_openpt(O_RDWR | O_NOCTTY);
      if (read_ >= 0 && ::grantpt(read_) == 0 && ::unlockpt(read_) == 0)
        if (const char* name = ::ptsname(read_)) writeEnd = ::open(name, O_RDWR | O_NOCTTY);
    } else {
      int fds[2];
      if (::pipe(fds) == 0) {
        read_ = fds[0];
        writeEnd = fds[1];
      }
    }
    ok_ = saved_ >= 0 && read_ >= 0 && writeEnd >= 0 && ::dup2(writeEnd, STDERR_FILENO) == STDERR_FILENO;
    if (writeEnd >= 0) ::close(writeEnd);
    if (ok_) reader_ = std::thread([this] { drain(); });
  }
  MeterStderr(const MeterStderr&) = delete;
  MeterStderr& operator=(const MeterStderr&) = delete;
  ~MeterStderr() {
    restore();
    stop_ = true;
    if (reader_.joinable()) reader_.join();
    if (read_ >= 0) ::close(read_);
  }
  [[nodiscard]] bool ok() const { return ok_; }

  // Everything written to stderr since the last call (stderr stays redirected).
  std::string written() {
    std::fflush(stderr);
    const char end = kMeterEnd;
    if (::write(STDERR_FILENO, &end, 1) != 1) return "(unwritable)";
    std::unique_lock lock(mutex_);
    // A bound for a broken pipe only: the mark comes as soon as the reader runs.
    if (!arrived_.wait_for(lock, std::chrono::seconds(20), [&] { return got_.find(kMeterEnd) != std::string::npos; }))
      return got_ + "(no end mark)";
    const std::size_t at = got_.find(kMeterEnd);
    std::string out = got_.substr(0, at);
    got_.erase(0, at + 1);
    return out;
  }

 private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_, STDERR_FILENO);
    ::close(saved_);
    saved_ = -1;
  }
  // Reads until the test is over and nothing more is waiting.
  void drain() {
    char buffer[4096];
    for (;;) {
      pollfd p{read_, POLLIN, 0};
      const int ready = ::poll(&p, 1, 20);
      if (ready < 0 && errno == EINTR) continue;
      if (ready <= 0 || (p.revents & POLLIN) == 0) {
        if (stop_ || ready < 0) return;
        continue;
      }
      const ssize_t n = ::read(read_, buffer, sizeof buffer);
      if (n <= 0) return;  // the write end closed (a pseudo-terminal's reads EIO)
      const std::lock_guard lock(mutex_);
      got_.append(buffer, std::size_t(n));
      arrived_.notify_all();
    }
  }

  int saved_ = -1, read_ = -1;
  bool ok_ = false;
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::string got_;
  std::thread reader_;
};

// The start of a redraw: back to the line's start, then the bar with `filled` of its 30 places filled.
std::string meterBarDrawn(int filled) {
  std::string bar = "\r[";
  bar.append(std::size_t(filled), '#').append(std::size_t(30 - filled), '-').push_back(']');
  return bar;
}

TEST(ProgressMeter, OnATerminalDrawsTheShareDoneOnOneLineRedrawnInPlace) {
  MeterStderr err(true);
  if (!err.ok()) GTEST_SKIP() << "no pseudo-terminal to draw on (/dev/ptmx)";
  ProgressMeter meter(4, false);
  EXPECT_TRUE(meter.onTerminal());
  EXPECT_EQ(err.written(), "") << "nothing before the first frame";
  meter.frameDone();
  const std::string first = err.written();
  EXPECT_TRUE(
      std::regex_match(first, std::regex(R"(\r\[#{7}-{23}\] 1/4 frames  [0-9]+\.[0-9] fps  ETA [0-9]+:[0-5][0-9] )")))
      << first;
  meter.frameDone();
  meter.frameDone();
  meter.frameDone();
  EXPECT_EQ(meter.framesDone(), 4);
  const std::string rest = err.written();
  EXPECT_EQ(rest.find('\n'), std::string::npos) << "one line: " << rest;
  // The last frame is always drawn, whatever the throttle: the full bar, nothing left to wait for.
  const std::size_t last = rest.rfind('\r');
  ASSERT_NE(last, std::string::npos) << rest;
  EXPECT_TRUE(
      std::regex_match(rest.substr(last), std::regex(R"(\r\[#{30}\] 4/4 frames  [0-9]+\.[0-9] fps  ETA 0:00 )")))
      << rest;
  EXPECT_EQ(rest.substr(last, 33), meterBarDrawn(30));
}

TEST(ProgressMeter, ClearErasesTheBarOnceAndOnlyIfOneIsDrawn) {
  MeterStderr err(true);
  if (!err.ok()) GTEST_SKIP() << "no pseudo-terminal to draw on (/dev/ptmx)";
  ProgressMeter meter(10, false);
  meter.clear();
  EXPECT_EQ(err.written(), "") << "no bar to erase yet";
  meter.frameDone();
  EXPECT_EQ(err.written().substr(0, 33), meterBarDrawn(3));
  meter.clear();
  EXPECT_EQ(err.written(), "\r\033[K");
  meter.clear();
  EXPECT_EQ(err.written(), "") << "already erased";
}

// A caller that counts one frame too many (a retried frame, say) still sees a full bar, not an exception from a
// negative remainder of the 30 places.
TEST(ProgressMeter, AFramePastTheTotalDrawsAFullBar) {
  MeterStderr err(true);
  if (!err.ok()) GTEST_SKIP() << "no pseudo-terminal to draw on (/dev/ptmx)";
  ProgressMeter meter(2, false);
  meter.frameDone();
  meter.frameDone();
  (void)err.written();
  std::this_thread::sleep_for(std::chrono::milliseconds(220));  // past the throttle: this frame is drawn
  EXPECT_NO_THROW(meter.frameDone());
  const std::string drawn = err.written();
  EXPECT_EQ(drawn.substr(0, 33), meterBarDrawn(30)) << drawn;
  EXPECT_NE(drawn.find("3/2 frames"), std::string::npos) << drawn;
  EXPECT_NE(drawn.find("ETA 0:00"), std::string::npos) << drawn;
}

// A bar redrawn for every frame would slow the render it shows: at most one redraw per 200 ms, so no more
// redraws than the time taken allows, however slow the machine (the last frame, always drawn, is not reached).
TEST(ProgressMeter, RedrawsAtMostFiveTimesASecond) {
  MeterStderr err(true);
  if (!err.ok()) GTEST_SKIP() << "no pseudo-terminal to draw on (/dev/ptmx)";
  ProgressMeter meter(1000, false);
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 200; ++i) meter.frameDone();
  const auto took = std::chrono::steady_clock::now() - start;
  const std::string drawn = err.written();
  const long long redraws = std::count(drawn.begin(), drawn.end(), '\r');
  EXPECT_GE(redraws, 1);
  EXPECT_LE(redraws, 1 + took / std::chrono::milliseconds(200)) << drawn;
  EXPECT_EQ(meter.framesDone(), 200);
}

TEST(ProgressMeter, WritesNothingWhenStderrIsNoTerminal) {
  MeterStderr err(false);
  ASSERT_TRUE(err.ok()) << "no pipe";
  ProgressMeter meter(3, false);
  EXPECT_FALSE(meter.onTerminal());
  for (int i = 0; i < 3; ++i) meter.frameDone();
  meter.clear();
  EXPECT_EQ(meter.framesDone(), 3);
  EXPECT_EQ(err.written(), "");
}

TEST(ProgressMeter, WritesNothingWhenQuietEvenOnATerminal) {
  MeterStderr err(true);
  if (!err.ok()) GTEST_SKIP() << "no pseudo-terminal to draw on (/dev/ptmx)";
  ProgressMeter meter(3, true);
  EXPECT_FALSE(meter.onTerminal());
  for (int i = 0; i < 3; ++i) meter.frameDone();
  meter.clear();
  EXPECT_EQ(meter.framesDone(), 3);
  EXPECT_EQ(err.written(), "");
}

// frameDone from the render's threads: every frame counted (none lost to a race), every bar drawn well formed, and
// the last frame's, full, among them.
TEST(ProgressMeter, CountsEveryFrameDoneFromSeveralThreads) {
  MeterStderr err(true);
  if (!err.ok()) GTEST_SKIP() << "no pseudo-terminal to draw on (/dev/ptmx)";
  constexpr int kThreads = 4, kEach = 20000;
  ProgressMeter meter(kThreads * kEach, false);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&] {
      for (int i = 0; i < kEach; ++i) meter.frameDone();
    });
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(meter.framesDone(), kThreads * kEach);
  const std::string drawn = err.written();
  const std::regex bar(R"(\r\[[#-]{30}\] [0-9]+/80000 frames  [0-9]+\.[0-9] fps  ETA [0-9]+:[0-5][0-9] )");
  std::size_t bars = 0;
  for (std::size_t at = drawn.find('\r'); at != std::string::npos; ++bars) {
    const std::size_t next = drawn.find('\r', at + 1);
    EXPECT_TRUE(std::regex_match(drawn.substr(at, next - at), bar)) << drawn.substr(at, next - at);
    at = next;
  }
  EXPECT_GE(bars, 1U);
  EXPECT_NE(drawn.find(meterBarDrawn(30) + " 80000/80000 frames"), std::string::npos) << "the last frame's bar";
}

}  // namespace
}  // namespace rollspin::jobs
