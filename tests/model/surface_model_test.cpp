// model/ on every row of the surface-kind table, on each side the kind
// offers: a scene that names only the kind builds a RollingModel whose path
// lies on its surface with the surface's own ball-side normal, a ball that
// touches at one point, and a look (mesh, up, cut-away) that agrees with
// where the ball is: a board's `up` is the normal the ball stands on, a
// sphere mesh passes through the path and is cut away exactly when the ball
// rolls inside it, and a chart mesh's parameters reach every contact point.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/param_table.hpp"
#include "geometry/surface_kinds.hpp"
#include "geometry/surface_paths.hpp"
#include "model/rolling_model.hpp"
#include "model/surface_builder.hpp"
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

}  // namespace
}  // namespace rollspin::model
