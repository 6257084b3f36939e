// core/output_path.hpp: an output path is refused up front (BadInput, at the
// flag's location) where writing it would only fail at the end, and the
// checks leave nothing behind.
#include "core/output_path.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;

struct OutputPathTest : ::testing::Test {
  fs::path dir = fs::temp_directory_path() / ("rollspin-output-path-" + std::to_string(::getpid()) + "-" +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
  const SourceLoc where{"-o", 0, 0};
  void SetUp() override {
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "a-file") << "x";
  }
  void TearDown() override { fs::remove_all(dir); }
  [[nodiscard]] std::size_t entries() const {
    return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}));
  }
};

// The message of the BadInput that `check` throws ("" if none).
template <class Check>
std::string refusal(const Check& check) {
  try {
    check();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_EQ(e.where().file, "-o");
    return e.message();
  }
  return "";
}

TEST_F(OutputPathTest, AFileGoesIntoAnExistingWritableFolder) {
  EXPECT_EQ(refusal([&] { checkOutputFile(dir / "clip.mp4", where); }), "");
  EXPECT_EQ(refusal([&] { checkOutputFile(dir / "a-file", where); }), "") << "an existing file is replaced";
  EXPECT_EQ(refusal([&] { checkOutputFile("/dev/null", where); }), "");
  EXPECT_EQ(entries(), 1u) << "the probe is removed";
}

TEST_F(OutputPathTest, AFileIsRefusedWhereItCouldNotBeWritten) {
  EXPECT_NE(refusal([&] { checkOutputFile(dir, where); }), "") << "a folder where a file goes";
  EXPECT_NE(refusal([&] { checkOutputFile(dir / "missing" / "clip.mp4", where); }), "") << "a missing parent";
  EXPECT_NE(refusal([&] { checkOutputFile(dir / "a-file" / "clip.mp4", where); }), "") << "a path through a file";
  EXPECT_EQ(entries(), 1u);
}

TEST_F(OutputPathTest, AFolderMayBeMissingButNotAFile) {
  EXPECT_EQ(refusal([&] { checkOutputFolder(dir / "frames" / "deep", where); }), "");
  EXPECT_FALSE(fs::exists(dir / "frames")) << "a check makes nothing";
  EXPECT_NE(refusal([&] { checkOutputFolder(dir / "a-file", where); }), "");
  EXPECT_NE(refusal([&] { checkOutputFolder(dir / "a-file" / "frames", where); }), "");
}

TEST_F(OutputPathTest, TheDefaultOutputIsInOutputAndItsFolderIsMadeOnlyWhenAsked) {
  EXPECT_EQ(defaultOutputFile("lollipop.mp4"), fs::path("output") / "lollipop.mp4");
  const fs::path file = dir / "made" / "here" / "still.png";
  createOutputParent(file);
  EXPECT_TRUE(fs::is_directory(dir / "made" / "here"));
  EXPECT_FALSE(fs::exists(file));
}

}  // namespace
}  // namespace rollspin
