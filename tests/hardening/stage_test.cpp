// Only what a scene needs: `--verbose` lists the stages a job ran, and each
// job here must run exactly the stages its scene calls for — no GL context
// for solve/timeline, no encoder for a still, no twin geometry without the
// twin, no surface/texture/shadow for the twin alone, no font without labels.
#include <gtest/gtest.h>

#include <algorithm>
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
  for (const char* unwanted : {"twin-geometry", "encoder", "png-frames", "strobe"}) EXPECT_FALSE(has(s, unwanted)) << unwanted;
}

TEST(Stages, TwinOnlyStillWithoutLabelsBuildsNoSurfaceTextureShadowOrFont) {
  const auto dir = freshTempDir("stages");
  const auto s = stagesOf({"render", scene("sphere-outside.toml"), "--still", "--width", "160", "--height", "90",
                           "--set", "render.layout=twin", "--set", "render.labels=false", "--set",
                           "ball.texture=" + (sourceDir() / "docs").string() + "/none.png", "-o",
                           (dir / "b.png").string()});
  EXPECT_TRUE(has(s, "twin-geometry"));
  for (const char* unwanted : {"surface-mesh", "ball-texture", "shadow-map", "font", "encoder"})
    EXPECT_FALSE(has(s, unwanted)) << unwanted;
}

TEST(Stages, StrobeWithoutTrailsOrShadow) {
  const auto dir = freshTempDir("stages");
  const auto s = stagesOf({"render", scene("tennis-ball.toml"), "--still", "--width", "160", "--height", "90",
                           "--set", "render.strobe=5", "--set", "render.trails=false", "--set",
                           "render.shadow=false", "-o", (dir / "c.png").string()});
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
