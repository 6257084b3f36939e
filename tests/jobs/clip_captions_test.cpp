// jobs/clip_captions.hpp: a clip's title and storyboard captions as subtitle
// cues, frame for frame with the FrameClock that times the pictures: each
// frame's cue is its segment's title (else render.title) over its caption,
// a segment's title replaces render.title while it plays, and frames with
// neither are in no cue.
#include "jobs/clip_captions.hpp"

#include <gtest/gtest.h>

#include "model/rolling_model.hpp"
#include "motion/frame_clock.hpp"
#include "scene/scene_loader.hpp"

namespace rollspin::jobs {
namespace {

const char* const kStory = R"(
[ball]
radius = 1
[render]
title = "Rolling"
[animation]
fps = 10
hold = 0
[[segment]]
path = { kind = "line", length = 4 }
duration = 2
caption = "along a line"
[[segment]]
hold = 1
[[segment]]
path = { kind = "circle", radius = 2, turns = 0.5 }
duration = 2
caption = "round half a circle"
title = "Turning"
)";

// The text frame k of the clip shows, from the cues ("" where no cue covers it).
std::string textAt(const media::SubtitleCues& cues, long long k) {
  for (const media::SubtitleCue& c : cues)
    if (c.firstFrame <= k && k < c.endFrame) return c.text;
  return "";
}

TEST(ClipCaptions, EachFrameSaysItsSegmentsTitleAndCaption) {
  const scene::SceneSpec spec = scene::loadSceneText(kStory, "story.toml", {}, {});
  const model::RollingModel model = model::buildSceneModel(spec);
  const motion::FrameClock clock(model.segments, spec);
  const media::SubtitleCues cues = clipCaptionCues(spec, clock);
  ASSERT_FALSE(cues.empty());
  for (std::size_t i = 1; i < cues.size(); ++i) {
    EXPECT_LE(cues[i - 1].endFrame, cues[i].firstFrame) << "cues in order, not overlapping";
    EXPECT_FALSE(cues[i - 1].endFrame == cues[i].firstFrame && cues[i - 1].text == cues[i].text)
        << "a run of one text is one cue";
  }
  const std::string expected[] = {"Rolling\nalong a line", "Rolling", "Turning\nround half a circle"};
  for (long long k = 0; k < clock.frameCount(); ++k)
    EXPECT_EQ(textAt(cues, k), expected[clock.place(k).segment]) << "frame " << k;
  EXPECT_EQ(cues.front().firstFrame, 0);
  EXPECT_EQ(cues.back().endFrame, clock.frameCount());
}

TEST(ClipCaptions, NoTitleAndNoCaptionIsNoCue) {
  const scene::SceneSpec spec =
      scene::loadSceneText("[ball]\nradius = 1\n[path]\nkind = \"circle\"\nradius = 3\n", "plain.toml", {}, {});
  const model::RollingModel model = model::buildSceneModel(spec);
  const motion::FrameClock clock(model.path->length(), spec);
  EXPECT_TRUE(clipCaptionCues(spec, clock).empty());
}

}  // namespace
}  // namespace rollspin::jobs
