// Scene loading: defaults, locations, overrides, and the model built from it
// (including Brockett's plate, whose contact circle is derived).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <fstream>
#include <numbers>

#include <unistd.h>

#include "core/error.hpp"
#include "geometry/uv_curve.hpp"
#include "media/output_format.hpp"
#include "model/rolling_model.hpp"
#include "motion/solve_job.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_writer.hpp"
#include "spin/field.hpp"
#include "spin/propagator.hpp"

using namespace rollspin;

TEST(SceneLoader, EmptySceneTakesEveryDefault) {
  const scene::SceneSpec spec = scene::loadSceneText("", "<empty>");
  EXPECT_EQ(spec.ball.radius, 1.0);
  EXPECT_EQ(spec.surface.kind, scene::SurfaceKind::Plane);
  EXPECT_EQ(spec.path.kind, scene::PathKind::Circle);
  EXPECT_EQ(spec.path.radius, 3.0);
  EXPECT_EQ(spec.path.turns, 1.0);
  EXPECT_TRUE(spec.path.counterClockwise);
  EXPECT_EQ(spec.solver.method, "magnus4");
  EXPECT_FALSE(spec.solver.steps.has_value());
  EXPECT_FALSE(spec.plate.has_value());
  EXPECT_EQ(spec.where("ball.radius").str(), "<empty>");  // default: the file, no line
}

TEST(SceneLoader, RemembersWhereEachKeyWasSet) {
  const scene::SceneSpec spec = scene::loadSceneText("[ball]\n  radius = 2.5\n", "s.toml");
  EXPECT_EQ(spec.ball.radius, 2.5);
  EXPECT_EQ(spec.where("ball.radius").str(), "s.toml:2:12");
}

TEST(SceneLoader, OverridesReplaceAndCreateKeys) {
  const std::vector<std::string> sets{"ball.radius=0.5", "surface.kind=sphere", "path.colatitude_deg=30",
                                      "solver.method=exact", "timeline.samples=11"};
  const scene::SceneSpec spec = scene::loadSceneText("[ball]\nradius = 2\n", "s.toml", sets);
  EXPECT_EQ(spec.ball.radius, 0.5);
  EXPECT_EQ(spec.surface.kind, scene::SurfaceKind::Sphere);
  EXPECT_EQ(spec.path.kind, scene::PathKind::Parallel);  // the sphere's one path kind
  EXPECT_EQ(spec.path.colatitudeDeg, 30.0);
  EXPECT_EQ(spec.where("ball.radius").str(), "--set ball.radius=0.5");
  EXPECT_EQ(*spec.timeline.samples, 11);
}

TEST(SceneLoader, PlaneNormalIsNormalisedAndLineDefaultsToAHorizontalDirection) {
  const scene::SceneSpec spec = scene::loadSceneText("[surface]\nnormal = [0, -2, 0]\n[path]\nkind = \"line\"\n", "w");
  const model::RollingModel model = model::buildModel(spec);
  const geometry::DarbouxSample f = model.path->at(0.0);
  EXPECT_NEAR(f.normal.y(), -1.0, 1e-15);
  EXPECT_NEAR(f.tangent.z(), 0.0, 1e-15);  // horizontal
  EXPECT_NEAR(std::abs(f.tangentNormal.z()), 1.0, 1e-15);
}

// toml++ gives no double for an integer above 2^53 (none holds it exactly);
// such a number still loads, as the nearest double, wherever a number goes:
// a number key, a vector's element, a point's coordinate. fuzz_scene found
// the first one escaping as std::bad_optional_access.
TEST(SceneLoader, IntegersBeyondTwoToThe53AreNumbers) {
  const double nearest = 9007199254740992.0;  // 2^53, nearest to 2^53 + 1
  const scene::SceneSpec uv =
      scene::loadSceneText("[path]\nkind = \"uv\"\nu = \"t\"\nv = \"0\"\nt_end = 9007199254740993\n", "s.toml");
  EXPECT_EQ(uv.path.tEnd, nearest);
  const scene::SceneSpec start = scene::loadSceneText(
      "[surface]\nkind = \"sphere\"\n[path]\nkind = \"geodesic\"\nstart_point = [9007199254740993, 0, 0]\n", "s.toml");
  ASSERT_TRUE(start.path.startPoint.has_value());
  EXPECT_EQ((*start.path.startPoint)[0], nearest);
  const scene::SceneSpec points =
      scene::loadSceneText("[path]\nkind = \"points\"\npoints = [[0, 0], [1, 9007199254740993], [2, 0]]\n", "s.toml");
  ASSERT_EQ(points.path.points.size(), 3u);
  EXPECT_EQ(points.path.points[1][1], nearest);
}

