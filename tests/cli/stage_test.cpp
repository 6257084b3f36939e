// Only what a scene needs: `--verbose` lists the stages a job ran, and each
// job here must run exactly the stages its scene calls for — no GL context
// for solve/timeline, no encoder for a still, no twin geometry without the
// twin, no surface/texture/shadow for the twin alone, no font without labels.
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "support/cli_runner.hpp"

using rollspin::test::freshTempDir;
using rollspin::test::runRollspin;
using rollspin::test::sourceDir;

namespace {

std::vector<std::string> stagesOf(const std::vector<std::string>& args) {
  std::vector<std::string> withVerbose = args;
  withVerbose.push_back("--verbose");
  const auto r = runRollspin(withVerbose);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  std::vector<std::string> stages;
  std::istringstream lines(r.err);
  for (std::string line; std::getline(lines, line);) {
    const std::string tag = "rollspin: stage: ";
    if (line.rfind(tag, 0) == 0) stages.push_back(line.substr(tag.size()));
  }
  return stages;
}

bool has(const std::vector<std::string>& stages, const std::string& s) {
  return std::find(stages.begin(), stages.end(), s) != stages.end();
}

std::string scene(const char* name) { return (sourceDir() / "scenes" / name).string(); }

}  // namespace

TEST(Stages, SolveRunsNoRenderer) {
  const auto s = stagesOf({"solve", scene("torus.toml")});
  EXPECT_EQ(s, (std::vector<std::string>{"scene", "model", "solver"}));
}

TEST(Stages, TimelineRunsNoRenderer) {
  const auto dir = freshTempDir("stages");
  const auto s = stagesOf({"timeline", scene("wall.toml"), "-o", (dir / "t.csv").string()});
  EXPECT_EQ(s, (std::vector<std::string>{"scene", "model", "solver", "timeline-csv"}));
}

TEST(Stages, BallOnlyStillBuildsNoTwinAndNoEncoder) {
  const auto dir = freshTempDir("stages");
  const auto s = stagesOf({"render", scene("lollipop.toml"), "--still", "--width", "160", "--height", "90", "--set",
                           "render.layout=ball", "-o", (dir / "a.png").string()});
  for (const char* want : {"scene", "model", "solver", "surface-mesh", "gl-context", "shadow-map", "png"})
    EXPECT_TRUE(has(s, want)) << want;
  for (const char* unwanted : {"twin-geometry", "encoder", "png-frames", "strobe"})
    EXPECT_FALSE(has(s, unwanted)) << unwanted;
}

TEST(Stages, TwinOnlyStillWithoutLabelsBuildsNoSurfaceTextureShadowOrFont) {
  const auto dir = freshTempDir("stages");
  const auto s =
      stagesOf({"render", scene("sphere-outside.toml"), "--still", "--width", "160", "--height", "90", "--set",
                "render.layout=twin", "--set", "render.labels=false", "--set",
                "ball.texture=" + (sourceDir() / "docs").string() + "/none.png", "-o", (dir / "b.png").string()});
  EXPECT_TRUE(has(s, "twin-geometry"));
  for (const char* unwanted : {"surface-mesh", "ball-texture", "shadow-map", "font", "encoder"})
    EXPECT_FALSE(has(s, unwanted)) << unwanted;
}

TEST(Stages, StrobeWithoutTrailsOrShadow) {
  const auto dir = freshTempDir("stages");
  const auto s = stagesOf({"render", scene("tennis-ball.toml"), "--still", "--width", "160", "--height", "90", "--set",
                           "render.strobe=5", "--set", "render.trails=false", "--set", "render.shadow=false", "-o",
                           (dir / "c.png").string()});
  EXPECT_TRUE(has(s, "strobe"));
  for (const char* unwanted : {"trails", "shadow-map", "encoder"}) EXPECT_FALSE(has(s, unwanted)) << unwanted;
}

