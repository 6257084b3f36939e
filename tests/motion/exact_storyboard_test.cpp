// `exact` on storyboards whose segments all have constant κ_n, κ_g, τ_g —
// sphere parallels, great-circle geodesics and meridians, cylinder parallels
// and helices, torus parallels and tube circles, plane lines and circles —
// against the independent kinematic oracle (src/kinematics: SO(3) from the
// surface's points and normals only), within 1e-10 rad; and `exact` refusing
// a storyboard with one varying segment, naming that segment.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "core/error.hpp"
#include "kinematics/rolling_kinematics.hpp"
#include "model/rolling_model.hpp"
#include "motion/solve_job.hpp"
#include "scene/scene_loader.hpp"
#include "spin/propagator.hpp"
#include "spin/su2.hpp"
#include "support/sweep.hpp"

using namespace rollspin;

namespace {

// Solves the storyboard with solver.method = "exact" as `rollspin solve`
// does and returns the SO(3) distance of U(L) to the oracle's Q(L).
double exactAgainstOracle(const std::string& toml, const std::string& name) {
  const scene::SceneSpec spec = scene::loadSceneText(toml + "[solver]\nmethod = \"exact\"\n", name);
  const model::RollingModel model = model::buildModel(spec);
  motion::SolverChoice choice = motion::chooseSolver(spec, model);
  EXPECT_EQ(choice.method, spin::Method::Exact) << name;
  const spin::SolveStats stats = motion::solveScene(spec, model, choice);
  EXPECT_EQ(stats.steps, 0) << name << ": the closed form takes no steps";
  kinematics::KinematicSettings settings;
  // The oracle's steps: 4e4, at least 512 per radian; its own floor is then
  // ~1e-11 (its finite differences' round-off), its truncation below that.
  settings.steps = 40000;
  settings.minStepsPerRadian = 512.0;
  const Eigen::Quaterniond oq(
      kinematics::RollingKinematics(*model.path, model.ballRadius, settings).finalOrientation());
  const double error = spin::rotationDistance(stats.final, spin::Su2{oq.w(), oq.x(), oq.y(), oq.z()});
  if (std::getenv("ROLLSPIN_VERBOSE")) std::printf("%-36s exact vs oracle %.2e rad\n", name.c_str(), error);
  return error;
}

TEST(ExactStoryboard, AgreesWithTheKinematicsOnEverySurfaceWithConstantCurvatures) {
  std::mt19937 rng(4301);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const std::size_t c : test::sweepIndices(3)) {
    const double R = 0.3 + 0.7 * unit(rng);
    // Sphere (outside, then inside): a parallel, a great-circle geodesic from
    // its end, another geodesic; then a parallel and a meridian from its end.
    const double sphere = 2.0 + 2.0 * unit(rng), colatitude = 40.0 + 80.0 * unit(rng);
    for (const char* side : {"outside", "inside"}) {
      const std::string head = fmt::format(
          "[ball]\nradius = {:.17g}\n[surface]\nkind = \"sphere\"\nradius = {:.17g}\nside = \"{}\"\n", R, sphere, side);
      EXPECT_LT(exactAgainstOracle(
                    head + fmt::format("[[segment]]\npath = {{ kind = \"parallel\", colatitude_deg = "
                                       "{:.17g}, turns = {:.17g} }}\n"
                                       "[[segment]]\npath = {{ kind = \"geodesic\", length = {:.17g} }}\n"
                                       "[[segment]]\npath = {{ kind = \"geodesic\", length = {:.17g} }}\n",
                                       colatitude, 0.3 + 0.7 * unit(rng), 1.0 + 2.0 * unit(rng), 0.5 + unit(rng)),
                    fmt::format("sphere {} geodesics {}", side, c)),
                1e-10);
      EXPECT_LT(
          exactAgainstOracle(head + fmt::format("[[segment]]\npath = {{ kind = \"parallel\", colatitude_deg = "
                                                "{:.17g}, turns = 1 }}\n[[segment]]\nhold = 1\n"
                                                "[[segment]]\npath = {{ kind = \"meridian\", azimuth_deg = 0, "
                                                "colatitude_start_deg = {:.17g}, colatitude_end_deg = {:.17g} }}\n",
                                                colatitude, colatitude, 20.0 + 140.0 * unit(rng)),
                             fmt::format("sphere {} meridian {}", side, c)),
          1e-10);
    }
    // Cylinder: a parallel, a helix from its end, a parallel where the helix ends.
    const double a = 1.5 + unit(rng), pitch = -60.0 + 120.0 * unit(rng), turns = 0.3 + unit(rng);
    const double rise = a * std::tan(pitch * std::numbers::pi / 180.0) * 2.0 * std::numbers::pi * turns;
    EXPECT_LT(exactAgainstOracle(
                  fmt::format("[ball]\nradius = {:.17g}\n[surface]\nkind = \"cylinder\"\nradius = {:.17g}\n"
                              "axis = [0, 0, 1]\nside = \"outside\"\n"
                              "[[segment]]\npath = {{ kind = \"parallel\", height = 0, turns = 1 }}\n"
                              "[[segment]]\npath = {{ kind = \"helix\", pitch_angle_deg = {:.17g}, height = 0, turns = "
                              "{:.17g} }}\n"
                              "[[segment]]\npath = {{ kind = \"parallel\", height = {:.17g}, start_azimuth_deg = "
                              "{:.17g}, turns = 0.5 }}\n",
                              R, a, pitch, turns, rise, 360.0 * turns),
                  fmt::format("cylinder helix {}", c)),
              1e-10);
    // Torus: a parallel up the tube, then once round the tube from its end.
    const double tube = -90.0 + 180.0 * unit(rng);
    EXPECT_LT(exactAgainstOracle(
                  fmt::format("[ball]\nradius = {:.17g}\n[surface]\nkind = \"torus\"\nmajor_radius = 4\n"
                              "minor_radius = 1.5\nside = \"outside\"\n"
                              "[[segment]]\npath = {{ kind = \"parallel\", tube_angle_deg = {:.17g}, turns = 1 }}\n"
                              "[[segment]]\npath = {{ kind = \"meridian\", azimuth_deg = 0, tube_angle_deg = {:.17g}, "
                              "turns = {:.17g} }}\n",
                              std::min(R, 1.2), tube, tube, 0.3 + unit(rng)),
                  fmt::format("torus tube {}", c)),
              1e-10);
    // A tilted plane: line, circle, line, circle (each from the previous end).
    const Eigen::Vector3d n = Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, 1.0).normalized();
    EXPECT_LT(exactAgainstOracle(
                  fmt::format("[ball]\nradius = {:.17g}\n[surface]\nkind = \"plane\"\nnormal = [{:.17g}, {:.17g}, "
                              "{:.17g}]\n"
                              "[[segment]]\npath = {{ kind = \"line\", length = {:.17g} }}\n"
                              "[[segment]]\npath = {{ kind = \"circle\", radius = {:.17g}, turns = {:.17g} }}\n"
                              "[[segment]]\npath = {{ kind = \"line\", length = 1 }}\n"
                              "[[segment]]\npath = {{ kind = \"circle\", radius = {:.17g}, turns = 0.3 }}\n",
                              R, n.x(), n.y(), n.z(), 0.5 + unit(rng), 0.5 + 2.0 * unit(rng), 0.2 + unit(rng),
                              0.3 + unit(rng)),
                  fmt::format("plane lines and circles {}", c)),
              1e-10);
  }
}

