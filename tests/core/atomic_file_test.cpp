// core/atomic_file.hpp: an output is written under a temporary name beside
// it and renamed over the final name only on commit(); anything else
// (destroyed uncommitted, a folder that does not exist) leaves nothing.
#include "core/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;

struct AtomicFileTest : ::testing::Test {
  fs::path dir = fs::temp_directory_path() / ("rollspin-atomic-" + std::to_string(::getpid()) + "-" +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void SetUp() override {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  [[nodiscard]] std::size_t entries() const {
    return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}));
  }
};

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST_F(AtomicFileTest, CommitRenamesTheTemporaryOverTheFinalName) {
  const fs::path out = dir / "clip.csv";
  {
    std::ofstream(out) << "old";
    AtomicFile file(out);
    EXPECT_EQ(file.tempPath().parent_path(), dir);
    EXPECT_NE(file.tempPath(), out);
    file.write("s,qw\n");
    file.write("0,1\n");
    EXPECT_EQ(contents(out), "old") << "the final name is untouched until commit";
    file.commit();
    EXPECT_FALSE(fs::exists(file.tempPath()));
  }
  EXPECT_EQ(contents(out), "s,qw\n0,1\n");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, AFileNotCommittedLeavesNothing) {
  const fs::path out = dir / "clip.mp4";
  fs::path temp;
  {
    AtomicFile file(out);
    temp = file.tempPath();
    file.write("half a clip");
    EXPECT_TRUE(fs::exists(temp));
  }
  EXPECT_FALSE(fs::exists(temp));
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(entries(), 0u);
}

TEST_F(AtomicFileTest, AMissingFolderIsARuntimeError) {
  try {
    AtomicFile file(dir / "no-such-folder" / "x.png");
    FAIL() << "opened a file in a folder that does not exist";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Runtime);
    EXPECT_NE(e.message().find("no-such-folder"), std::string::npos) << e.message();
  }
  EXPECT_EQ(entries(), 0u);
}

TEST_F(AtomicFileTest, ADeviceIsWrittenDirectly) {
  AtomicFile file("/dev/null");
  EXPECT_EQ(file.tempPath(), fs::path("/dev/null"));
  file.write("discarded");
  file.commit();
  EXPECT_TRUE(fs::exists("/dev/null"));
}

}  // namespace
}  // namespace rollspin