TEST(Stages, VideoOpensTheEncoderOnce) {
  const auto dir = freshTempDir("stages");
  const auto s = stagesOf({"render", scene("penny.toml"), "--width", "128", "--height", "72", "--quiet", "--set",
                           "animation.duration=0.2", "--set", "animation.hold=0", "-o", (dir / "v.mp4").string()});
  for (const char* want : {"scene", "model", "solver", "gl-context", "encoder", "font", "shadow-map"})
    EXPECT_TRUE(has(s, want)) << want;
  EXPECT_FALSE(has(s, "png"));
}

// A render restarts itself once so that malloc can ask for huge pages
// (jobs/huge_pages.hpp); other commands do not, a user's own setting wins, and
// the pixels do not depend on it.
TEST(Stages, RenderRestartsOnceForHugePages) {
#if defined(ROLLSPIN_ADDRESS_SANITIZER)
  GTEST_SKIP() << "AddressSanitizer's malloc is not glibc's: no restart";
#endif
  if (rollspin::test::readFile("/sys/kernel/mm/transparent_hugepage/enabled").find("[madvise]") == std::string::npos)
    GTEST_SKIP() << "transparent huge pages are not in madvise mode here: no restart";
  const std::string line = "rollspin: memory: restarted with GLIBC_TUNABLES=glibc.malloc.hugetlb=1";
  const auto dir = freshTempDir("stages");
  const std::vector<std::string> still = {
      "render", scene("lollipop.toml"), "--still", "--width", "160", "--height", "90", "--verbose", "-o"};
  auto withOutput = [&](const char* name) {
    std::vector<std::string> args = still;
    args.push_back((dir / name).string());
    return args;
  };
  const auto restarted = runRollspin(withOutput("huge.png"), {}, 0, {"GLIBC_TUNABLES="});
  ASSERT_EQ(restarted.exitCode, 0) << restarted.err;
  const auto at = restarted.err.find(line);
  EXPECT_NE(at, std::string::npos) << restarted.err;
  EXPECT_EQ(restarted.err.find(line, at + 1), std::string::npos) << "restarted twice:\n" << restarted.err;

  const auto kept = runRollspin(withOutput("small.png"), {}, 0, {"GLIBC_TUNABLES=glibc.malloc.hugetlb=0"});
  ASSERT_EQ(kept.exitCode, 0) << kept.err;
  EXPECT_EQ(kept.err.find("rollspin: memory:"), std::string::npos) << kept.err;
  const std::string huge = rollspin::test::readFile(dir / "huge.png");
  EXPECT_FALSE(huge.empty());
  EXPECT_EQ(huge, rollspin::test::readFile(dir / "small.png")) << "the pixels depend on the page size";

  const auto solve = runRollspin({"solve", scene("lollipop.toml"), "--verbose"}, {}, 0, {"GLIBC_TUNABLES="});
  EXPECT_EQ(solve.err.find("rollspin: memory:"), std::string::npos) << solve.err;

  // Restarted, the process keeps its name for ps, top and pkill (an exec of
  // /proc/self/exe would rename it "exe").
  if (const char* tunables = std::getenv("GLIBC_TUNABLES"); tunables != nullptr && *tunables != '\0')
    GTEST_SKIP() << "GLIBC_TUNABLES is set here: the spawned render would not restart";
  rollspin::test::SpawnedRollspin child({"render", scene("penny.toml"), "--width", "128", "--height", "72", "--set",
                                         "animation.duration=60", "--verbose", "-o", (dir / "long.mp4").string()},
                                        dir / "stderr");
  ASSERT_TRUE(child.waitUntil([&] { return rollspin::test::readFile(dir / "stderr").find(line) != std::string::npos; }))
      << rollspin::test::readFile(dir / "stderr");
  EXPECT_EQ(rollspin::test::readFile("/proc/" + std::to_string(child.pid()) + "/comm"), "rollspin\n");
  EXPECT_EQ(kill(child.pid(), SIGTERM), 0);
  child.wait();
}
