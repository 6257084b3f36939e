// A storyboard across surfaces (issue 53): the model holds one surface per
// segment, the path jumps where the surface changes and the ball's
// orientation carries on. Each surface's stretch, built on its own
// (motion/surface_stretches), is checked against the independent kinematic
// oracle (src/kinematics) with the orientation carried from the previous
// stretch's end; the pose stream's cut poses equal a separate solve; and the
// loader refuses surface keys that make no sense.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "kinematics/rolling_kinematics.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_poses.hpp"
#include "motion/frame_sampling.hpp"
#include "motion/solve_job.hpp"
#include "motion/surface_stretches.hpp"
#include "scene/scene_loader.hpp"
#include "spin/su2.hpp"
#include "support/test_files.hpp"

using namespace rollspin;

namespace {

scene::SceneSpec torusToFloor() {
  return model::loadScene(test::shippedScenePath("torus-to-floor"), {"render.trails=false"});
}

// U at each arc length of `at` (non-decreasing) from one march over the whole path.
std::vector<spin::Su2> solveAt(const scene::SceneSpec& spec, const model::RollingModel& model,
                               const std::vector<double>& at) {
  std::vector<spin::Su2> out(at.size());
  motion::marchScene(spec, model, at, [&](std::size_t i, double, const spin::Su2& q) { out[i] = q; });
  return out;
}

spin::Su2 toSu2(const Eigen::Matrix3d& m) {
  const Eigen::Quaterniond q(m);
  return {q.w(), q.x(), q.y(), q.z()};
}

std::string loadError(const std::string& toml) {
  try {
    (void)scene::loadSceneText(toml, "case.toml");
  } catch (const Error& e) {
    return e.what();
  }
  return "(loaded)";
}

const std::string kTwoSurfaces =
    "[ball]\nradius = 0.8\n[surface]\nkind = \"torus\"\nmajor_radius = 4\nminor_radius = 1.5\n";

}  // namespace

