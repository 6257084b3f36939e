// The default camera keeps the ball: for every scene in scenes/ at 16:9 and
// 9:16, at seven places along the clip (a storyboard: its frames every
// quarter second, camera moves and holds included, and storyboards on every
// curved surface written here), ≥ 90 % of each ball's disc is seen
// past the surface and inside the frame. Measured from pictures, not from
// the camera's own sight-line model: the frame's surface meshes are drawn
// with the ball and without it (nothing else: no lines, text, shadow), and
// the pixels whose centres lie in the ball's projected disc and that differ
// between the two are the ball seen (label gl). And the frame does not cut
// the ball: its outline keeps inside its view, at every frame of every
// storyboard.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "draw/draw_style.hpp"
#include "draw/scene_drawer.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_sampling.hpp"
#include "motion/scene_facts.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "support/cli_runner.hpp"
#include "support/sweep.hpp"

namespace rollspin::draw {
namespace {
using namespace rollspin::model;
using namespace rollspin::motion;

struct Disc {
  glm::vec2 centre;  // view pixels, y down
  float radius;
};

// The ball's outline on screen: the cone from the eye tangent to the ball
// (its centre's projection is close enough to the ellipse's for a test at
// this field of view; the radius is the cone's, measured on the image plane).
Disc projectedDisc(const render::View &v, const render::MeshItem &ball) {
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  const glm::vec4 c = clipFromWorld * glm::vec4(glm::vec3(ball.worldFromModel[3]), 1.0f);
  const float R = glm::length(glm::vec3(ball.worldFromModel[0]));
  const float radius = R * 0.5f * float(v.height) * v.camera.clipFromView[1][1] / std::sqrt(c.w * c.w - R * R);
  return {{(c.x / c.w * 0.5f + 0.5f) * float(v.width), (0.5f - c.y / c.w * 0.5f) * float(v.height)}, radius};
}

// The ball's outline's extent in the view's pixels (x0, y0, x1, y1; y
// down), exact for a perspective view without skew (the tangents from the
// eye to the sphere, as render::sphereBounds takes them, unrounded).
glm::vec4 outlineExtent(const render::View &v, const glm::vec3 &centre, float radius) {
  const glm::mat4 &P = v.camera.clipFromView;
  const glm::vec3 c(v.camera.viewFromWorld * glm::vec4(centre, 1.0f));
  const double r = radius, d = -c.z;
  double ndc[2][2];
  for (int axis = 0; axis < 2; ++axis) {
    const double t = std::sqrt(std::max(0.0, double(c[axis]) * c[axis] + d * d - r * r));
    const double lo = (c[axis] * d - r * t) / (d * d - r * r), hi = (c[axis] * d + r * t) / (d * d - r * r);
    ndc[axis][0] = P[axis][axis] * lo - P[2][axis];
    ndc[axis][1] = P[axis][axis] * hi - P[2][axis];
  }
  return {float((ndc[0][0] * 0.5 + 0.5) * v.width), float((0.5 - ndc[1][1] * 0.5) * v.height),
          float((ndc[0][1] * 0.5 + 0.5) * v.width), float((0.5 - ndc[1][0] * 0.5) * v.height)};
}

// Whether the ball's outline keeps at least a pixel inside the view (the
// frame, or a view's edge inside it, does not cut or touch it).
bool insideTheView(const render::View &v, const render::MeshItem &ball) {
  const glm::vec4 e =
      outlineExtent(v, glm::vec3(ball.worldFromModel[3]), glm::length(glm::vec3(ball.worldFromModel[0])));
  return e.x >= 1.0f && e.y >= 1.0f && e.z <= float(v.width) - 1.0f && e.w <= float(v.height) - 1.0f;
}

class BallInSight : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = render::createContext().release();  // ROLLSPIN_GL chooses the backend
    renderer_ = new render::Renderer(*context_, render::ShaderLibrary{});
  }
  static void TearDownTestSuite() {
    delete renderer_;
    delete context_;
  }
  static render::GlContext *context_;
  static render::Renderer *renderer_;

