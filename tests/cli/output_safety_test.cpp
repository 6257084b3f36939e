// Outputs are whole or absent: every writing command (timeline, report, a
// still, a video) stopped by SIGINT or SIGTERM exits 128 + signal, says on
// stderr what it left, and leaves no temporary (a crash removes it too); a temporary left by a process
// that died hard is removed by the next run to the same name; an output path
// that cannot work is refused (exit 2) before any work.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <sstream>

#include "support/cli_runner.hpp"

namespace fs = std::filesystem;
namespace test = rollspin::test;

namespace {

// Every entry of `dir` but the stderr capture.
std::vector<std::string> entriesBesideStderr(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename() != "stderr") names.push_back(fs::relative(e.path(), dir).string());
  std::sort(names.begin(), names.end());
  return names;
}

bool stderrHas(const fs::path& dir, const std::string& text) {
  return test::readFile(dir / "stderr").find(text) != std::string::npos;
}

bool anyEntryStartsWith(const fs::path& dir, const std::string& prefix) {
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    if (e.path().filename().string().starts_with(prefix)) return true;
  return false;
}

const char* signalName(int signal) { return signal == SIGINT ? "SIGINT" : "SIGTERM"; }

// Runs `args`, waits for `ready`, sends `signal`; the child must exit (not be
// killed) with 128 + signal and name the signal on stderr.
template <typename Ready>
std::string interrupt(const fs::path& dir, const std::vector<std::string>& args, Ready ready, int signal) {
  test::SpawnedRollspin child(args, dir / "stderr");
  EXPECT_TRUE(child.waitUntil(ready)) << "never got under way: " << test::readFile(dir / "stderr");
  test::sleepMilliseconds(100);  // into the work, not at its door
  EXPECT_EQ(kill(child.pid(), signal), 0);
  bool signalled = false;
  const int code = child.wait(&signalled);
  const std::string err = test::readFile(dir / "stderr");
  EXPECT_FALSE(signalled) << "killed by " << signalName(signal) << " instead of cleaning up: " << err;
  EXPECT_EQ(code, 128 + signal) << err;
  EXPECT_NE(err.find(std::string("rollspin: interrupted (") + signalName(signal) + ")"), std::string::npos) << err;
  return err;
}

class Interrupted : public ::testing::TestWithParam<int> {};

TEST_P(Interrupted, TimelineLeavesNothingAndSaysSo) {
  const int signal = GetParam();
  const fs::path dir = test::freshTempDir(std::string("interrupt_timeline_") + signalName(signal));
  const fs::path out = dir / "big.csv";
  const std::string err = interrupt(
      dir,
      {"timeline", test::shippedScenePath("lollipop"), "--set", "timeline.samples=5000000", "--set", "path.turns=1000",
       "-o", out.string()},
      [&] { return anyEntryStartsWith(dir, ".big.csv."); }, signal);
  EXPECT_NE(err.find("removed the unfinished " + out.string()), std::string::npos) << err;
  EXPECT_EQ(entriesBesideStderr(dir), std::vector<std::string>{}) << err;
}

TEST_P(Interrupted, ReportLeavesOnlyCompleteFiles) {
  const int signal = GetParam();
  const fs::path dir = test::freshTempDir(std::string("interrupt_report_") + signalName(signal));
  const std::string err = interrupt(
      dir,
      {"report", "errors", test::shippedScenePath("lollipop"), "--set", "path.turns=400", "-o",
       (dir / "report").string()},
      [&] { return stderrHas(dir, "reference"); }, signal);
  EXPECT_NE(err.find("any output already reported as written is complete"), std::string::npos) << err;
  for (const std::string& name : entriesBesideStderr(dir))
    EXPECT_EQ(name.find(".tmp"), std::string::npos) << "a temporary is left: " << name;
  // Whatever the report said it wrote is there.
  std::istringstream lines(err);
  for (std::string line; std::getline(lines, line);)
    if (line.starts_with("rollspin: wrote ")) {
      EXPECT_TRUE(fs::exists(line.substr(16))) << line;
    }
}

