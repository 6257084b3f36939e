// A storyboard's frames: the clock (frame count = the segments' frames plus
// the holds, each motion ending exactly at its segment's end, which segment
// each frame is in) and the DrawList each frame becomes (the segment's
// caption and title, its camera, and the move from the previous camera).
// Plain data: no GL context is created.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "draw/scene_drawer.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_clock.hpp"
#include "scene/scene_loader.hpp"

namespace rollspin::motion {
namespace {
using namespace rollspin::model;
using namespace rollspin::draw;

constexpr const char* kStory = R"(
[render]
title = "the lecture"
[animation]
fps = 30
hold = 0.5
speed = 1.5
[[segment]]
path = { kind = "line", length = 4 }
duration = 3
caption = "first: a line"
[[segment]]
path = { kind = "circle", radius = 3 }
duration = 7
caption = "second: a circle"
title = "the circle"
camera = { azimuth_deg = 60, elevation_deg = 40 }
[[segment]]
hold = 2.5
caption = "third: rest"
[[segment]]
path = { kind = "line", length = 3 }
caption = "fourth: on"
)";

struct Story {
  scene::SceneSpec spec;
  RollingModel model;
};

Story load(const std::string& text, std::vector<std::string> overrides = {}) {
  Story s{scene::loadSceneText(text, "<story>", overrides), {}};
  s.model = buildModel(s.spec);
  return s;
}

TEST(StoryboardClock, FrameCountIsTheSegmentsFramesPlusTheHolds) {
  const Story s = load(kStory);
  const FrameClock clock = FrameClock(s.model.segments, s.spec);
  // Opening hold 15, line 3 s = 90, circle 7 s = 210, rest 2.5 s = 75, the
  // last line 3 / 1.5 = 2 s = 60 (animation.speed), closing hold 15.
  EXPECT_EQ(clock.frameCount(), 15 + 90 + 210 + 75 + 60 + 15);
  EXPECT_EQ(clock.motionFrames(), 90 + 210 + 60);
  const auto& spans = s.model.segments;
  ASSERT_EQ(spans.size(), 4u);
  for (long long k = 0; k < 15; ++k) EXPECT_EQ(clock.arcLength(k), 0.0);
  EXPECT_GT(clock.arcLength(15), 0.0);                // the first motion frame has moved
  EXPECT_EQ(clock.arcLength(15 + 89), spans[0].end);  // each motion ends exactly at its end
  EXPECT_EQ(clock.arcLength(105 + 209), spans[1].end);
  for (long long k = 315; k < 390; ++k) EXPECT_EQ(clock.arcLength(k), spans[2].start);  // the rest
  EXPECT_EQ(clock.arcLength(449), s.model.path->length());
  for (long long k = 450; k < 465; ++k) EXPECT_EQ(clock.arcLength(k), s.model.path->length());
  for (long long k = 1; k < clock.frameCount(); ++k) EXPECT_LE(clock.arcLength(k - 1), clock.arcLength(k)) << k;
  // Smooth easing per motion: it starts and stops at rest at every join.
  EXPECT_LT(clock.arcLength(105) - clock.arcLength(104), clock.arcLength(210) - clock.arcLength(209));

  EXPECT_EQ(clock.place(0).segment, 0u);
  EXPECT_EQ(clock.place(104).segment, 0u);
  EXPECT_EQ(clock.place(105).segment, 1u);
  EXPECT_EQ(clock.place(105).seconds, 0.0);
  EXPECT_NEAR(clock.place(135).seconds, 1.0, 1e-12);
  EXPECT_NEAR(clock.place(135).duration, 7.0, 1e-12);
  EXPECT_EQ(clock.place(315).segment, 2u);
  EXPECT_EQ(clock.place(390).segment, 3u);
  EXPECT_EQ(clock.place(464).segment, 3u);                    // the closing hold belongs to the last segment,
  EXPECT_NEAR(clock.place(464).seconds, 74.0 / 30.0, 1e-12);  // whose time runs on
  EXPECT_NEAR(clock.place(464).duration, 2.0, 1e-12);         // (a camera move ended with it)
}

TEST(StoryboardClock, NoHoldStillOpensOnTheStartAndTooShortAMotionIsBadInput) {
  const Story s = load(kStory, {"animation.hold=0"});
  const FrameClock clock(s.model.segments, s.spec);
  EXPECT_EQ(clock.frameCount(), 1 + 90 + 210 + 75 + 60);
  EXPECT_EQ(clock.arcLength(0), 0.0);
  const Story fast = load(kStory, {"animation.speed=1000"});
  try {
    (void)FrameClock(fast.model.segments, fast.spec);
    FAIL() << "a motion of 3 ms got frames";
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("animation.speed"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("segment[4]"), std::string::npos) << e.message();
  }
}

std::vector<std::string> texts(const render::DrawList& list) {
  std::vector<std::string> out;
  for (const auto& l : list.labels) out.push_back(l.text);
  return out;
}

bool has(const std::vector<std::string>& v, const std::string& text) {
  return std::find(v.begin(), v.end(), text) != v.end();
}

TEST(StoryboardFrames, EachSegmentShowsItsCaptionTitleAndCamera) {
  const Story s = load(kStory, {"render.width=320", "render.height=180"});
  const SceneDrawer drawer(s.spec, s.model, nullptr);
  auto frameAt = [&](std::size_t segment, double seconds, double duration) {
    FrameOrientations f;
    f.current.s = s.model.segments[segment].start;
    f.story = {segment, seconds, duration};
    return drawer.draw(f);
  };
  const std::vector<std::string> captions{"first: a line", "second: a circle", "third: rest", "fourth: on"};
  for (std::size_t k = 0; k < 4; ++k) {
    const auto labels = texts(frameAt(k, 10.0, 10.0));
    for (std::size_t j = 0; j < 4; ++j) EXPECT_EQ(has(labels, captions[j]), j == k) << k << " " << captions[j];
    // Segment 2's title replaces render.title while it plays.
    EXPECT_TRUE(has(labels, k == 1 ? "the circle" : "the lecture")) << k;
  }
  // The title band stays for every frame: the ball view starts below it.
  const render::DrawList first = frameAt(0, 10.0, 10.0), second = frameAt(1, 10.0, 10.0);
  EXPECT_EQ(first.views[1].y, second.views[1].y);
  EXPECT_GT(first.views[1].y, 0);

  // Cameras: segment 2 looks from azimuth 60°, elevation 40°; segment 3
  // keeps it (camera keys carry over); the move from segment 1's camera
  // starts exactly there and lasts one second.
  auto eye = [](const render::DrawList& l) { return l.views[1].camera.position; };
  auto eyeDirection = [&](const render::DrawList& l) {
    const glm::mat4& v = l.views[1].camera.viewFromWorld;
    return glm::vec3(v[0][2], v[1][2], v[2][2]);  // the view's +z (towards the eye) in world coordinates
  };
  const glm::vec3 settled = eyeDirection(second);
  EXPECT_NEAR(std::atan2(settled.y, settled.x), 60.0 * std::numbers::pi / 180.0, 1e-5);
  EXPECT_NEAR(std::asin(settled.z), 40.0 * std::numbers::pi / 180.0, 1e-5);
  const glm::vec3 kept = eyeDirection(frameAt(2, 10.0, 10.0));
  EXPECT_NEAR(glm::length(kept - settled), 0.0, 1e-6);
  const render::DrawList start = frameAt(1, 0.0, 7.0), half = frameAt(1, 0.5, 7.0), after = frameAt(1, 1.0, 7.0);
  EXPECT_NEAR(glm::length(eye(start) - eye(frameAt(0, 0.0, 3.0))), 0.0, 1e-4);  // where segment 1 left it
  EXPECT_NEAR(glm::length(eye(after) - eye(second)), 0.0, 1e-4);                // settled after 1 s
  EXPECT_GT(glm::length(eye(half) - eye(start)), 0.1);
  EXPECT_GT(glm::length(eye(half) - eye(after)), 0.1);
  const glm::vec3 mid = eyeDirection(half);
  const double midAzimuth = std::atan2(mid.y, mid.x);
  EXPECT_GT(midAzimuth, std::atan2(eyeDirection(start).y, eyeDirection(start).x));
  EXPECT_LT(midAzimuth, 60.0 * std::numbers::pi / 180.0);
}

}  // namespace
}  // namespace rollspin::motion
