// path.start_azimuth_deg on every surface that has parallels: the parallel
// starts at that azimuth (φ0, about the surface's axis), it is the default
// parallel turned by φ0 about the axis, and the ball's rotation after it is
// the independent kinematic oracle's (src/kinematics, which sees only the
// contact point and normal), within 1e-8.
#include <gtest/gtest.h>

#include <cmath>

#include "kinematics/rolling_kinematics.hpp"
#include "model/rolling_model.hpp"
#include "motion/solve_job.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_writer.hpp"
#include "spin/propagator.hpp"
#include "support/numbers.hpp"

using namespace rollspin;
using rollspin::test::kPi;

namespace {

struct Case {
  const char* name;
  const char* scene;  // without the path's start_azimuth_deg
};

const Case kCases[] = {
    {"sphere outside (closed form)", "[surface]\nkind = \"sphere\"\nradius = 3\n[path]\nkind = \"parallel\"\n"},
    {"sphere inside, cw",
     "[ball]\nradius = 0.8\n[surface]\nkind = \"sphere\"\nradius = 3\nside = \"inside\"\n"
     "[path]\nkind = \"parallel\"\ndirection = \"cw\"\ncolatitude_deg = 70\n"},
    {"cylinder", "[surface]\nkind = \"cylinder\"\nradius = 2\n[path]\nkind = \"parallel\"\nheight = 0.5\n"},
    {"torus", "[ball]\nradius = 0.5\n[surface]\nkind = \"torus\"\n[path]\nkind = \"parallel\"\ntube_angle_deg = 40\n"},
    {"paraboloid", "[ball]\nradius = 0.5\n[surface]\nkind = \"paraboloid\"\n[path]\nkind = \"parallel\"\n"},
};

model::RollingModel build(const std::string& text, double startAzimuthDeg) {
  std::vector<std::string> overrides;
  if (startAzimuthDeg != 0.0) overrides.push_back("path.start_azimuth_deg=" + std::to_string(startAzimuthDeg));
  return model::buildSceneModel(scene::loadSceneText(text, "<start-azimuth>", overrides));
}

spin::Su2 solve(const model::RollingModel& m) {
  // magnus6 at a fixed, generous step count: the generic parallels are
  // solved numerically, the sphere's closed form exactly.
  const spin::SolveStats st = spin::Propagator(*m.path, m.ballRadius, spin::Method::Magnus6, 20000).solveFinal();
  EXPECT_EQ(st.status, spin::SolveStatus::Ok);
  return st.final;
}

Eigen::Matrix3d aboutZ(double angle) { return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

}  // namespace

TEST(StartAzimuth, AParallelStartsThereAndRollsAsTheKinematicOracleSays) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.name);
    const model::RollingModel turned = build(c.scene, 90.0);
    const model::RollingModel plain = build(c.scene, 0.0);
    const auto& path = *turned.path;
    const Eigen::Vector3d p0 = path.point(0.0);
    EXPECT_NEAR(std::atan2(p0.y(), p0.x()), kPi / 2, 1e-12);
    EXPECT_NEAR(std::atan2(plain.path->point(0.0).y(), plain.path->point(0.0).x()), 0.0, 1e-12);
    EXPECT_NEAR(path.length(), plain.path->length(), 1e-12 * path.length());
    // The same parallel turned by 90° about the axis (+z), all along.
    for (double f : {0.0, 0.3, 0.77, 1.0}) {
      const double s = f * path.length();
      EXPECT_LT((path.point(s) - aboutZ(kPi / 2) * plain.path->point(s)).norm(), 1e-9) << "s = " << s;
    }
    // The ball's rotation: the solver against the oracle on the turned path,
    // and the turned path's rotation is the plain one conjugated by the turn.
    const Eigen::Matrix3d solver = solve(turned).rotationMatrix();
    const std::vector<double> end{path.length()};
    const Eigen::Matrix3d oracle =
        kinematics::RollingKinematics(path, turned.ballRadius, {40000, 0.0}).orientations(end).back();
    EXPECT_LT((solver - oracle).norm(), 1e-8);
    const Eigen::Matrix3d conjugated = aboutZ(kPi / 2) * solve(plain).rotationMatrix() * aboutZ(-kPi / 2);
    EXPECT_LT((solver - conjugated).norm(), 1e-9);
  }
}

TEST(StartAzimuth, TheDefaultIsZeroAndScenePrintWritesIt) {
  const scene::SceneSpec spec = scene::loadSceneText(kCases[2].scene, "<start-azimuth>");
  EXPECT_EQ(spec.path.startAzimuthDeg, 0.0);
  const std::vector<std::string> overrides{"path.start_azimuth_deg=-45"};
  const scene::SceneSpec set = scene::loadSceneText(kCases[3].scene, "<start-azimuth>", overrides);
  EXPECT_EQ(set.path.startAzimuthDeg, -45.0);
  const std::string printed = scene::writeScene(set);
  EXPECT_NE(printed.find("start_azimuth_deg = -45"), std::string::npos) << printed;
  EXPECT_EQ(scene::loadSceneText(printed, "<printed>").path.startAzimuthDeg, -45.0);
}