TEST(SurfaceChange, ModelHoldsOneSurfacePerSegmentAndThePathJumps) {
  const scene::SceneSpec spec = torusToFloor();
  ASSERT_EQ(spec.surfaceCount(), 2u);
  const model::RollingModel model = model::buildModel(spec);
  ASSERT_EQ(model.surfaces.size(), 2u);
  ASSERT_EQ(model.segments.size(), 4u);
  const std::vector<std::size_t> expected{0, 0, 1, 1};
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(model.segments[k].surface, expected[k]) << k;
  EXPECT_EQ(model.surface, model.surfaces[0]);
  // The torus's outer equator ends at (A + a, 0, 0); the floor's circle
  // starts where its own keys put it: r e1 = (3, 0, 0), on z = 0.
  const double cut = model.segments[2].start;
  EXPECT_NEAR((model.path->point(std::nextafter(cut, 0.0)) - geometry::Vec3(5.5, 0, 0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((model.path->point(cut) - geometry::Vec3(3, 0, 0)).norm(), 0.0, 1e-9);
  // The line after the circle continues along the circle's end heading (a join on one surface).
  const double lineStart = model.segments[3].start;
  EXPECT_NEAR((model.path->point(lineStart) - model.path->point(std::nextafter(lineStart, 0.0))).norm(), 0.0, 1e-9);
  EXPECT_EQ(motion::cutArcLengths(model), std::vector<double>{cut});
  // A scene of one surface: one entry, no cut.
  const scene::SceneSpec one = model::loadScene(test::shippedScenePath("storyboard"), {});
  const model::RollingModel oneModel = model::buildModel(one);
  EXPECT_EQ(oneModel.surfaces.size(), 1u);
  EXPECT_TRUE(motion::cutArcLengths(oneModel).empty());
}

TEST(SurfaceChange, OrientationAndSignCarryAcrossTheCut) {
  const scene::SceneSpec spec = torusToFloor();
  const model::RollingModel model = model::buildModel(spec);
  const double cut = model.segments[2].start, h = 1e-6;
  const std::vector<spin::Su2> q = solveAt(spec, model, {cut - h, cut, cut + h});
  // |ω| ≤ (1/R)(1 + R|κ_n|) + |τ_g| on either side; q moves by at most |ω| h / 2.
  const double bound = 4.0 * h / model.ballRadius;
  for (int i = 0; i < 2; ++i) {
    const spin::Su2 &a = q[i], &b = q[i + 1];
    const double dot = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
    EXPECT_GT(dot, 0.999) << "the spinor keeps its sign across the cut";
    EXPECT_LT(std::sqrt((a.w - b.w) * (a.w - b.w) + (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) +
                        (a.z - b.z) * (a.z - b.z)),
              bound);
  }
}

TEST(SurfaceChange, EachStretchAgreesWithTheKinematicsWithTheOrientationCarried) {
  const scene::SceneSpec spec = torusToFloor();
  const model::RollingModel model = model::buildModel(spec);
  const std::vector<motion::SurfaceStretch> stretches = motion::surfaceStretches(spec, model);
  ASSERT_EQ(stretches.size(), 2u);
  EXPECT_EQ(stretches[0].firstSegment, 0u);
  EXPECT_EQ(stretches[1].firstSegment, 2u);
  std::vector<double> ends;
  for (const auto& s : stretches) ends.push_back(s.end);
  const std::vector<spin::Su2> solved = solveAt(spec, model, ends);
  kinematics::KinematicSettings settings;
  settings.steps = 20000;
  settings.minStepsPerRadian = 256.0;
  Eigen::Matrix3d carried = Eigen::Matrix3d::Identity();  // Q at the stretch's start
  for (std::size_t k = 0; k < stretches.size(); ++k) {
    const motion::SurfaceStretch& stretch = stretches[k];
    EXPECT_EQ(stretch.model.surfaces.size(), 1u);
    EXPECT_NEAR(stretch.model.path->length(), stretch.end - stretch.start, 1e-12);
    // The stretch, built from its own scene, lies where the whole path does.
    // (Short of its end: the whole path's join belongs to the next piece.)
    for (double f : {0.0, 0.3, 0.7, 0.999}) {
      const double local = f * (stretch.end - stretch.start);
      EXPECT_NEAR((stretch.model.path->point(local) - model.path->point(stretch.start + local)).norm(), 0.0, 1e-9)
          << "stretch " << k << " at " << f;
    }
    const Eigen::Matrix3d piece =
        kinematics::RollingKinematics(*stretch.model.path, stretch.model.ballRadius, settings).finalOrientation();
    carried = piece * carried;
    EXPECT_LT(spin::rotationDistance(solved[k], toSu2(carried)), 1e-7) << "stretch " << k;
  }
}

TEST(SurfaceChange, StreamedFramesCarryTheCutPoseOfASeparateSolve) {
  const scene::SceneSpec spec = torusToFloor();
  const model::RollingModel model = model::buildModel(spec);
  const motion::FrameClock clock = motion::clipClock(spec, model);
  const double cut = model.segments[2].start;
  const spin::Su2 atCut = solveAt(spec, model, {cut})[0];
  const long long last = clock.frameCount() - 1;
  motion::FramePoseStream stream(spec, model, clock, {last - 2, last});
  const auto frame = stream.next();
  ASSERT_TRUE(frame.has_value());
  ASSERT_EQ(frame->cuts.size(), 1u);
  EXPECT_EQ(frame->cuts[0].s, cut);
  EXPECT_LT(spin::rotationDistance(frame->cuts[0].q, atCut), 1e-12);
  const motion::FrameOrientations still = motion::solveFrame(spec, model, 0.5 * cut);
  ASSERT_EQ(still.cuts.size(), 1u);
  EXPECT_LT(spin::rotationDistance(still.cuts[0].q, atCut), 1e-12);
}

TEST(SurfaceChange, LoaderRefusesSurfaceKeysThatMakeNoSense) {
  const std::string floor = "surface = { kind = \"plane\" }\n";
  const std::string torusLap = "[[segment]]\npath = { kind = \"parallel\" }\n";
  // A hold rests on the previous motion's surface.
  EXPECT_NE(loadError(kTwoSurfaces + torusLap + "[[segment]]\nhold = 1\n" + floor)
                .find("segment[2].surface: a hold rests where the previous motion ended"),
            std::string::npos);
  // transition and fade_seconds belong where the surface changes.
  EXPECT_NE(loadError(kTwoSurfaces + torusLap + "[[segment]]\npath = { kind = \"parallel\" }\ntransition = \"fade\"\n")
                .find("segment[2].transition: applies where the surface changes"),
            std::string::npos);
  EXPECT_NE(loadError(kTwoSurfaces + "[[segment]]\npath = { kind = \"parallel\" }\n" + floor + "transition = \"cut\"\n")
                .find("segment[1].transition: applies where the surface changes; the first segment"),
            std::string::npos);
  EXPECT_NE(
      loadError(kTwoSurfaces + torusLap + "[[segment]]\npath = { kind = \"line\" }\n" + floor + "fade_seconds = 1\n")
          .find("segment[2].fade_seconds: applies to transition = \"fade\""),
      std::string::npos);
  // A segment's path is checked against its own surface, its surface keys against its kind.
  EXPECT_NE(loadError(kTwoSurfaces + torusLap + "[[segment]]\npath = { kind = \"parallel\" }\n" + floor)
                .find("but segment[2].surface.kind is \"plane\""),
            std::string::npos);
  EXPECT_NE(loadError(kTwoSurfaces + torusLap +
                      "[[segment]]\npath = { kind = \"parallel\" }\nsurface = { kind = \"torus\", major_radius = 1, "
                      "minor_radius = 2 }\n")
                .find("segment[2].surface.minor_radius"),
            std::string::npos);
  EXPECT_NE(loadError(kTwoSurfaces + torusLap +
                      "[[segment]]\npath = { kind = \"line\" }\nsurface = { kind = "
                      "\"plane\", radius = 2 }\n")
                .find("segment[2].surface.radius"),
            std::string::npos);
  // After the change, a line on the floor starts at its own keys: direction_vector is allowed there.
  EXPECT_EQ(loadError(kTwoSurfaces + torusLap +
                      "[[segment]]\npath = { kind = \"line\", direction_vector = [0, 1, 0] }\n" + floor),
            "(loaded)");
}