// A uv ellipse over a long parameter range needs arc-length panels in
// proportion (about 7 per turn): under a PanelBudget (the fuzzer sets one)
// building it stops with a BadInput naming the path key, without one it
// builds, and a budget ends with its scope.
TEST(PanelBudget, BoundsTheWorkOfBuildingALongPath) {
  const std::string text =
      "[surface]\nkind = \"height\"\nz = \"0.3*sin(x)*cos(y)\"\n[path]\nkind = \"uv\"\n"
      "u = \"2*cos(t)\"\nv = \"1.5*sin(t)\"\nt_end = 628.3\n";  // 100 turns
  const scene::SceneSpec spec = scene::loadSceneText(text, "long.toml");
  {
    const geometry::PanelBudget budget(200);
    try {
      (void)model::buildModel(spec);
      ADD_FAILURE() << "a path of 100 turns built within 200 panels";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("path"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("200 panels"), std::string::npos) << e.what();
    }
    {
      const geometry::PanelBudget roomy(2000);  // the innermost counts
      EXPECT_NO_THROW((void)model::buildModel(spec));
    }
    EXPECT_THROW((void)model::buildModel(spec), Error);
  }
  const model::RollingModel model = model::buildModel(spec);
  EXPECT_GT(model.path->length(), 100.0 * 2.0 * std::numbers::pi);
}

TEST(BrockettPlate, ContactCircleIsHalfThePlateCircleAndTheTopMovesWithThePlate) {
  const scene::SceneSpec spec = scene::loadSceneText("[ball]\nradius = 1\n[plate]\nradius = 4\n", "brockett");
  const model::RollingModel model = model::buildModel(spec);
  ASSERT_TRUE(model.plate.has_value());
  EXPECT_NEAR(model.plate->contactSpeedRatio, 2.0, 1e-15);
  EXPECT_NEAR(model.path->length(), 2 * std::numbers::pi * 2.0, 1e-12);  // r = R1/2 = 2
  // Along the path, the velocity of the ball's top point (from the solver's
  // quaternions: C' + ω × R n) is twice the contact velocity, so a plate
  // translated by 2(P(s) − P(0)) stays on the top without slipping and its
  // points describe circles of radius R1.
  const double R = model.ballRadius, h = 1e-4;
  const spin::Propagator propagator(*model.path, R, spin::Method::Exact, 0);
  for (double s : {0.5, 3.0, 7.0, 11.0}) {
    const std::vector<double> at{s - h, s, s + h};
    std::vector<spin::Su2> q(3);
    (void)propagator.run(at, [&](std::size_t j, double, const spin::Su2& u) { q[j] = u; });
    const spin::Su2 dq{(q[2].w - q[0].w) / (2 * h), (q[2].x - q[0].x) / (2 * h), (q[2].y - q[0].y) / (2 * h),
                       (q[2].z - q[0].z) / (2 * h)};
    const Eigen::Vector3d omega = 2.0 * (dq * q[1].conjugate()).vec();
    const geometry::DarbouxSample f = model.path->at(s);
    const Eigen::Vector3d top = f.tangent + omega.cross(R * f.normal);  // C' = t on a plane
    EXPECT_LT((top - 2.0 * f.tangent).norm(), 1e-7) << s;
    const Eigen::Vector3d platePoint = model.plate->initialTopPoint + 2.0 * (f.point - model.path->point(0.0));
    EXPECT_NEAR((platePoint - Eigen::Vector3d(0, 0, 2 * R) - Eigen::Vector3d(-2, 0, 0)).head<2>().norm(), 4.0, 1e-12);
  }
}

