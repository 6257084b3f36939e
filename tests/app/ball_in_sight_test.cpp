// The default camera keeps the ball: for every scene in scenes/ at 16:9 and
// 9:16, at seven places along the clip (a storyboard: its frames every
// quarter second, camera moves and holds included, and storyboards on every
// curved surface written here), ≥ 90 % of each ball's disc is seen
// past the surface and inside the frame. Measured from pictures, not from
// the camera's own sight-line model: the frame's surface meshes are drawn
// with the ball and without it (nothing else: no lines, text, shadow), and
// the pixels whose centres lie in the ball's projected disc and that differ
// between the two are the ball seen (label gl).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "draw/scene_drawer.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_sampling.hpp"
#include "motion/scene_facts.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "support/cli_runner.hpp"

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
            if (m.material.pattern == render::Pattern::Checker) surfaceOnly.meshes.push_back(m);
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
  std::vector<std::filesystem::path> scenes;
  for (const auto &e : std::filesystem::directory_iterator(test::sourceDir() / "scenes"))
    if (e.path().extension() == ".toml") scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());
  ASSERT_GE(scenes.size(), 20u);
  int checked = 0, hiddenSomewhere = 0;
  measure(scenes, checked, hiddenSomewhere);
  EXPECT_GE(checked, 14 * 2 * 7);
  EXPECT_EQ(hiddenSomewhere, 0);
}

// Issue 42, still open: once round a torus's tube, the turning camera loses
// the ball under the inner side for about half a second (1 of 259 ball
// pixels seen at 480x270, s = 40.57). The scene waits in tests/draw/pending/
// until the camera keeps it; run with --gtest_also_run_disabled_tests.
TEST_F(BallInSight, DISABLED_TorusStoryKeepsTheBall) {
  int checked = 0, hiddenSomewhere = 0;
  measure({test::sourceDir() / "tests/draw/pending/torus-story.toml"}, checked, hiddenSomewhere);
  EXPECT_GT(checked, 0);
  EXPECT_EQ(hiddenSomewhere, 0);
}

// Storyboards written for the test, beyond those in scenes/: other segment
// kinds on each curved surface, a partial camera key (elevation only), a
// view from below, segments without holds between them.
TEST_F(BallInSight, StoryboardsWrittenForTheTestKeepTheBallInEveryQuarterSecond) {
  const std::filesystem::path dir = test::freshTempDir("ball_in_sight_storyboards");
  const std::vector<std::pair<std::string, std::string>> boards{
      {"cylinder-meridian-helix",
       "[ball]\nradius = 0.8\n[surface]\nkind = \"cylinder\"\nradius = 2.5\n"
       "[[segment]]\npath = { kind = \"helix\", pitch_angle_deg = 20, height = "
       "0, turns = 1 }\nduration = 4\n"
       "[[segment]]\npath = { kind = \"geodesic\", length = 6 }\nduration = "
       "3\ncamera = { elevation_deg = 20 }\n"},
      {"sphere-loxodrome-geodesic",
       "[ball]\nradius = 0.8\n[surface]\nkind = \"sphere\"\nradius = 3.0\n"
       "[[segment]]\npath = { kind = \"loxodrome\", heading_deg = 70, "
       "colatitude_start_deg = 40, "
       "colatitude_end_deg = 120 }\nduration = 4\n"
       "[[segment]]\nhold = 1\n"
       "[[segment]]\npath = { kind = \"geodesic\", length = 8 }\nduration = "
       "4\n"},
      {"torus-inner-parallel-geodesic",
       "[ball]\nradius = 0.6\n[surface]\nkind = \"torus\"\nmajor_radius = "
       "4.0\nminor_radius = 1.5\n"
       "[solver]\nmethod = \"frame4\"\n"
       "[[segment]]\npath = { kind = \"parallel\", tube_angle_deg = 120, turns "
       "= 0.75 }\nduration = 4\n"
       "[[segment]]\npath = { kind = \"geodesic\", length = 6 }\nduration = "
       "3\n"},
      {"height-uv-points",
       "[ball]\nradius = 0.5\n[surface]\nkind = \"height\"\nz = "
       "\"0.4*sin(x)*sin(y)\"\n"
       "[solver]\nmethod = \"frame4\"\n"
       "[[segment]]\npath = { kind = \"uv\", u = \"t\", v = \"0.5*t\", t_start "
       "= -2, t_end = 2 }\nduration = 3\n"
       "[[segment]]\npath = { kind = \"geodesic\", length = 3 }\nduration = "
       "3\n"},
  };
  std::vector<std::filesystem::path> scenes;
  for (const auto &[name, text] : boards) {
    scenes.push_back(dir / (name + ".toml"));
    std::ofstream(scenes.back()) << text;
  }
  int checked = 0, hiddenSomewhere = 0;
  measure(scenes, checked, hiddenSomewhere);
  EXPECT_GE(checked, 4 * 2 * 20);
  EXPECT_EQ(hiddenSomewhere, 0);
}

}  // namespace
}  // namespace rollspin::draw
