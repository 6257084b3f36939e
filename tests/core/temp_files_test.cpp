// core/temp_files.hpp: the temporaries' one naming pattern, stale ones of
// dead processes removed (and nothing else), folders a command made removed
// again unless kept, and the signal names the handlers print. (The
// handlers themselves are exercised by the fault tests: tests/faults/.)
#include "core/temp_files.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace rollspin {
namespace {

namespace fs = std::filesystem;

struct TempFilesTest : ::testing::Test {
  fs::path dir = fs::temp_directory_path() / ("rollspin-temp-files-" + std::to_string(::getpid()) + "-" +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void SetUp() override {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
};

// A process id that is not running: a child that has exited and been reaped.
pid_t deadPid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

TEST_F(TempFilesTest, ATemporaryIsAHiddenNameWithThePidBesideTheOutput) {
  EXPECT_EQ(temporaryPathFor(dir / "clip.mp4"), dir / (".clip.mp4." + std::to_string(::getpid()) + ".tmp"));
  EXPECT_EQ(temporaryPathFor("clip.mp4").parent_path(), fs::path(""));
}

TEST_F(TempFilesTest, OnlyADeadProcesssTemporariesAreRemoved) {
  const fs::path out = dir / "clip.mp4";
  const std::string dead = std::to_string(deadPid()), alive = std::to_string(::getpid());
  std::ofstream(dir / (".clip.mp4." + dead + ".tmp")) << "stale";
  fs::create_directories(dir / (".clip.mp4." + dead + "9.tmp") / "frames");  // another dead one, a folder
  std::ofstream(dir / (".clip.mp4." + alive + ".tmp")) << "ours";            // a running process's
  std::ofstream(dir / (".other.mp4." + dead + ".tmp")) << "another output's";
  std::ofstream(dir / (".clip.mp4." + dead + ".tmp.bak")) << "not the pattern";
  std::ofstream(dir / "clip.mp4") << "the output";
  const int removed = removeStaleTemporaries(out);
  // (The second name's pid, dead's digits and a 9, may run by chance: then it stays.)
  const bool ninthRuns = ::kill(::pid_t(std::stoll(dead + "9")), 0) == 0;
  EXPECT_EQ(removed, ninthRuns ? 1 : 2);
  EXPECT_FALSE(fs::exists(dir / (".clip.mp4." + dead + ".tmp")));
  EXPECT_TRUE(fs::exists(dir / (".clip.mp4." + alive + ".tmp")));
  EXPECT_TRUE(fs::exists(dir / (".other.mp4." + dead + ".tmp")));
  EXPECT_TRUE(fs::exists(dir / (".clip.mp4." + dead + ".tmp.bak")));
  EXPECT_TRUE(fs::exists(dir / "clip.mp4"));
}

TEST_F(TempFilesTest, FoldersACommandMadeGoUnlessKept) {
  std::error_code ec;
  {
    CreatedFolders made(dir / "a" / "b" / "c", ec);
    ASSERT_FALSE(ec);
    EXPECT_TRUE(fs::is_directory(dir / "a" / "b" / "c"));
    std::ofstream(dir / "a" / "b" / "c" / "half.png") << "x";
  }
  EXPECT_FALSE(fs::exists(dir / "a")) << "a failed run leaves none of the folders it made";
  fs::create_directories(dir / "kept-before");
  {
    CreatedFolders made(dir / "kept-before" / "new", ec);
    ASSERT_FALSE(ec);
  }
  EXPECT_TRUE(fs::is_directory(dir / "kept-before")) << "a folder that existed stays";
  EXPECT_FALSE(fs::exists(dir / "kept-before" / "new"));
  {
    CreatedFolders made(dir / "report", ec);
    made.keep();
  }
  EXPECT_TRUE(fs::is_directory(dir / "report"));
}

TEST(SignalName, NamesTheSignalsTheHandlersReport) {
  EXPECT_EQ(signalName(SIGINT), "SIGINT");
  EXPECT_EQ(signalName(SIGTERM), "SIGTERM");
  EXPECT_EQ(signalName(SIGSEGV), "SIGSEGV");
  EXPECT_EQ(signalName(SIGABRT), "SIGABRT");
  EXPECT_EQ(signalName(100000), "SIG?");
}

}  // namespace
}  // namespace rollspin
