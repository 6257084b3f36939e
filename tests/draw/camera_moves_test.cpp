// Storyboard cameras move smoothly (but where a storyboard changes surface:
// a cut is its choice): along every storyboard in scenes/ and in
// tests/draw/storyboards/, frame by frame, the ball view's camera as the
// drawer sets it (SceneDrawer::ballCamera, the camera draw() uses) turns its
// view direction by at most CameraFraming::kMaxTurnRateDeg a second (the
// peak of a 40° move eased over one second) and its eye never jumps (no
// cut). And a storyboard whose own camera keys hide the ball is warned
// about, naming its segment; one that leaves the camera free is not. No GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "draw/scene_drawer.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_clock.hpp"
#include "motion/frame_sampling.hpp"
#include "motion/scene_facts.hpp"
#include "support/cli_runner.hpp"
#include "support/sweep.hpp"

namespace rollspin::draw {
namespace {
using namespace rollspin::model;
using namespace rollspin::motion;

std::vector<std::filesystem::path> tomlFiles(const std::filesystem::path &dir) {
  std::vector<std::filesystem::path> files;
  for (const auto &e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The unit vector from the camera's target towards its eye (the view's +z).
glm::vec3 towardEye(const render::View &v) {
  const glm::mat4 &m = v.camera.viewFromWorld;
  return glm::normalize(glm::vec3(m[0][2], m[1][2], m[2][2]));
}

TEST(CameraMoves, EveryStoryboardsCameraTurnsNoFasterThanTheStoryboardMovesAndNeverCuts) {
  std::vector<std::filesystem::path> boards = tomlFiles(test::sourceDir() / "tests/draw/storyboards");
  for (const auto &file : tomlFiles(test::sourceDir() / "scenes")) boards.push_back(file);
  // The storyboards among them (the sweep samples those, not the files).
  std::erase_if(boards, [](const std::filesystem::path &file) {
    const scene::SceneSpec spec = loadScene(file.string(), {"render.width=480", "render.height=270"});
    return !spec.isStoryboard() || spec.render.layout == scene::RenderLayout::Twin;
  });
  int storyboards = 0;
  long long frames = 0;
  for (const auto &file : test::sweep(boards)) {
    const scene::SceneSpec spec = loadScene(file.string(), {"render.width=480", "render.height=270"});
    ++storyboards;
    const RollingModel model = buildSceneModel(spec);
    const SceneDrawer drawer(spec, model, nullptr, makeSceneFacts(spec, model));
    const FrameClock clock = clipClock(spec, model);
    const double fps = clock.fps().value();
    double worstRate = 0.0, worstJump = 0.0;
    long long worstFrame = 0;
    render::View previous = drawer.ballCamera(clock.place(0), clock.arcLength(0));
    for (long long f = 1; f < clock.frameCount(); ++f, ++frames) {
      const render::View v = drawer.ballCamera(clock.place(f), clock.arcLength(f));
      // Where the surface changes (segment.surface) the scene asks for a cut.
      if (model.segments[clock.place(f).segment].surface != model.segments[clock.place(f - 1).segment].surface) {
        previous = v;
        continue;
      }
      const double turnDeg =
          std::acos(std::clamp(double(glm::dot(towardEye(previous), towardEye(v))), -1.0, 1.0)) * 180.0 / M_PI;
      // No cut: the eye moves by a small part of its distance to the ball
      // in a frame (a turn at kMaxTurnRateDeg moves it by 3.5 % at 30 fps).
      const geometry::Vec3 c = model.path->at(clock.arcLength(f)).centre(model.ballRadius);
      const glm::vec3 ball(float(c.x()), float(c.y()), float(c.z()));
      const double jump =
          glm::length(v.camera.position - previous.camera.position) / glm::length(previous.camera.position - ball);
      if (turnDeg * fps > worstRate) {
        worstRate = turnDeg * fps;
        worstFrame = f;
      }
      worstJump = std::max(worstJump, jump);
      previous = v;
    }
    const StoryPlace at = clock.place(worstFrame);
    EXPECT_LE(worstRate, CameraFraming::kMaxTurnRateDeg * 1.001)
        << file.stem() << ": the camera turns " << worstRate << "°/s at frame " << worstFrame << " (segment "
        << at.segment + 1 << ", " << at.seconds << " s in)";
    EXPECT_LE(worstJump, 0.1) << file.stem() << ": the eye jumps by " << worstJump << " of its distance in a frame";
  }
  EXPECT_GE(storyboards, test::sweepSampled() ? 3 : 12);
  EXPECT_GT(frames, test::sweepSampled() ? 500 : 3000);
}

// Once round a torus's tube no camera that turns at most kMaxTurnRateDeg a
// second keeps the ball in sight past the surface: where the scene leaves
// the camera free, the surface is cut away towards the eye instead
// (BallInSight measures the ball seen), so nothing is warned about; where
// the scene's own keys fix the view, the warning names the segment and says
// that the keys fix it.
TEST(CameraMoves, ATorusTubeOnceRoundIsCutAwayWhenFreeAndWarnedAboutWhenKeyed) {
  const auto file = test::sourceDir() / "tests/draw/storyboards/torus-once-round-the-tube.toml";
  {
    const scene::SceneSpec spec = loadScene(file.string(), {"render.width=480", "render.height=270"});
    const RollingModel model = buildSceneModel(spec);
    const SceneDrawer drawer(spec, model, nullptr, makeSceneFacts(spec, model));
    const std::vector<std::string> warnings = drawer.cameraWarnings();
    EXPECT_TRUE(warnings.empty()) << warnings.front();
  }
  const scene::SceneSpec spec = loadScene(
      file.string(), {"render.width=480", "render.height=270", "render.azimuth_deg=0", "render.elevation_deg=20"});
  const RollingModel model = buildSceneModel(spec);
  const SceneDrawer drawer(spec, model, nullptr, makeSceneFacts(spec, model));
  const std::vector<std::string> warnings = drawer.cameraWarnings();
  ASSERT_FALSE(warnings.empty());
  EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(),
                          [](const std::string &w) { return w.find("segment[2]") != std::string::npos; }));
  for (const std::string &w : warnings)
    EXPECT_NE(w.find("the scene's own camera keys fix this view"), std::string::npos) << w;
}

}  // namespace
}  // namespace rollspin::draw