  // Measures every scene in `scenes` at 16:9 and 9:16; counts the balls
  // checked and those seen under 90 %.
  static void measure(const std::vector<std::filesystem::path> &scenes, int &checked, int &hiddenSomewhere) {
    for (const auto &file : scenes) {
      for (const auto &[width, height] : {std::pair{480, 270}, std::pair{270, 480}}) {
        const scene::SceneSpec spec = loadScene(
            file.string(), {"render.width=" + std::to_string(width), "render.height=" + std::to_string(height)});
        if (spec.render.layout == scene::RenderLayout::Twin) continue;  // no ball to see
        const RollingModel model = buildSceneModel(spec);
        const SceneDrawer drawer(spec, model, nullptr, makeSceneFacts(spec, model));
        const double L = model.path->length();
        // A single path: seven places along it. A storyboard: its clip's
        // frames every quarter second (holds and camera moves included).
        struct Place {
          double s;
          StoryPlace story;
        };
        std::vector<Place> places;
        if (spec.isStoryboard()) {
          const FrameClock clock = clipClock(spec, model);
          const long long step = std::max<long long>(1, std::llround(clock.fps().value() / 4.0));
          for (long long f = 0; f < clock.frameCount(); f += step)
            places.push_back({clock.arcLength(f), clock.place(f)});
          // (Under ROLLSPIN_TEST_SWEEP=sample, every storyboard at a
          // quarter of those frames: each segment kind is still drawn.)
          places = test::sweep(places);
        } else {
          for (int k = 0; k <= 6; ++k) places.push_back({L * k / 6.0, storyPlaceAt(model, L * k / 6.0)});
        }
        for (const auto &[s, story] : places) {
          FrameOrientations frame = solveFrame(spec, model, s);
          frame.story = story;
          const render::DrawList list = drawer.draw(frame);
          // The surface alone, and each ball with it.
          render::DrawList surfaceOnly = list;
          surfaceOnly.polylines.clear();
          surfaceOnly.labels.clear();
          surfaceOnly.arrows.clear();
          surfaceOnly.meshes.clear();
          for (render::View &v : surfaceOnly.views) v.light.shadow = false;
          std::vector<const render::MeshItem *> balls;
          for (const render::MeshItem &m : list.meshes) {
            // The surface: a chart's or a board's checker, or the world
            // cubes of a steep chart.
            if (m.material.pattern == render::Pattern::Checker || m.material.pattern == render::Pattern::SolidChecker)
              surfaceOnly.meshes.push_back(m);
            if (m.material.pattern == render::Pattern::Texture) balls.push_back(&m);
          }
          ASSERT_FALSE(balls.empty()) << file.stem();
          const media::Image without = renderer_->render(surfaceOnly);
          for (const render::MeshItem *ball : balls) {
            render::DrawList withBall = surfaceOnly;
            withBall.meshes.push_back(*ball);
            const media::Image with = renderer_->render(withBall);
            const render::View &v = list.views[std::size_t(ball->view)];
            const Disc disc = projectedDisc(v, *ball);
            int area = 0, seen = 0;
            const int r = int(std::ceil(disc.radius)) + 1;
            for (int y = int(disc.centre.y) - r; y <= int(disc.centre.y) + r; ++y)
              for (int x = int(disc.centre.x) - r; x <= int(disc.centre.x) + r; ++x) {
                if (glm::length(glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - disc.centre) > disc.radius) continue;
                ++area;
                if (x < 0 || y < 0 || x >= v.width || y >= v.height) continue;  // outside the frame: not seen
                const int px = v.x + x, py = v.y + y;
                int difference = 0;
                for (int c = 0; c < 3; ++c)
                  difference += std::abs(int(with.pixel(px, py)[c]) - int(without.pixel(px, py)[c]));
                if (difference > 6) ++seen;
              }
            ASSERT_GT(area, 20) << file.stem() << ": the ball is too small to measure";
            EXPECT_TRUE(insideTheView(v, *ball))
                << file.stem() << " " << width << "x" << height << " at s = " << s << ": the view's edge cuts the ball";
            const double share = double(seen) / area;
            EXPECT_GE(share, 0.9) << file.stem() << " " << width << "x" << height << " at s = " << s << " of " << L
                                  << " (segment " << story.segment + 1 << ", " << story.seconds << " s in)"
                                  << ": " << seen << " of " << area << " pixels of the ball's disc seen";
            if (share < 0.9) ++hiddenSomewhere;
            ++checked;
          }
        }
      }
    }
  }
};
render::GlContext *BallInSight::context_ = nullptr;
render::Renderer *BallInSight::renderer_ = nullptr;

TEST_F(BallInSight, EveryScenesDefaultCameraSeesNineTenthsOfTheBallAtEverySampledFrame) {
  ASSERT_GE(test::bundledSceneFiles().size(), 20u);
  int checked = 0, hiddenSomewhere = 0;
  measure(test::sweep(test::bundledSceneFiles()), checked, hiddenSomewhere);
  EXPECT_GE(checked, test::sweepSampled() ? 2 * 7 : 14 * 2 * 7);
  EXPECT_EQ(hiddenSomewhere, 0);
}