TEST(SolveJob, AutomaticStepsReachRoundOffOnTheLollipop) {
  const scene::SceneSpec spec = scene::loadSceneText("", "lollipop");
  const model::RollingModel model = model::buildModel(spec);
  const motion::SolverChoice choice = motion::chooseSolver(spec, model);
  EXPECT_TRUE(choice.automaticSteps);
  const spin::Su2 exact = spin::Propagator(*model.path, 1.0, spin::Method::Exact, 0).solveFinal().final;
  const spin::Su2 got = motion::solveScene(spec, model, choice).final;
  EXPECT_LT(spin::spinorDistance(got, exact), 1e-12);
}

TEST(SolveJob, DefaultSamplesAreSixtyPerTurn) {
  const scene::SceneSpec spec = scene::loadSceneText("[path]\nturns = 2\n[ball]\nradius = 100\n", "slow");
  const model::RollingModel model = model::buildModel(spec);
  EXPECT_EQ(motion::defaultSampleCount(model), 121);  // the path turns more than the ball
}

// ---- extends -------------------------------------------------------------

namespace {
std::filesystem::path writeFile(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
  return p;
}
}  // namespace

TEST(Extends, ChildKeysOverrideTheBaseAndBaseKeysKeepTheirLocation) {
  const auto dir = std::filesystem::temp_directory_path() / ("rollspin-extends-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir / "family");
  writeFile(dir / "base.toml", "[ball]\nradius = 0.5\n[path]\nturns = 2\nradius = 4\n");
  const auto child = writeFile(dir / "family" / "child.toml", "extends = \"../base.toml\"\n[path]\nradius = 1.5\n");
  const scene::SceneSpec spec = scene::loadSceneFile(child);
  EXPECT_EQ(spec.ball.radius, 0.5);  // inherited
  EXPECT_EQ(spec.path.turns, 2.0);   // inherited
  EXPECT_EQ(spec.path.radius, 1.5);  // overridden
  EXPECT_EQ(spec.name, "child");
  EXPECT_EQ(spec.where("ball.radius").str(), (dir / "base.toml").lexically_normal().string() + ":2:10");
  EXPECT_EQ(spec.where("path.radius").line, 3);
  // Two levels, and an override on top.
  const auto grandchild = writeFile(dir / "family" / "g.toml", "extends = \"child.toml\"\n[ball]\nradius = 2\n");
  const std::vector<std::string> sets{"path.turns=3"};
  const scene::SceneSpec g = scene::loadSceneFile(grandchild, sets);
  EXPECT_EQ(g.ball.radius, 2.0);
  EXPECT_EQ(g.path.radius, 1.5);
  EXPECT_EQ(g.path.turns, 3.0);
  std::filesystem::remove_all(dir);
}

TEST(Extends, CyclesMissingFilesAndBadValuesAreErrors) {
  const auto dir = std::filesystem::temp_directory_path() / ("rollspin-extends-bad-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto a = writeFile(dir / "a.toml", "extends = \"b.toml\"\n");
  writeFile(dir / "b.toml", "# b\nextends = \"a.toml\"\n");
  const auto self = writeFile(dir / "self.toml", "extends = \"self.toml\"\n");
  const auto missing = writeFile(dir / "missing.toml", "extends = \"nope.toml\"\n");
  const auto number = writeFile(dir / "number.toml", "extends = 3\n");
  const auto badBase = writeFile(dir / "badbase.toml", "extends = \"base.toml\"\n");
  writeFile(dir / "base.toml", "[ball]\nradius = -1\n");
  auto message = [](const std::filesystem::path& p) {
    try {
      (void)scene::loadSceneFile(p);
    } catch (const Error& e) {
      EXPECT_EQ(e.exitCode(), 2);
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(a).find("cycle: a.toml -> b.toml -> a.toml"), std::string::npos) << message(a);
  EXPECT_NE(message(a).find("b.toml:2:11"), std::string::npos) << message(a);
  EXPECT_NE(message(self).find("cycle"), std::string::npos);
  EXPECT_NE(message(missing).find("cannot read the scene file"), std::string::npos);
  EXPECT_NE(message(missing).find("missing.toml:1:11"), std::string::npos);
  EXPECT_NE(message(number).find("expected the path"), std::string::npos);
  EXPECT_NE(message(badBase).find("base.toml:2:10: ball.radius"), std::string::npos) << message(badBase);
  std::filesystem::remove_all(dir);
}

TEST(SceneLoader, FrameRatesAreExactRationals) {
  auto rate = [](const std::string& value) {
    return scene::loadSceneText("[animation]\nfps = " + value + "\n", "s.toml").animation.fps;
  };
  using scene::FrameRate;
  EXPECT_EQ(rate("24"), (FrameRate{24, 1}));
  EXPECT_EQ(rate("25.0"), (FrameRate{25, 1}));
  EXPECT_EQ(rate("23.976"), (FrameRate{24000, 1001}));
  EXPECT_EQ(rate("23.98"), (FrameRate{24000, 1001}));
  EXPECT_EQ(rate("29.97"), (FrameRate{30000, 1001}));
  EXPECT_EQ(rate("59.94"), (FrameRate{60000, 1001}));
  EXPECT_EQ(rate("119.88"), (FrameRate{120000, 1001}));
  EXPECT_EQ(rate("12.5"), (FrameRate{25, 2}));
  EXPECT_EQ(rate("\"30000/1001\""), (FrameRate{30000, 1001}));
  EXPECT_EQ(rate("\"60/2\""), (FrameRate{30, 1})) << "reduced";
  EXPECT_EQ(rate("\"29.97\""), (FrameRate{30000, 1001}));
  EXPECT_EQ(scene::loadSceneText("", "s.toml").animation.fps, (FrameRate{30, 1}));
  const std::vector<std::string> ntscFilm{"animation.fps=24000/1001"};
  EXPECT_EQ(scene::loadSceneText("", "s.toml", ntscFilm).animation.fps, (FrameRate{24000, 1001}));

  for (const std::string bad :
       {"0", "-30", "0.5", "241", "240.5", "12.3456", "\"abc\"", "\"30000/0\"", "\"0/1\"", "\"-30/1\"", "\"30/1001/2\"",
        "\"99999999999/1\"", "\"1/99999999999\"", "true", "inf"}) {
    try {
      (void)rate(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.exitCode(), 2) << bad;
      EXPECT_NE(what.find("s.toml:2:7: animation.fps: expected frames per second in [1, 240]"), std::string::npos)
          << bad << ": " << what;
      EXPECT_NE(what.find("\"30000/1001\""), std::string::npos) << what;
    }
  }
}

// render.format takes exactly the names of media's output-format table:
// each loads, prints back and loads again to the same name; the output keys
// (jpeg_quality, crf left to the format, loop) round-trip too.
TEST(SceneLoader, EveryOutputFormatNameLoadsAndPrintsBack) {
  for (const media::OutputFormat& f : media::kOutputFormats) {
    const std::string text =
        fmt::format("[render]\nformat = \"{}\"\njpeg_quality = 70\n[animation]\nloop = false\n", f.name);
    const scene::SceneSpec spec = scene::loadSceneText(text, "s.toml");
    ASSERT_TRUE(spec.render.format.has_value());
    EXPECT_EQ(*spec.render.format, f.name);
    const scene::SceneSpec again = scene::loadSceneText(scene::writeScene(spec), "printed.toml");
    EXPECT_EQ(again.render.format, spec.render.format) << scene::writeScene(spec);
    EXPECT_EQ(again.render.jpegQuality, 70);
    EXPECT_FALSE(again.animation.loop);
    EXPECT_FALSE(again.animation.crf.has_value()) << "crf stays the format's default";
  }
  try {
    (void)scene::loadSceneText("[render]\nformat = \"mkv\"\n", "s.toml");
    ADD_FAILURE() << "mkv accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("s.toml:2:10: render.format"), std::string::npos) << e.what();
  }
}

TEST(SceneLoader, FrameRatePrintsBackAsItsRational) {
  for (const std::string value : {"29.97", "24", "\"25/2\""}) {
    const scene::SceneSpec spec = scene::loadSceneText("[animation]\nfps = " + value + "\n", "s.toml");
    const scene::SceneSpec again = scene::loadSceneText(scene::writeScene(spec), "printed.toml");
    EXPECT_EQ(again.animation.fps, spec.animation.fps) << value << "\n" << scene::writeScene(spec);
  }
}
