// `cmake --install build --prefix P` lays rollspin out like a tool: the
// binary renders a bundled scene by name from another directory (the scenes
// found through ../share/rollspin/scenes), and the man page and the bash
// and zsh completions are where man and the shells look.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "support/cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using rollspin::test::freshTempDir;

TEST(Install, LaysOutATool) {
  const fs::path prefix = freshTempDir("install_prefix");
  const std::string install = std::string("\"") + ROLLSPIN_CMAKE + "\" --install \"" + ROLLSPIN_BUILD_DIR +
                              "\" --prefix \"" + prefix.string() + "\" > \"" + (prefix / "install.log").string() +
                              "\" 2>&1";
  ASSERT_EQ(std::system(install.c_str()), 0) << rollspin::test::readFile(prefix / "install.log");
  EXPECT_TRUE(fs::is_regular_file(prefix / "bin" / "rollspin"));
  EXPECT_TRUE(fs::is_regular_file(prefix / "share" / "rollspin" / "scenes" / "lollipop.toml"));
  EXPECT_TRUE(fs::is_regular_file(prefix / "share" / "man" / "man1" / "rollspin.1"));
  EXPECT_TRUE(fs::is_regular_file(prefix / "share" / "bash-completion" / "completions" / "rollspin"));
  EXPECT_TRUE(fs::is_regular_file(prefix / "share" / "zsh" / "vendor-completions" / "_rollspin"));
  EXPECT_FALSE(fs::exists(prefix / "share" / "rollspin" / "shaders")) << "shaders are compiled in";
  EXPECT_NE(rollspin::test::readFile(prefix / "share" / "man" / "man1" / "rollspin.1").find(".SS \"rollspin render"),
            std::string::npos);

  // From another directory, by name, with the installed binary only.
  const fs::path elsewhere = freshTempDir("install_cwd");
  const std::string render = "cd \"" + elsewhere.string() + "\" && \"" + (prefix / "bin" / "rollspin").string() +
                             "\" render lollipop --still --width 320 --height 180 -o x.png --quiet > render.log 2>&1";
  ASSERT_EQ(std::system(render.c_str()), 0) << rollspin::test::readFile(elsewhere / "render.log");
  EXPECT_GT(fs::file_size(elsewhere / "x.png"), 1000u);
  const std::string scenes = "\"" + (prefix / "bin" / "rollspin").string() + "\" scenes > \"" +
                             (elsewhere / "scenes.txt").string() + "\"";
  ASSERT_EQ(std::system(scenes.c_str()), 0);
  EXPECT_NE(rollspin::test::readFile(elsewhere / "scenes.txt").find((prefix / "share" / "rollspin" / "scenes").string()),
            std::string::npos)
      << rollspin::test::readFile(elsewhere / "scenes.txt");
}

}  // namespace
