// model/ on every row of the surface-kind table, on each side the kind
// offers: a scene that names only the kind builds a RollingModel whose path
// lies on its surface with the surface's own ball-side normal, a ball that
// touches at one point, and a look (mesh, up, cut-away) that agrees with
// where the ball is: a board's `up` is the normal the ball stands on, a
// sphere mesh passes through the path and is cut away exactly when the ball
// rolls inside it, and a chart mesh's parameters reach every contact point.
// surface_model itself: which scenes are the foundation's closed forms
// (isAnalyticScene), points in space mapped to a chart, and the BadInput of
// buildSurfaceModel at the key responsible (a point with no parameters, a
// geodesic along the normal, a ball that stops touching at one point).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/param_table.hpp"
#include "geometry/surface_kinds.hpp"
#include "geometry/surface_paths.hpp"
#include "model/rolling_model.hpp"
#include "model/surface_builder.hpp"
#include "model/surface_model.hpp"
#include "scene/scene_loader.hpp"

namespace rollspin::model {
namespace {

using geometry::SurfaceLook;
using geometry::Vec3;

struct KindScene {
  std::string label;  // "torus side=inside"
  std::string toml;
};

// One scene per kind and per value of each of its choice keys (the sides).
std::vector<KindScene> kindScenes(double ballRadius) {
  std::vector<KindScene> out;
  for (const geometry::SurfaceKindRow& row : geometry::surfaceKindTable()) {
    const std::string head =
        "[ball]\nradius = " + std::to_string(ballRadius) + "\n[surface]\nkind = \"" + row.name + "\"\n";
    out.push_back({row.name, head});
    for (const ParamDecl& p : row.params)
      if (p.type == ParamType::Choice)
        for (const std::string& choice : p.choices)
          out.push_back({row.name + " " + p.key + "=" + choice, head + p.key + " = \"" + choice + "\"\n"});
  }
  return out;
}

std::vector<double> samples(double length, int n) {
  std::vector<double> s;
  for (int k = 0; k <= n; ++k) s.push_back(length * k / n);
  return s;
}

TEST(SurfaceModel, TheDefaultPathLiesOnTheSurfaceWithItsBallSideNormal) {
  for (const KindScene& k : kindScenes(0.5)) {
    const RollingModel m = buildModel(scene::loadSceneText(k.toml, "<" + k.label + ">"));
    ASSERT_TRUE(m.surface && m.path) << k.label;
    EXPECT_DOUBLE_EQ(m.ballRadius, 0.5) << k.label;
    for (double s : samples(m.path->length(), 24)) {
      const Vec3 p = m.path->point(s);
      EXPECT_NEAR(m.surface->distance(p), 0.0, 1e-9) << k.label << " s = " << s;
      EXPECT_NEAR((m.path->normal(s) - m.surface->normalAt(p)).norm(), 0.0, 1e-9) << k.label << " s = " << s;
    }
    // Curves laid on a chart carry the one-point-contact check (the closed-form
    // paths, a plane's circle and a sphere's parallel, fit by construction).
    if (const auto* curve = dynamic_cast<const geometry::SurfaceCurvePath*>(m.path.get())) {
      EXPECT_TRUE(geometry::checkSingleContact(*curve, m.ballRadius).ok) << k.label;
    }
  }
}

TEST(SurfaceModel, TheLookAgreesWithWhereTheBallIs) {
  for (const KindScene& k : kindScenes(0.5)) {
    const RollingModel m = buildModel(scene::loadSceneText(k.toml, "<" + k.label + ">"));
    const SurfaceLook look = m.surface->look();
    for (double s : samples(m.path->length(), 12)) {
      const Vec3 p = m.path->point(s), centre = p + m.ballRadius * m.path->normal(s);
      switch (look.mesh) {
        case SurfaceLook::Mesh::Board:
          // A flat board under the path: the ball stands on the side `up` names.
          EXPECT_NEAR((look.up - m.surface->normalAt(p)).norm(), 0.0, 1e-12) << k.label;
          EXPECT_NEAR((centre - p).dot(look.up), m.ballRadius, 1e-12) << k.label;
          EXPECT_FALSE(look.canHideBall) << k.label;
          break;
        case SurfaceLook::Mesh::Sphere:
          // The mesh passes through the contact; its near cap is cut away
          // exactly when the ball is inside it.
          EXPECT_NEAR(p.norm(), look.radius, 1e-9) << k.label;
          EXPECT_EQ(look.cutAwayTowardEye, centre.norm() < look.radius) << k.label;
          break;
        case SurfaceLook::Mesh::Chart: {
          // The mesh is x(u, v) over the parameters the path visits.
          const auto uv = m.surface->parametersOf(p);
          ASSERT_TRUE(uv.has_value()) << k.label << " s = " << s;
          EXPECT_NEAR((m.surface->position(*uv) - p).norm(), 0.0, 1e-9) << k.label << " s = " << s;
          EXPECT_FALSE(look.cutAwayTowardEye) << k.label << ": only a closed mesh can be cut away";
          break;
        }
      }
    }
  }
}

// The side key reaches the surface: the two sides of a kind put the ball on
// opposite sides of the same contact point.
TEST(SurfaceModel, TheTwoSidesOfAKindAreOpposite) {
  int pairs = 0;
  for (const geometry::SurfaceKindRow& row : geometry::surfaceKindTable())
    for (const ParamDecl& p : row.params) {
      if (p.type != ParamType::Choice || p.choices.size() != 2) continue;
      std::vector<std::shared_ptr<const geometry::Surface>> sides;
      for (const std::string& choice : p.choices)
        sides.push_back(buildSurface(scene::loadSceneText(
            "[ball]\nradius = 0.5\n[surface]\nkind = \"" + row.name + "\"\n" + p.key + " = \"" + choice + "\"\n",
            "<" + row.name + ">")));
      const Vec3 x = sides[0]->position(geometry::Vec2(0.4, 0.3));
      EXPECT_NEAR(sides[1]->distance(x), 0.0, 1e-12) << row.name;
      EXPECT_NEAR((sides[0]->normalAt(x) + sides[1]->normalAt(x)).norm(), 0.0, 1e-12) << row.name << " " << p.key;
      ++pairs;
    }
  EXPECT_GE(pairs, 3);
}

// The foundation's closed-form paths are exactly a plane's line, circle and
// clothoid and a sphere's parallel; every other scene is a curve laid on a
// chart by buildSurfaceModel.
TEST(SurfaceModel, OnlyThePlanesLinesCirclesAndClothoidsAndTheSpheresParallelsAreAnalytic) {
  struct Case {
    const char* surface;
    const char* path;
    bool analytic;
  };
  const Case cases[] = {
      {"plane", "line", true},       {"plane", "circle", true},         {"plane", "clothoid", true},
      {"sphere", "parallel", true},  {"plane", "points", false},        {"plane", "uv", false},
      {"plane", "geodesic", false},  {"sphere", "meridian", false},     {"sphere", "loxodrome", false},
      {"sphere", "geodesic", false}, {"torus", "parallel", false},      {"cylinder", "parallel", false},
      {"cylinder", "helix", false},  {"paraboloid", "parallel", false},
  };
  for (const Case& c : cases) {
    const std::string label = std::string(c.surface) + " " + c.path;
    const std::string points = std::string(c.path) == "points" ? "points = [[0, 0], [1, 1], [2, 0]]\n" : "";
    const scene::SceneSpec spec = scene::loadSceneText(
        std::string("[surface]\nkind = \"") + c.surface + "\"\n[path]\nkind = \"" + c.path + "\"\n" + points,
        "<" + label + ">");
    EXPECT_EQ(isAnalyticScene(spec), c.analytic) << label;
    if (!c.analytic) {
      const RollingModel m = buildSurfaceModel(spec);
      EXPECT_NE(dynamic_cast<const geometry::SurfaceCurvePath*>(m.path.get()), nullptr) << label;
      EXPECT_EQ(m.ballRadius, spec.ball.radius) << label;
    }
  }
}

// Points may be given in the surface's parameters (two numbers) or in space
// (three, mapped to the parameters of that point): on a sphere of radius 2
// the path then starts on the sphere in the direction of the first point.
TEST(SurfaceModel, PointsInSpaceAreMappedToTheSurfacesParameters) {
  const scene::SceneSpec spec = scene::loadSceneText(
      "[surface]\nkind = \"sphere\"\nradius = 2\n[path]\nkind = \"points\"\nclosed = true\n"
      "points = [[2, 0, 0.5], [0, 2, 0.5], [-2, 0, 0.5], [0, -2, 1]]\n",
      "<points in space>");
  const RollingModel m = buildSurfaceModel(spec);
  EXPECT_NEAR((m.path->point(0.0) - 2.0 * Vec3(2, 0, 0.5).normalized()).norm(), 0.0, 1e-12);
  const scene::SceneSpec flat = scene::loadSceneText(
      "[path]\nkind = \"points\"\npoints = [[0.5, -1], [2, 0], [3, 2]]\n", "<points in parameters>");
  EXPECT_NEAR((buildSurfaceModel(flat).path->point(0.0) - Vec3(0.5, -1, 0)).norm(), 0.0, 1e-12);
}

// A scene's BadInput from buildSurfaceModel, with the key's line in the scene text.
Error surfaceModelError(const std::string& toml) {
  try {
    (void)buildSurfaceModel(scene::loadSceneText(toml, "scene.toml"));
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "expected BadInput from:\n" << toml;
  return Error(ErrorKind::Runtime, {}, "");
}

// A point on a torus's axis (or a cylinder's) has no (φ, ψ): refused at the
// key that gave it, with the point and what the parameters are.
TEST(SurfaceModel, APointWithNoSurfaceParametersIsBadInputAtTheKeyThatGaveIt) {
  const Error start =
      surfaceModelError("[surface]\nkind = \"torus\"\n[path]\nkind = \"geodesic\"\nstart_point = [0, 0, 1]\n");
  EXPECT_EQ(start.kind(), ErrorKind::BadInput);
  EXPECT_EQ(start.where().file, "scene.toml");
  EXPECT_EQ(start.where().line, 5);
  EXPECT_EQ(start.message().rfind("path.start_point: the point (0, 0, 1) has no surface parameters here (", 0), 0u)
      << start.what();
  const Error points = surfaceModelError(
      "[surface]\nkind = \"cylinder\"\n[path]\nkind = \"points\"\npoints = [[1, 0, 0], [0, 0, 2], [0, 1, 3]]\n");
  EXPECT_EQ(points.kind(), ErrorKind::BadInput);
  EXPECT_EQ(points.where().line, 5);
  EXPECT_EQ(points.message().rfind("path.points: the point (0, 0, 2) has no surface parameters here", 0), 0u)
      << points.what();
}

// A geodesic needs a direction along the surface: one along the normal at
// the start point is refused at path.direction_vector.
TEST(SurfaceModel, AGeodesicDirectionAlongTheNormalIsBadInputAtTheDirection) {
  const Error e = surfaceModelError(
      "[surface]\nkind = \"sphere\"\nradius = 2\n[path]\nkind = \"geodesic\"\nstart_point = [0, 2, 0]\n"
      "direction_vector = [0, -3, 0]\n");
  EXPECT_EQ(e.kind(), ErrorKind::BadInput);
  EXPECT_EQ(e.where().line, 7);
  EXPECT_EQ(e.message().rfind("path.direction_vector: perpendicular to the surface at the start point", 0), 0u)
      << e.what();
}

// A ball that the scene loader lets through but that stops touching at one
// point somewhere along the curve (on a saddle's meridian, where the
// surface curves towards it more tightly than 1/R) is blamed on
// ball.radius, with the first arc length where the check fails.
TEST(SurfaceModel, ABallThatDoesNotTouchAtOnePointIsBadInputAtTheBallRadius) {
  const Error e = surfaceModelError(
      "[ball]\nradius = 1.5\n[surface]\nkind = \"saddle\"\na = 1\nb = 2\n[path]\nkind = \"meridian\"\n"
      "azimuth_deg = 90\nlength = 6\n");
  EXPECT_EQ(e.kind(), ErrorKind::BadInput);
  EXPECT_EQ(e.where().line, 2);
  EXPECT_EQ(e.message().rfind("ball.radius: ", 0), 0u) << e.what();
  EXPECT_NE(e.message().find("arc length s = "), std::string::npos) << e.what();
}

}  // namespace
}  // namespace rollspin::model