TEST_P(Interrupted, StillLeavesNothingAndSaysSo) {
  const int signal = GetParam();
  const fs::path dir = test::freshTempDir(std::string("interrupt_still_") + signalName(signal));
  const fs::path out = dir / "still.png";
  // A large frame: the render outlasts the wait after the GL context is made.
  const std::string err = interrupt(
      dir,
      {"render", test::shippedScenePath("lollipop"), "--still", "--verbose", "--width", "4096", "--height", "4096",
       "--set", "render.msaa=4", "-o", out.string()},
      [&] { return stderrHas(dir, "stage: gl-context"); }, signal);
  EXPECT_NE(err.find("nothing unfinished left"), std::string::npos) << err;
  EXPECT_EQ(entriesBesideStderr(dir), std::vector<std::string>{}) << err;
}

TEST_P(Interrupted, PngFramesLeaveAPartialFolderNamedSo) {
  const int signal = GetParam();
  const fs::path dir = test::freshTempDir(std::string("interrupt_frames_") + signalName(signal));
  const fs::path out = dir / "frames";
  const std::string err = interrupt(
      dir,
      {"render", test::shippedScenePath("lollipop"), "--set", "render.width=64", "--set", "render.height=48", "--set",
       "animation.duration=100", "-o", out.string() + "/"},
      [&] { return anyEntryStartsWith(dir, "frame_00002.png"); }, signal);
  EXPECT_NE(err.find(out.string() + ".partial holds complete frames"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(out));
  for (const std::string& name : entriesBesideStderr(dir)) EXPECT_TRUE(name.starts_with("frames.partial")) << name;
}

// A second Ctrl-C (seconds, not milliseconds, after the first) does not wait
// for the video to be finished: the shared clean-up removes the temporary
// and the process exits 130 at once (it was killed by the signal, leaving
// .clip.mp4.PID.tmp behind).
TEST(SecondSignal, EndsAVideoAtOnceWithoutATemporary) {
  const fs::path dir = test::freshTempDir("interrupt_twice");
  test::SpawnedRollspin child(
      {"render", test::shippedScenePath("lollipop"), "--set", "render.width=640", "--set", "render.height=480", "--set",
       "animation.duration=100", "-o", (dir / "clip.mp4").string()},
      dir / "stderr");
  ASSERT_TRUE(child.waitUntil([&] {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
      if (e.path().filename().string().starts_with(".clip.mp4.") && e.file_size() > 4096) return true;
    return false;
  })) << test::readFile(dir / "stderr");
  ASSERT_EQ(kill(child.pid(), SIGINT), 0);
  // A deliberate second Ctrl-C: later than InterruptGuard's 250 ms, within
  // which a second signal is the same interruption delivered twice (to the
  // process and its group). The flush may finish first: then the partial stays.
  test::sleepMilliseconds(400);
  ASSERT_EQ(kill(child.pid(), SIGINT), 0);
  bool signalled = false;
  const int code = child.wait(&signalled);
  const std::string err = test::readFile(dir / "stderr");
  EXPECT_FALSE(signalled) << err;
  EXPECT_EQ(code, 128 + SIGINT) << err;
  EXPECT_NE(err.find("interrupted (SIGINT)"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "clip.mp4"));
  for (const std::string& name : entriesBesideStderr(dir))
    EXPECT_TRUE(name == "clip.partial.mp4") << "left behind: " << name;
}

// A crash (here a signal sent from outside: the same handler runs) says which
// signal with a backtrace, removes the unfinished video's temporary, and the
// process still dies of that signal (exit status and core dump unchanged).
class Crashed : public ::testing::TestWithParam<int> {};

TEST_P(Crashed, SaysWhereRemovesTheTemporaryAndDiesOfTheSignal) {
#if defined(ROLLSPIN_ADDRESS_SANITIZER)
  GTEST_SKIP() << "under the sanitizers their own crash report runs instead";
#endif
  const int signal = GetParam();
  const std::string name = signal == SIGSEGV ? "SIGSEGV" : "SIGABRT";
  const fs::path dir = test::freshTempDir("crash_" + name);
  const rlimit noCore{0, 0};  // inherited by the child: no core file in the build tree
  ASSERT_EQ(setrlimit(RLIMIT_CORE, &noCore), 0);
  test::SpawnedRollspin child(
      {"render", test::shippedScenePath("lollipop"), "--set", "render.width=320", "--set", "render.height=180", "--set",
       "animation.duration=100", "-o", (dir / "clip.mp4").string()},
      dir / "stderr");
  ASSERT_TRUE(child.waitUntil([&] { return anyEntryStartsWith(dir, ".clip.mp4."); })) << test::readFile(dir / "stderr");
  test::sleepMilliseconds(100);
  ASSERT_EQ(kill(child.pid(), signal), 0);
  bool signalled = false;
  const int code = child.wait(&signalled);
  const std::string err = test::readFile(dir / "stderr");
  EXPECT_TRUE(signalled) << err;
  EXPECT_EQ(code, 128 + signal) << err;
  EXPECT_NE(err.find("rollspin: fatal signal " + name), std::string::npos) << err;
  EXPECT_NE(err.find("rollspin(+0x"), std::string::npos) << "no frame of rollspin's own: " << err;
  EXPECT_NE(err.find("libc.so.6"), std::string::npos) << "no library frame: " << err;
  EXPECT_NE(err.find("rollspin: crashed: removed the unfinished " + (dir / "clip.mp4").string()), std::string::npos)
      << err;
  EXPECT_EQ(entriesBesideStderr(dir), std::vector<std::string>{}) << err;
}

INSTANTIATE_TEST_SUITE_P(Signals, Crashed, ::testing::Values(SIGSEGV, SIGABRT),
                         [](const auto& info) { return std::string(info.param == SIGSEGV ? "SIGSEGV" : "SIGABRT"); });

INSTANTIATE_TEST_SUITE_P(Signals, Interrupted, ::testing::Values(SIGINT, SIGTERM),
                         [](const auto& info) { return std::string(signalName(info.param)); });

// A PID no process has: the largest free one below pid_max.
long deadPid() {
  long pid = 4194000;
  while (kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) --pid;
  return pid;
}

TEST(StaleTemporaries, TheNextRunToTheSameNameRemovesThoseOfDeadProcessesOnly) {
  const fs::path dir = test::freshTempDir("stale_temporaries");
  const std::string dead = std::to_string(deadPid()), alive = std::to_string(getpid());
  for (const std::string& name :
       std::vector<std::string>{".t.csv." + dead + ".tmp", ".t.csv." + alive + ".tmp", ".t.csv.12ab.tmp",
                                ".u.csv." + dead + ".tmp", ".clip.mp4." + dead + ".tmp"})
    std::ofstream(dir / name) << "half";
  fs::create_directories(dir / (".frames." + dead + ".tmp"));
  std::ofstream(dir / (".frames." + dead + ".tmp") / "frame_00000.png") << "half";

  const auto csv = test::runRollspin({"timeline", test::shippedScenePath("lollipop"), "-o", (dir / "t.csv").string()});
  ASSERT_EQ(csv.exitCode, 0) << csv.err;
  EXPECT_NE(csv.err.find("removed " + (dir / (".t.csv." + dead + ".tmp")).string()), std::string::npos) << csv.err;
  const auto mp4 = test::runRollspin({"render", test::shippedScenePath("lollipop"), "--set", "render.width=64", "--set",
                                      "render.height=48", "--frames", "0:1", "-o", (dir / "clip.mp4").string()});
  ASSERT_EQ(mp4.exitCode, 0) << mp4.err;
  const auto frames =
      test::runRollspin({"render", test::shippedScenePath("lollipop"), "--set", "render.width=64", "--set",
                         "render.height=48", "--frames", "0:1", "-o", (dir / "frames").string()});
  ASSERT_EQ(frames.exitCode, 0) << frames.err;
  std::vector<std::string> top;
  for (const auto& e : fs::directory_iterator(dir)) top.push_back(e.path().filename().string());
  std::sort(top.begin(), top.end());
  std::vector<std::string> expected{".t.csv." + alive + ".tmp",
                                    ".t.csv.12ab.tmp",
                                    ".u.csv." + dead + ".tmp",
                                    "clip.mp4",
                                    "frames",
                                    "t.csv",
                                    "t.csv.json"};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(top, expected) << "dead-owner temporaries of these names go; a live owner's, other names and other "
                              "patterns stay";
}

// ---- output paths refused before any work -----------------------------

struct OutputCase {
  const char* name;
  std::vector<std::string> args;  // {DIR} is replaced
  const char* message;
};

TEST(OutputPaths, RefusedWithExit2BeforeAnyWork) {
  const fs::path dir = test::freshTempDir("output_paths");
  fs::create_directories(dir / "adir.mp4");
  fs::create_directories(dir / "adir.csv");
  std::ofstream(dir / "afile") << "x";
  const std::vector<OutputCase> cases = {
      {"mp4 onto a folder",
       {"render", test::shippedScenePath("lollipop"), "-o", "{DIR}/adir.mp4"},
       "'{DIR}/adir.mp4' is a directory"},
      {"csv onto a folder",
       {"timeline", test::shippedScenePath("lollipop"), "-o", "{DIR}/adir.csv"},
       "'{DIR}/adir.csv' is a directory"},
      {"still through a file",
       {"render", test::shippedScenePath("lollipop"), "--still", "-o", "{DIR}/afile/x.png"},
       "'{DIR}/afile' is a file, not a folder"},
      {"csv in a missing folder",
       {"timeline", test::shippedScenePath("lollipop"), "-o", "{DIR}/nope/x.csv"},
       "the folder '{DIR}/nope' does not exist"},
      {"mp4 in a folder that takes no files",
       {"render", test::shippedScenePath("lollipop"), "-o", "/proc/x.mp4"},
       "cannot write in the folder '/proc'"},
      {"frames onto a file",
       {"render", test::shippedScenePath("lollipop"), "-o", "{DIR}/afile"},
       "'{DIR}/afile' is a file; a folder is needed"},
      {"report into a file",
       {"report", "errors", test::shippedScenePath("lollipop"), "-o", "{DIR}/afile/r"},
       "'{DIR}/afile' is a file"},
      {"diff onto a folder", {"compare", "{GOLDEN}", "{GOLDEN}", "--diff", "{DIR}/adir.csv"}, "is a directory"},
      {"transparent JPEG",
       {"render", test::shippedScenePath("lollipop"), "--still", "--transparent", "-o", "{DIR}/out.jpg"},
       "JPEG has none"},
      {"still as MP4",
       {"render", test::shippedScenePath("lollipop"), "--still", "-o", "{DIR}/out.mp4"},
       "is an animation format (drop --still"},
      {"clip as JPEG",
       {"render", test::shippedScenePath("lollipop"), "-o", "{DIR}/out.jpg"},
       "is a still format (pass --still"},
  };
  const std::string golden = (test::sourceDir() / "tests" / "golden" / "strobe.png").string();
  auto fill = [&](std::string text) {
    for (const auto& [key, value] : {std::pair<std::string, std::string>{"{DIR}", dir.string()}, {"{GOLDEN}", golden}})
      for (std::size_t at; (at = text.find(key)) != std::string::npos;) text.replace(at, key.size(), value);
    return text;
  };
  for (const OutputCase& c : cases) {
    std::vector<std::string> args{"--verbose"};
    for (const std::string& a : c.args) args.push_back(fill(a));
    const auto r = test::runRollspin(args);
    EXPECT_EQ(r.exitCode, 2) << c.name << "\n" << r.err;
    EXPECT_NE(r.err.find(fill(c.message)), std::string::npos) << c.name << "\n" << r.err;
    for (const char* work : {"stage: solver", "stage: gl-context", "stage: encoder", "stage: timeline-csv"})
      EXPECT_EQ(r.err.find(work), std::string::npos) << c.name << ": refused only after " << work << "\n" << r.err;
  }
  std::vector<std::string> left = entriesBesideStderr(dir);
  EXPECT_EQ(left, (std::vector<std::string>{"adir.csv", "adir.mp4", "afile"})) << "nothing written";
}

}  // namespace
