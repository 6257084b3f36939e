// jobs/scene_print.hpp: `scene --print`'s resolved scene — its header, what the engine derives noted beside the
// keys (automatic steps, samples, each storyboard segment's timing, a plate's radius), and text that loads back.
#include "jobs/scene_print.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <vector>

#include "model/rolling_model.hpp"
#include "motion/frame_clock.hpp"
#include "motion/solve_job.hpp"
#include "scene/scene_loader.hpp"

namespace rollspin::jobs {
namespace {

const char* const kPrintCircle = "[ball]\nradius = 1\n[path]\nkind = \"circle\"\nradius = 3\n";

// A line, a rest and half a circle at 10 frames a second.
const char* const kPrintStory = R"(
[ball]
radius = 1
[animation]
fps = 10
hold = 0
[[segment]]
path = { kind = "line", length = 4 }
duration = 2
[[segment]]
hold = 1
[[segment]]
path = { kind = "circle", radius = 2, turns = 0.5 }
)";

// Once round a sphere, then a line on the floor.
const char* const kPrintTwoSurfaces = R"(
[surface]
kind = "sphere"
[animation]
fps = 10
hold = 0
[[segment]]
path = { kind = "parallel", turns = 1 }
duration = 2
[[segment]]
surface = { kind = "plane" }
path = { kind = "line", length = 3 }
duration = 1
)";

scene::SceneSpec printLoad(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return scene::loadSceneText(text, "print.toml", overrides, {});
}

bool printHas(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ScenePrint, TheHeaderNamesTheSceneAndItsPath) {
  const std::string text = resolvedSceneText("scenes/circle.toml", printLoad(kPrintCircle));
  const std::string length = fmt::format("{}", 2.0 * std::numbers::pi * 3.0);
  EXPECT_EQ(
      text.rfind("# scenes/circle.toml resolved: every default filled in, extends and --set applied.\n# path: ", 0), 0U)
      << text;
  const std::size_t pathLine = text.find("# path: ");
  const std::string second = text.substr(pathLine, text.find('\n', pathLine) - pathLine);
  EXPECT_TRUE(second.ends_with(", length " + length)) << second;
  EXPECT_TRUE(printHas(second, "circle")) << second;
}

TEST(ScenePrint, AutomaticStepsAndSamplesAreNotedWithTheirCounts) {
  const scene::SceneSpec spec = printLoad(kPrintCircle);
  const std::string text = resolvedSceneText("c.toml", spec);
  const model::RollingModel model = model::buildSceneModel(spec);
  const motion::SolverChoice choice = motion::chooseSolver(spec, model);
  ASSERT_TRUE(choice.automaticSteps);
  ASSERT_GT(choice.steps, 0);
  EXPECT_TRUE(printHas(text, "\n# steps = automatic: " + std::to_string(choice.steps) + " steps\n")) << text;
  // The timeline's own count: 60 a turn of the ball (3 as it rolls once round the circle of radius 3) + 1.
  EXPECT_EQ(motion::defaultSampleCount(model), 181);
  EXPECT_TRUE(printHas(text, "\n# samples = 181 (60 per turn + 1)\n")) << text;
}

TEST(ScenePrint, StepsAndSamplesTheSceneSetsCarryNoNote) {
  const std::string text =
      resolvedSceneText("c.toml", printLoad(kPrintCircle, {"solver.steps=500", "timeline.samples=7"}));
  EXPECT_TRUE(printHas(text, "\nsteps = 500\n")) << text;
  EXPECT_TRUE(printHas(text, "\nsamples = 7\n")) << text;
  EXPECT_FALSE(printHas(text, "automatic:")) << text;
  EXPECT_FALSE(printHas(text, "per turn")) << text;
}

