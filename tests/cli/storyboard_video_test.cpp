// A storyboard rendered through the CLI (label gl): the clip has the frames
// the segments and holds ask for, --frames across a join and a camera move
// is byte-identical to a full render, a caption change re-renders a held
// pose, and a settled hold repeats its pixels.
#include <gtest/gtest.h>

#include "media/image_io.hpp"
#include "media/video_probe.hpp"

#include <cmath>
#include "support/cli_runner.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;

// 96×64 at 4 fps: opening hold round(0.5·4) = 2, line 3 s = 12, circle 7 s =
// 28, rest 2.5 s = 10, last line 3/1.5 s = 8, closing hold 2: 62 frames.
// Frames 14 … 41 are the circle, 42 … 51 the rest (whose camera moves over
// its first second, frames 42 … 45), 52 … 59 the last line.
std::vector<std::string> story(std::vector<std::string> args) {
  args.insert(args.begin() + 1, (test::sourceDir() / "scenes/storyboard.toml").string());
  for (const char* s : {"render.width=96", "render.height=64", "animation.fps=4"}) {
    args.push_back("--set");
    args.push_back(s);
  }
  return args;
}

std::string frameName(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", k);
  return name;
}

TEST(StoryboardVideo, ClipHasTheSegmentsFramesAndHolds) {
  const fs::path dir = test::freshTempDir("storyboard_mp4");
  const auto r = test::runRollspin(story({"render", "-o", (dir / "s.mp4").string()}));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const test::VideoProbe probe = test::probeVideo(dir / "s.mp4");
  EXPECT_EQ(probe.ptsSeconds.size(), 62u);
  EXPECT_NEAR(probe.frameRate, 4.0, 1e-9);
}

TEST(StoryboardVideo, FramesAcrossJoinsAreByteIdenticalAndCaptionsRerender) {
  const fs::path dir = test::freshTempDir("storyboard_frames");
  ASSERT_EQ(test::runRollspin(story({"render", "-o", (dir / "full").string()})).exitCode, 0);
  const auto r = test::runRollspin(story({"render", "--frames", "38:55", "-o", (dir / "part").string()}));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir / "full")) ++count;
  EXPECT_EQ(count, 62u);
  for (int k = 38; k <= 55; ++k) {
    const std::string a = test::readFile(dir / "full" / frameName(k)), b = test::readFile(dir / "part" / frameName(k));
    EXPECT_FALSE(a.empty()) << k;
    EXPECT_TRUE(a == b) << frameName(k) << " differs between the full and the partial render";
  }
  auto frame = [&](int k) { return test::readFile(dir / "full" / frameName(k)); };
  // End of the circle → first frame of the rest: the same pose, a new caption.
  EXPECT_NE(frame(41), frame(42));
  // The rest's camera moves during its first second, then holds still.
  EXPECT_NE(frame(43), frame(44));
  EXPECT_EQ(frame(47), frame(48));
  EXPECT_EQ(frame(50), frame(51));
}

// A part that starts after the rest's camera move (frames 42 … 45) draws the
// camera where the move stopped; the whole clip must too, not repeat its last
// mid-move image over the held frames.
TEST(StoryboardVideo, HeldFramesAfterACameraMoveMatchAPartStartingThere) {
  const fs::path dir = test::freshTempDir("storyboard_after_move");
  ASSERT_EQ(test::runRollspin(story({"render", "-o", (dir / "full").string()})).exitCode, 0);
  const auto r = test::runRollspin(story({"render", "--frames", "46:48", "-o", (dir / "part").string()}));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (int k = 46; k <= 48; ++k)
    EXPECT_TRUE(test::readFile(dir / "full" / frameName(k)) == test::readFile(dir / "part" / frameName(k)))
        << frameName(k) << " differs between the full render and a part starting after the camera move";
}

// torus-to-floor at 96×64, 4 fps, no opening hold, a 1 s fade: frame 0,
// the torus 24 frames (1 … 24), the rest 6 (25 … 30), then the floor's
// circle from frame 31, whose first four frames (0, 0.25, 0.5, 0.75 s into
// it) are cross-fades from the torus's last picture (weights 1, 0.75, 0.5,
// 0.25).
std::vector<std::string> lecture(std::vector<std::string> args) {
  args.insert(args.begin() + 1, (test::sourceDir() / "scenes/torus-to-floor.toml").string());
  for (const char* s :
       {"render.width=96", "render.height=64", "animation.fps=4", "animation.hold=0", "segment[3].fade_seconds=1"}) {
    args.push_back("--set");
    args.push_back(s);
  }
  return args;
}

TEST(StoryboardVideo, ACrossFadeBetweenSurfacesIsByteIdenticalInAPartAndLiesBetweenBothViews) {
  const fs::path dir = test::freshTempDir("surface_fade_frames");
  ASSERT_EQ(test::runRollspin(lecture({"render", "-o", (dir / "full").string()})).exitCode, 0);
  const auto r = test::runRollspin(lecture({"render", "--frames", "32:34", "-o", (dir / "part").string()}));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (int k = 32; k <= 34; ++k)
    EXPECT_TRUE(test::readFile(dir / "full" / frameName(k)) == test::readFile(dir / "part" / frameName(k)))
        << frameName(k) << " differs between the full render and a part starting in the fade";
  auto frame = [&](int k) { return media::loadImage(dir / "full" / frameName(k), {"frame"}); };
  const media::Image torus = frame(30), floor = frame(35), half = frame(33);
  // The middle of the fade is the mean of the torus's last picture and the
  // floor's at that instant; the floor's view has barely moved by frame 35
  // (the circle eases in), so each byte lies within a few levels of the mean.
  double meanError = 0.0;
  for (std::size_t i = 0; i < half.rgba.size(); ++i)
    meanError += std::abs(double(half.rgba[i]) - 0.5 * (double(torus.rgba[i]) + double(floor.rgba[i])));
  meanError /= double(half.rgba.size());
  EXPECT_LT(meanError, 6.0);
  EXPECT_NE(test::readFile(dir / "full" / frameName(33)), test::readFile(dir / "full" / frameName(35)));
}

}  // namespace
}  // namespace rollspin
