// A storyboard across surfaces drawn (issue 53), as DrawLists: each
// surface's stretch framed by its own camera (a cut where the surface
// changes, the new ball in view), the cross-fade's weights over
// segment.fade_seconds and none with transition = "cut", the Bloch trail
// kept through the change. Plain data: no GL context is created.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>

#include "draw/scene_drawer.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_clock.hpp"
#include "motion/frame_sampling.hpp"
#include "scene/scene_loader.hpp"
#include "support/test_files.hpp"

namespace rollspin::draw {
namespace {

struct Lecture {
  scene::SceneSpec spec;
  model::RollingModel model;
};

Lecture lecture(std::vector<std::string> overrides = {}) {
  overrides.insert(overrides.end(), {"render.width=320", "render.height=180"});
  Lecture l{model::loadScene(test::shippedScenePath("torus-to-floor"), overrides), {}};
  l.model = model::buildModel(l.spec);
  return l;
}

// Where the ball's centre lands in the view's clip space (x, y in [−1, 1]: in view).
glm::vec2 onScreen(const render::View& v, const geometry::Vec3& c) {
  const glm::vec4 p =
      v.camera.clipFromView * v.camera.viewFromWorld * glm::vec4(float(c.x()), float(c.y()), float(c.z()), 1.0f);
  return glm::vec2(p) / p.w;
}

// One drawer for the torus-to-floor lecture (building it is most of the
// cost): the cut's cameras, the fade's weights and pictures, the trail.
TEST(SurfaceChangeFrames, EachSurfaceHasItsOwnCameraAFadeWeighsTheOldViewDownAndTheTrailRunsOn) {
  const Lecture l = lecture({"segment[3].fade_seconds=0.5"});
  const SceneDrawer drawer(l.spec, l.model, nullptr);
  const motion::FrameClock clock = motion::clipClock(l.spec, l.model);
  const double cut = l.model.segments[2].start;
  long long firstAfter = -1;
  for (long long f = 0; f < clock.frameCount() && firstAfter < 0; ++f)
    if (clock.place(f).segment == 2) firstAfter = f;
  ASSERT_GT(firstAfter, 0);

  // A cut between the torus's camera and the floor's, each with its ball in view.
  const render::View before = drawer.ballCamera(clock.place(firstAfter - 1), clock.arcLength(firstAfter - 1));
  const render::View after = drawer.ballCamera(clock.place(firstAfter), clock.arcLength(firstAfter));
  EXPECT_EQ(clock.arcLength(firstAfter - 1), cut) << "the last frame on the torus rests at the cut";
  EXPECT_GT(glm::length(before.camera.position - after.camera.position), 1.0f) << "a cut, not a move";
  const double R = l.model.ballRadius;
  const glm::vec2 torusBall = onScreen(before, l.model.path->at(std::nextafter(cut, 0.0)).centre(R));
  const glm::vec2 floorBall = onScreen(after, l.model.path->at(clock.arcLength(firstAfter)).centre(R));
  for (const glm::vec2 p : {torusBall, floorBall}) {
    EXPECT_LT(std::abs(p.x), 1.0f);
    EXPECT_LT(std::abs(p.y), 1.0f);
  }

  // The fade: weight 1 − t / 0.5 s from the segment's first frame, the
  // outgoing picture the torus's last view (views: title band, ball, twin).
  double lastWeight = 2.0;
  int fading = 0;
  for (long long f = 0; f < clock.frameCount(); ++f) {
    const motion::StoryPlace story = clock.place(f);
    motion::FrameOrientations frame;
    frame.current.s = clock.arcLength(f);
    frame.story = story;
    frame.cuts = {{cut, {}}};
    const auto fade = drawer.fadeAt(frame);
    const bool inFade = story.segment == 2 && story.seconds < 0.5;
    ASSERT_EQ(fade.has_value(), inFade) << "frame " << f << " (segment " << story.segment + 1 << ", " << story.seconds
                                        << " s)";
    if (!fade) continue;
    ++fading;
    EXPECT_NEAR(fade->weight, 1.0 - story.seconds / 0.5, 1e-12);
    EXPECT_LT(fade->weight, lastWeight);
    lastWeight = fade->weight;
    ASSERT_EQ(fade->from.views.size(), 3u);
    EXPECT_EQ(fade->from.views[1].camera.position, before.camera.position);
  }
  EXPECT_EQ(fading, int(std::ceil(0.5 * clock.fps().value())));

  // Half way round the floor's circle the Bloch trail still holds the torus's samples.
  const double s = l.model.segments[2].start + 0.5 * (l.model.segments[2].end - l.model.segments[2].start);
  motion::FrameOrientations frame = motion::solveFrame(l.spec, l.model, s);
  frame.story = motion::storyPlaceAt(l.model, s);
  ASSERT_EQ(frame.story.segment, 2u);
  const render::DrawList list = drawer.draw(frame);
  ASSERT_EQ(list.views.size(), 3u);
  std::size_t longest = 0, onTorus = 0;
  for (const render::PolylineItem& p : list.polylines)
    if (p.view == 2) longest = std::max(longest, p.points.size());
  for (const motion::OrientedSample& t : frame.trail) onTorus += t.s < cut ? 1 : 0;
  EXPECT_GT(longest, onTorus + 10);
  // The ball view's lines keep to the floor (the circle of radius 3 and the
  // line after it, within 3√2 of the axis, a marker R further): none
  // reaches the torus's equator (5.5).
  for (const render::PolylineItem& p : list.polylines)
    if (p.view == 1) {
      for (const glm::vec3& q : p.points) EXPECT_LT(std::hypot(q.x, q.y), 5.3f);
    }
}

// transition = "cut" (the default): no frame fades. Two floors, cheap to frame.
TEST(SurfaceChangeFrames, ACutHasNoFade) {
  const scene::SceneSpec spec = scene::loadSceneText(
      "[render]\nwidth = 320\nheight = 180\n[[segment]]\npath = { kind = \"line\", length = 3 }\n[[segment]]\n"
      "path = { kind = \"line\", length = 3 }\nsurface = { kind = \"plane\", normal = [0, 1, 1] }\n",
      "cut.toml");
  const model::RollingModel model = model::buildModel(spec);
  ASSERT_EQ(model.surfaces.size(), 2u);
  const SceneDrawer drawer(spec, model, nullptr);
  const motion::FrameClock clock = motion::clipClock(spec, model);
  for (long long f = 0; f < clock.frameCount(); ++f) {
    motion::FrameOrientations frame;
    frame.story = clock.place(f);
    frame.cuts = {{model.segments[1].start, {}}};
    EXPECT_FALSE(drawer.fadeAt(frame).has_value()) << f;
  }
}

}  // namespace
}  // namespace rollspin::draw
