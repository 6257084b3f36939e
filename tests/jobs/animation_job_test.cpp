// jobs/animation_job.hpp in process (label gl): which frames a run renders
// and where they go (--frames, --shard, the default names), the progress
// it reports (a GIF's palette pass counted), the quality presets, and the
// refusals made before any frame is rendered. The CLI's own tests
// (tests/cli/) run the same job as a subprocess, on every format.
#include "jobs/animation_job.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "support/test_files.hpp"

namespace rollspin::jobs {
namespace animation_job_test {

namespace fs = std::filesystem;

// A one-second clip of a ball on a circle at 12 frames a second, small and quick.
AnimationOptions smallClip(const fs::path& output) {
  AnimationOptions o;
  o.scenePath = "tiny_roll.toml";
  o.sceneText =
      "[ball]\nradius = 0.5\n[path]\nkind = \"circle\"\nradius = 2\n"
      "[animation]\nduration = 1\nfps = 12\nhold = 0\n[render]\nmsaa = 1\n";
  o.width = 64;
  o.height = 48;
  o.output = output;
  o.quiet = true;
  return o;
}

// The error `call` throws (a test failure, and an empty error, when none).
template <typename Call>
Error animationErrorOf(Call call) {
  try {
    call();
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error";
  return Error(ErrorKind::Runtime, {}, "");
}

std::vector<std::string> namesIn(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(AnimationJob, QualityPresetsAreManimsSizesAndRates) {
  const QualityPreset* high = findQualityPreset("high");
  ASSERT_NE(high, nullptr);
  EXPECT_EQ((std::vector<int>{high->width, high->height, high->fps}), (std::vector<int>{1920, 1080, 60}));
  ASSERT_NE(findQualityPreset("low"), nullptr);
  EXPECT_EQ(findQualityPreset("low")->height, 480);
  EXPECT_EQ(findQualityPreset("4k")->width, 3840);
  EXPECT_EQ(findQualityPreset("medium")->fps, 30);
  EXPECT_EQ(findQualityPreset("ultra"), nullptr);
  EXPECT_EQ(findQualityPreset(""), nullptr);
}

TEST(AnimationJob, AFrameRangeIntoAFolderWritesThoseFramesUnderTheirClipIndex) {
  const fs::path dir = test::freshTempDir("animation_job_frames");
  AnimationOptions o = smallClip(dir / "frames");
  o.frames = "3:6";
  std::vector<std::pair<long long, long long>> progress;
  o.onFrame = [&](long long done, long long total) { progress.emplace_back(done, total); };
  const AnimationResult r = renderAnimation(o);
  EXPECT_EQ(r.framesRequested, 4);
  EXPECT_EQ(r.framesWritten, 4);
  EXPECT_EQ(r.interruptedBy, 0);
  EXPECT_EQ(namesIn(dir / "frames"),
            (std::vector<std::string>{"frame_00003.png", "frame_00004.png", "frame_00005.png", "frame_00006.png"}));
  EXPECT_EQ(progress, (std::vector<std::pair<long long, long long>>{{1, 4}, {2, 4}, {3, 4}, {4, 4}}));
}

// The palette pass looks at frames before any is written: the progress
// counts them too, and ends at its total.
TEST(AnimationJob, AGifsPalettePassIsCountedInItsProgress) {
  const fs::path dir = test::freshTempDir("animation_job_gif");
  AnimationOptions o = smallClip(dir / "clip.gif");
  long long lastDone = 0, total = 0, calls = 0;
  o.onFrame = [&](long long done, long long of) {
    EXPECT_EQ(done, lastDone + 1);
    lastDone = done;
    total = of;
    ++calls;
  };
  const AnimationResult r = renderAnimation(o);
  EXPECT_EQ(r.written, dir / "clip.gif");
  EXPECT_GE(r.framesWritten, 12);
  EXPECT_EQ(r.framesWritten, r.framesRequested);
  EXPECT_GT(total, r.framesWritten);
  EXPECT_EQ(lastDone, total);
  EXPECT_EQ(calls, total);
  EXPECT_TRUE(fs::exists(dir / "clip.gif"));
}

// Without -o, a part of a video takes a name of its own beside the clip's;
// a scene given as text is named by its caller, else "scene".
TEST(AnimationJob, APartOfAVideoIsNotGivenTheWholeClipsName) {
  const fs::path before = fs::current_path(), dir = test::freshTempDir("animation_job_default");
  fs::current_path(dir);
  AnimationOptions o = smallClip({});
  o.frames = "0:2";
  AnimationResult named, unnamed;
  o.sceneName = "tiny_roll";
  EXPECT_NO_THROW(named = renderAnimation(o));
  o.sceneName.clear();
  EXPECT_NO_THROW(unnamed = renderAnimation(o));
  fs::current_path(before);
  EXPECT_EQ(named.written, fs::path("output") / "tiny_roll.frames_0-2.mp4");
  EXPECT_EQ(unnamed.written, fs::path("output") / "scene.frames_0-2.mp4");
  EXPECT_TRUE(fs::exists(dir / "output" / "tiny_roll.frames_0-2.mp4"));
  EXPECT_FALSE(fs::exists(dir / "output" / "tiny_roll.mp4"));
  EXPECT_EQ(named.framesWritten, 3);
}

// Each refusal comes before the first frame and leaves nothing behind.
TEST(AnimationJob, WhatCannotBeRenderedIsRefusedBeforeAnyFrameNamingTheFlag) {
  const fs::path dir = test::freshTempDir("animation_job_refused");
  struct Case {
    const char* output;
    std::optional<std::string> frames, shard, quality;
    const char* flag;
    const char* says;
  };
  const std::vector<Case> cases{
      {"a.mp4", "0:2", "1/2", std::nullopt, "--shard 1/2", "give --frames or --shard, not both"},
      {"b.gif", std::nullopt, "1/2", std::nullopt, "--shard 1/2", "cannot be joined"},
      {"c.mp4", std::nullopt, std::nullopt, "ultra", "--quality ultra", "expected low (854x480@15)"},
      {"d.mp4", "9:40", std::nullopt, std::nullopt, "--frames 9:40", ""},
      {"e.html", "0:2", std::nullopt, std::nullopt, "--frames 0:2", "not to the web viewer"},
  };
  for (const Case& c : cases) {
    AnimationOptions o = smallClip(dir / c.output);
    o.frames = c.frames;
    o.shard = c.shard;
    o.quality = c.quality;
    const Error e = animationErrorOf([&] { (void)renderAnimation(o); });
    EXPECT_EQ(e.kind(), ErrorKind::BadInput) << c.output;
    EXPECT_EQ(e.where().file, c.flag) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
  }
  EXPECT_TRUE(namesIn(dir).empty());
}

}  // namespace animation_job_test
}  // namespace rollspin::jobs