// The whole path (10.2832) in animation.duration's 10 s: 1.02832 a second, so the circle (2π) takes 6.11015 s.
TEST(ScenePrint, EachStoryboardSegmentSaysWhereAndForHowLong) {
  const scene::SceneSpec spec = printLoad(kPrintStory);
  const std::string text = resolvedSceneText("story.toml", spec);
  EXPECT_TRUE(printHas(text,
                       "\n# segment 1: s 0 to 4 (length 4) in 2 s, 20 frames\n[[segment]]\n"
                       "duration = 2  # this segment lasts 2 s (s 0 to 4), not the clip\n"))
      << text;
  EXPECT_TRUE(printHas(text, "\n# segment 2: rests at s = 4 for 1 s, 10 frames\n[[segment]]\nhold = 1\n")) << text;
  EXPECT_TRUE(printHas(text,
                       "\n# segment 3: s 4 to 10.2832 (length 6.28319) in 6.11015 s, 61 frames\n[[segment]]\n"
                       "# duration = 6.11015 s: this segment (s 4 to 10.2832) at the storyboard's speed "
                       "(see [animation])\n"))
      << text;
  // hold = 0: the clip opens on one frame of the start, then the segments' 20 + 10 + 61, and ends on their last.
  const motion::FrameClock clock(model::buildSceneModel(spec).segments, spec);
  EXPECT_EQ(clock.frameCount(), 1 + 20 + 10 + 61);
  EXPECT_TRUE(printHas(text, fmt::format("\nduration = 10  # the whole path's time at one speed, not the clip's: "
                                         "segments without their own timing move at 1.02832 per second; the clip "
                                         "lasts {:.6g} s, {} frames (1 opening, 91 in the segments, 0 closing)\n",
                                         double(clock.frameCount()) / 10.0, clock.frameCount())))
      << text;
}

// animation.speed in place of the duration; a segment's own speed is noted beside its speed key.
TEST(ScenePrint, ASpeedIsNotedBesideTheSpeedKey) {
  const scene::SceneSpec spec = printLoad(R"(
[animation]
fps = 10
hold = 0
speed = 2
[[segment]]
path = { kind = "line", length = 4 }
speed = 4
[[segment]]
path = { kind = "circle", radius = 2, turns = 0.5 }
)");
  const std::string text = resolvedSceneText("speed.toml", spec);
  EXPECT_TRUE(printHas(text,
                       "\n# segment 1: s 0 to 4 (length 4) in 1 s, 10 frames\n[[segment]]\n"
                       "speed = 4  # this segment lasts 1 s (s 0 to 4), not the clip\n"))
      << text;
  EXPECT_TRUE(printHas(text, "\n# segment 2: s 4 to 10.2832 (length 6.28319) in 3.14159 s, 31 frames\n")) << text;
  // hold = 0: the clip opens on one frame of the start, then the segments' 10 + 31, and ends on their last.
  const motion::FrameClock clock(model::buildSceneModel(spec).segments, spec);
  EXPECT_EQ(clock.frameCount(), 1 + 10 + 31);
  EXPECT_TRUE(printHas(text, fmt::format("\nspeed = 2  # segments without their own timing move at 2 per second; "
                                         "the clip lasts {:.6g} s, {} frames (1 opening, 41 in the segments, 0 "
                                         "closing)\n",
                                         double(clock.frameCount()) / 10.0, clock.frameCount())))
      << text;
  EXPECT_FALSE(printHas(text, "not the clip's")) << text;
}

// A storyboard over two surfaces names each segment's (a scene of one surface does not: kPrintStory).
TEST(ScenePrint, ASegmentOfAStoryboardOverSeveralSurfacesNamesItsSurface) {
  const std::string text = resolvedSceneText("two.toml", printLoad(kPrintTwoSurfaces));
  EXPECT_TRUE(printHas(text, " in 2 s, 20 frames, on surface 0 (a sphere)\n[[segment]]\n")) << text;
  EXPECT_TRUE(printHas(text, "\n# segment 2: s ")) << text;
  EXPECT_TRUE(printHas(text, " in 1 s, 10 frames, on surface 1 (a plane)\n[[segment]]\n")) << text;
  EXPECT_FALSE(printHas(resolvedSceneText("story.toml", printLoad(kPrintStory)), "on surface")) << "one surface";
}

TEST(ScenePrint, APlatesContactCircleIsNotedAsDerived) {
  const std::string text = resolvedSceneText("plate.toml", printLoad("[ball]\nradius = 1\n[plate]\nradius = 6\n"));
  EXPECT_TRUE(printHas(text, "\n[plate]\nradius = 6  # the contact circle's radius is derived: R1/2 = 3\n")) << text;
  EXPECT_FALSE(printHas(resolvedSceneText("c.toml", printLoad(kPrintCircle)), "derived")) << "no plate, no note";
}

TEST(ScenePrint, ThePrintedSceneLoadsBackToTheSameText) {
  for (const char* scene : {kPrintCircle, kPrintStory, kPrintTwoSurfaces, "[plate]\nradius = 4\n"}) {
    const std::string text = resolvedSceneText("once.toml", printLoad(scene));
    const std::string again = resolvedSceneText("once.toml", printLoad(text));
    EXPECT_EQ(again, text);
  }
}

}  // namespace
}  // namespace rollspin::jobs