// Issue 42: a storyboard on a torus (round the outer equator, a rest, then
// over the tube into the hole), whose camera turns with the ball along the
// meridian, keeps the ball at every quarter second.
TEST_F(BallInSight, TorusStoryKeepsTheBall) {
  int checked = 0, hiddenSomewhere = 0;
  measure({test::sourceDir() / "scenes/torus-story.toml"}, checked, hiddenSomewhere);
  // Over 11 s of clip at 16:9 and 9:16, four places a second (one under
  // ROLLSPIN_TEST_SWEEP=sample).
  EXPECT_GE(checked, 2 * (test::sweepSampled() ? 1 : 4) * 11);
  EXPECT_EQ(hiddenSomewhere, 0);
}

// Storyboards written for the test (tests/draw/storyboards/), beyond those
// in scenes/: other segment kinds on each curved surface, a partial camera
// key (elevation only), a view from below, segments without holds between
// them, and once round a torus's tube, where no camera sees the ball past
// the surface and the surface is cut away towards the eye.
TEST_F(BallInSight, StoryboardsWrittenForTheTestKeepTheBallInEveryQuarterSecond) {
  std::vector<std::filesystem::path> scenes;
  for (const auto &e : std::filesystem::directory_iterator(test::sourceDir() / "tests/draw/storyboards"))
    if (e.path().extension() == ".toml") scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());
  ASSERT_EQ(scenes.size(), 5u);
  scenes = test::sweep(scenes);
  int checked = 0, hiddenSomewhere = 0;
  measure(scenes, checked, hiddenSomewhere);
  EXPECT_GE(checked, int(scenes.size()) * 2 * (test::sweepSampled() ? 5 : 20));
  EXPECT_EQ(hiddenSomewhere, 0);
}

// Issue 42: the frame does not cut the ball (sphere-story at 1080p was seen
// with the ball on the bottom edge): at every frame of every storyboard in
// scenes/ and tests/draw/storyboards/, at 1920x1080, 640x360 and 270x480,
// the ball's outline keeps a margin of 2 % of the view's height (at least
// a pixel) inside its view, with the camera the drawer sets for that frame.
// Geometry only: no picture is rendered.
TEST(BallInFrame, EveryFrameOfEveryStoryboardHoldsTheWholeBall) {
  std::vector<std::filesystem::path> scenes;
  for (const auto &file : test::bundledSceneFiles())
    if (loadScene(file.string(), {}).isStoryboard()) scenes.push_back(file);
  for (const auto &e : std::filesystem::directory_iterator(test::sourceDir() / "tests/draw/storyboards"))
    if (e.path().extension() == ".toml") scenes.push_back(e.path());
  ASSERT_GE(scenes.size(), 8u);
  long long frames = 0;
  for (const auto &file : test::sweep(scenes))
    for (const auto &[width, height] : {std::pair{1920, 1080}, std::pair{640, 360}, std::pair{270, 480}}) {
      const scene::SceneSpec spec = loadScene(
          file.string(), {"render.width=" + std::to_string(width), "render.height=" + std::to_string(height)});
      if (spec.render.layout == scene::RenderLayout::Twin) continue;
      const RollingModel model = buildSceneModel(spec);
      const SceneDrawer drawer(spec, model, nullptr, makeSceneFacts(spec, model));
      const FrameClock clock = clipClock(spec, model);
      int cut = 0;
      float least = 1e9f;
      for (long long f = 0; f < clock.frameCount(); ++f) {
        const double s = clock.arcLength(f);
        const render::View v = drawer.ballCamera(clock.place(f), s);
        const glm::vec4 e =
            outlineExtent(v, toGlm(model.path->at(s).centre(model.ballRadius)), float(model.ballRadius));
        const float margin = std::min({e.x, e.y, float(v.width) - e.z, float(v.height) - e.w});
        least = std::min(least, margin);
        if (margin < std::max(1.0f, 0.02f * float(v.height)) && cut++ < 3)
          ADD_FAILURE() << file.stem() << " " << width << "x" << height << " frame " << f << ": the ball's outline ("
                        << e.x << ", " << e.y << ")-(" << e.z << ", " << e.w << ") comes within " << margin
                        << " px of the edge of its view of " << v.width << "x" << v.height;
        ++frames;
      }
      std::printf("%s %dx%d: least margin %.1f px\n", file.stem().c_str(), width, height, least);
      EXPECT_EQ(cut, 0) << file.stem() << " " << width << "x" << height << ": frames whose ball the view cuts";
    }
  EXPECT_GT(frames, 1000);
}

}  // namespace
}  // namespace rollspin::draw
