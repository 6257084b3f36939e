// version_info in-process: `rollspin --version`'s line (the release from the
// top-level project(), then git describe or "not built from a git clone") and
// the GL backend line, which names why no context can be made instead of
// throwing. The build's `git describe` is read from its generated header as
// a file (src/cli/git_describe.cmake writes it), not included: an include
// would compile this program again at every commit.
#include "cli/version_info.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <regex>
#include <string>

#include "support/cli_runner.hpp"
#include "support/test_files.hpp"

namespace version_info_test {

using rollspin::test::has;

// The release as the top-level CMakeLists.txt declares it: project(rollspin VERSION x.y.z ...).
std::string declaredRelease() {
  const std::string lists = rollspin::test::readFile(rollspin::test::sourceDir() / "CMakeLists.txt");
  std::smatch m;
  static const std::regex project(R"(project\(rollspin VERSION ([0-9]+\.[0-9]+\.[0-9]+))");
  return std::regex_search(lists, m, project) ? m[1].str() : "";
}

// The describe text of the build's generated header: #define ROLLSPIN_GIT_DESCRIBE "..." (empty outside a clone).
std::optional<std::string> builtDescribe() {
  const std::string header = rollspin::test::readFile(rollspin::test::buildDir() / "generated" / "git_describe.hpp");
  std::smatch m;
  static const std::regex define(R"re(#define ROLLSPIN_GIT_DESCRIBE "([^"]*)")re");
  if (!std::regex_search(header, m, define)) return std::nullopt;
  return m[1].str();
}

// Sets an environment variable for one scope and puts the old value back.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value, 1);
  }
  ~ScopedVariable() {
    if (old_) setenv(name_, old_->c_str(), 1);
    else unsetenv(name_);
  }
  ScopedVariable(const ScopedVariable&) = delete;
  ScopedVariable& operator=(const ScopedVariable&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(VersionInfo, LineNamesTheReleaseThenGitDescribeOrItsAbsence) {
  const std::string release = declaredRelease();
  ASSERT_FALSE(release.empty()) << "no project(rollspin VERSION ...) in " << rollspin::test::sourceDir();
  const std::optional<std::string> built = builtDescribe();
  ASSERT_TRUE(built) << "no ROLLSPIN_GIT_DESCRIBE in " << rollspin::test::buildDir() / "generated/git_describe.hpp";
  const std::string describe = *built;
  const std::string expected = "rollspin " + release + " (" +
                               (describe.empty() ? std::string("not built from a git clone") : "git " + describe) + ")";
  EXPECT_EQ(rollspin::cli::versionLine(), expected);
}

TEST(VersionInfo, LineIsOneLineOfTheDocumentedShape) {
  const std::string line = rollspin::cli::versionLine();
  static const std::regex shape(R"(rollspin [0-9]+\.[0-9]+\.[0-9]+ \((git [^\s()]+|not built from a git clone)\))");
  EXPECT_TRUE(std::regex_match(line, shape)) << line;
}

TEST(VersionInfo, AnUnknownBackendIsNamedNotThrown) {
  // The backend named in ROLLSPIN_GL is checked before any context is made:
  // no GL is needed to see the refusal.
  const ScopedVariable backend("ROLLSPIN_GL", "no-such-backend");
  std::string line;
  ASSERT_NO_THROW(line = rollspin::cli::glBackendDescription());
  EXPECT_TRUE(line.starts_with("none: ")) << line;
  EXPECT_TRUE(has(line, "no-such-backend")) << line;
}

}  // namespace version_info_test
