// Scene files as a new user writes them, through the built binary run from a
// folder outside the clone: `extends` naming a bundled scene ("storyboard")
// resolves as `render storyboard` does and, when there is none, says where it
// looked; an empty scene file (or one of comments only) is bad input that
// says how to print a full one; a key typed without its unit suffix is
// answered with the key in its unit.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using rollspin::test::runRollspin;
using rollspin::test::sourceDir;

using rollspin::test::has;

// A fresh folder outside the clone (the system's temporary folder), removed afterwards.
class OutsideTheClone : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rollspin-scene-files-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }
  fs::path dir_;
};

TEST_F(OutsideTheClone, ExtendsABundledSceneByName) {
  write("mine.toml", "extends = \"storyboard\"\n\n[render]\ntitle = \"mine\"\n");
  const auto mine = runRollspin({"scene", "mine.toml", "--print"}, dir_);
  ASSERT_EQ(mine.exitCode, 0) << mine.err;
  const auto bundled = runRollspin({"scene", "storyboard", "--print", "--set", "render.title=\"mine\""}, dir_);
  ASSERT_EQ(bundled.exitCode, 0) << bundled.err;
  // The same scene but for the header's first line (the file's name).
  EXPECT_EQ(mine.out.substr(mine.out.find('\n')), bundled.out.substr(bundled.out.find('\n')));
  // With .toml too, and a file beside the scene still comes first.
  write("lollipop.toml", "[ball]\nradius = 0.5\n");
  write("child.toml", "extends = \"lollipop.toml\"\n");
  const auto beside = runRollspin({"scene", "child.toml", "--print"}, dir_);
  ASSERT_EQ(beside.exitCode, 0) << beside.err;
  EXPECT_TRUE(has(beside.out, "radius = 0.5")) << beside.out;
}

TEST_F(OutsideTheClone, AMissingBaseSaysWhereItLooked) {
  write("mine.toml", "extends = \"storybord\"\n");
  const auto r = runRollspin({"scene", "mine.toml", "--print"}, dir_, 0, {"ROLLSPIN_SCENE_PATH=/nonexistent/scenes"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err,
                  "mine.toml:1:11: extends: cannot read the scene file 'storybord': there is none; looked in "
                  "the folder of mine.toml (" +
                      fs::canonical(dir_).string() + "), /nonexistent/scenes"))
      << r.err;
  EXPECT_TRUE(has(r.err, (sourceDir() / "scenes").string())) << r.err;
  EXPECT_TRUE(has(r.err, "did you mean 'storyboard'?")) << r.err;
}

TEST_F(OutsideTheClone, AnEmptySceneFileIsBadInput) {
  for (const std::string text : {"", "\n  \n", "# only a comment\n\n   # and another\r\n"}) {
    write("empty.toml", text);
    const auto r = runRollspin({"render", "empty.toml", "--still"}, dir_);
    EXPECT_EQ(r.exitCode, 2) << "text: '" << text << "'";
    EXPECT_TRUE(has(r.err, "empty.toml: empty scene: the file has no keys")) << r.err;
    EXPECT_TRUE(has(r.err, "`rollspin scene lollipop --print > empty.toml`")) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "output")) << "nothing written";
  }
  // Keys given with --set make a scene of an empty file.
  const auto set = runRollspin({"solve", "empty.toml", "--set", "path.radius=2"}, dir_);
  EXPECT_EQ(set.exitCode, 0) << set.err;
  // A table header alone is not empty: the default scene, as before.
  write("header.toml", "[render]\n");
  EXPECT_EQ(runRollspin({"solve", "header.toml"}, dir_).exitCode, 0);
}

TEST_F(OutsideTheClone, AKeyWithoutItsUnitSuggestsIt) {
  write("sphere.toml", "extends = \"sphere-outside\"\n\n[path]\ncolatitude = 60\n");
  const auto r = runRollspin({"solve", "sphere.toml"}, dir_);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(
      has(r.err, "sphere.toml:4:14: path.colatitude: unknown key; did you mean `colatitude_deg` (in degrees)?\n"))
      << r.err;
}

}  // namespace
