// `cmake --install build --prefix P` lays rollspin out like a tool: the
// binary renders a bundled scene by name from another directory (the scenes
// found through ../share/rollspin/scenes), and the man page and the bash
// and zsh completions are where man and the shells look: zsh's completion
// in P/share/zsh/site-functions (on Debian, /usr/local/share/zsh/site-functions
// is in zsh's fpath), under /usr in vendor-completions, as in the .deb, whose
// man page is gzip -9n (scripts/cpack_deb_man_pages.cmake).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using rollspin::test::freshTempDir;

TEST(Install, LaysOutATool) {
  const fs::path prefix = freshTempDir("install_prefix");
  const std::string install = "\"" + rollspin::test::cmakeCommand() + "\" --install \"" +
                              rollspin::test::buildDir().string() + "\" --prefix \"" + prefix.string() + "\" > \"" +
                              (prefix / "install.log").string() + "\" 2>&1";
  ASSERT_EQ(std::system(install.c_str()), 0) << rollspin::test::readFile(prefix / "install.log");
  EXPECT_TRUE(fs::is_regular_file(prefix / "bin" / "rollspin"));
  EXPECT_TRUE(fs::is_regular_file(prefix / "share" / "rollspin" / "scenes" / "lollipop.toml"));
  EXPECT_TRUE(fs::is_regular_file(prefix / "share" / "man" / "man1" / "rollspin.1"));
  EXPECT_TRUE(fs::is_regular_file(prefix / "share" / "bash-completion" / "completions" / "rollspin"));
  EXPECT_TRUE(fs::is_regular_file(prefix / "share" / "zsh" / "site-functions" / "_rollspin"));
  EXPECT_FALSE(fs::exists(prefix / "share" / "zsh" / "vendor-completions")) << "vendor-completions is /usr's";
  EXPECT_FALSE(fs::exists(prefix / "share" / "rollspin" / "shaders")) << "shaders are compiled in";
  EXPECT_NE(rollspin::test::readFile(prefix / "share" / "man" / "man1" / "rollspin.1").find(".SS \"rollspin render"),
            std::string::npos);

  // From another directory, by name, with the installed binary only.
  const fs::path elsewhere = freshTempDir("install_cwd");
  const std::string render = "cd \"" + elsewhere.string() + "\" && \"" + (prefix / "bin" / "rollspin").string() +
                             "\" render lollipop --still --width 320 --height 180 -o x.png --quiet > render.log 2>&1";
  ASSERT_EQ(std::system(render.c_str()), 0) << rollspin::test::readFile(elsewhere / "render.log");
  EXPECT_GT(fs::file_size(elsewhere / "x.png"), 1000u);
  const std::string scenes =
      "\"" + (prefix / "bin" / "rollspin").string() + "\" scenes > \"" + (elsewhere / "scenes.txt").string() + "\"";
  ASSERT_EQ(std::system(scenes.c_str()), 0);
  EXPECT_NE(
      rollspin::test::readFile(elsewhere / "scenes.txt").find((prefix / "share" / "rollspin" / "scenes").string()),
      std::string::npos)
      << rollspin::test::readFile(elsewhere / "scenes.txt");
}

// `cmake --install build` into DESTDIR with prefix /usr, as cpack -G DEB
// does, then the package's pre-build script on the staged tree: the zsh
// completion in Debian's vendor-completions, the man page compressed
// without a name or time stamp (gzip -n: the header's FLG has no FNAME bit
// and MTIME is 0), and its text unchanged.
TEST(Install, UnderUsrLaysOutTheDebianPackage) {
  const fs::path stage = freshTempDir("install_deb_stage");
  const std::string install = "DESTDIR=\"" + stage.string() + "\" \"" + rollspin::test::cmakeCommand() +
                              "\" --install \"" + rollspin::test::buildDir().string() + "\" --prefix /usr > \"" +
                              (stage / "install.log").string() + "\" 2>&1";
  ASSERT_EQ(std::system(install.c_str()), 0) << rollspin::test::readFile(stage / "install.log");
  const fs::path usr = stage / "usr";
  EXPECT_TRUE(fs::is_regular_file(usr / "share" / "zsh" / "vendor-completions" / "_rollspin"));
  EXPECT_FALSE(fs::exists(usr / "share" / "zsh" / "site-functions"));
  const fs::path page = usr / "share" / "man" / "man1" / "rollspin.1";
  ASSERT_TRUE(fs::is_regular_file(page)) << "cmake --install keeps the man page uncompressed";
  const std::string roff = rollspin::test::readFile(page);

  const fs::path script = rollspin::test::sourceDir() / "scripts" / "cpack_deb_man_pages.cmake";
  const std::string compress = "\"" + rollspin::test::cmakeCommand() +
                               "\" -DCPACK_GENERATOR=DEB -DCPACK_TEMPORARY_DIRECTORY=\"" + stage.string() + "\" -P \"" +
                               script.string() + "\" > \"" + (stage / "compress.log").string() + "\" 2>&1";
  ASSERT_EQ(std::system(compress.c_str()), 0) << rollspin::test::readFile(stage / "compress.log");
  EXPECT_FALSE(fs::exists(page));
  const fs::path gz = usr / "share" / "man" / "man1" / "rollspin.1.gz";
  ASSERT_TRUE(fs::is_regular_file(gz));
  const std::string bytes = rollspin::test::readFile(gz);
  ASSERT_GT(bytes.size(), 10u);
  EXPECT_EQ(static_cast<unsigned char>(bytes[0]), 0x1f);
  EXPECT_EQ(static_cast<unsigned char>(bytes[1]), 0x8b);
  EXPECT_EQ(bytes[3] & 0x08, 0) << "gzip stored the file name (not -n)";
  EXPECT_EQ(bytes.substr(4, 4), std::string(4, '\0')) << "gzip stored a time stamp (not -n)";
  const std::string unzip = "gzip -dc \"" + gz.string() + "\" > \"" + (stage / "page.1").string() + "\"";
  ASSERT_EQ(std::system(unzip.c_str()), 0);
  EXPECT_EQ(rollspin::test::readFile(stage / "page.1"), roff);
}

}  // namespace