TEST(ExactStoryboard, RefusesAVaryingSegmentAndNamesIt) {
  // Segment 1 (a parallel) is constant; segment 3 (a geodesic on a
  // paraboloid, integrated) is not: the message names segment[3].
  const std::string toml =
      "[ball]\nradius = 0.5\n[surface]\nkind = \"paraboloid\"\na = 2\nb = 2\nside = \"above\"\n"
      "[[segment]]\npath = { kind = \"parallel\", radius = 1, turns = 1 }\n"
      "[[segment]]\nhold = 1\n"
      "[[segment]]\npath = { kind = \"geodesic\", length = 2 }\n"
      "[solver]\nmethod = \"exact\"\n";
  const scene::SceneSpec spec = scene::loadSceneText(toml, "paraboloid-story");
  const model::RollingModel model = model::buildModel(spec);
  try {
    (void)motion::chooseSolver(spec, model);
    FAIL() << "exact accepted a storyboard with a geodesic on a paraboloid";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("segment[3].path"), std::string::npos) << what;
    EXPECT_NE(what.find("geodesic"), std::string::npos) << what;
    EXPECT_EQ(what.find("segment[1]"), std::string::npos) << what;
    EXPECT_NE(what.find("constant curvatures"), std::string::npos) << what;
  }
}

}  // namespace
