// Walks every variation-point table the scene layer reads: each surface kind,
// path kind and solver method is reachable from a scene file (and builds its
// geometry), the keys of other kinds stay rejected, and `scene --print`'s text
// reads back to the same scene.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "model/rolling_model.hpp"
#include "motion/solve_job.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_writer.hpp"
#include "spin/propagator.hpp"

namespace rollspin::scene {
namespace {

// Keys a kind needs beyond its defaults to make a valid scene.
std::string pathExtras(PathKind kind) {
  if (kind == PathKind::Points) return "points = [[1.0, 0.3], [1.2, 0.8], [1.4, 1.2]]\n";  // inside every domain
  return "";
}

SceneSpec roundTrip(const SceneSpec& spec) { return loadSceneText(writeScene(spec), "<printed>"); }

TEST(KindTables, EverySurfaceKindIsReachableBuildsAndRoundTrips) {
  for (const SceneSurfaceKind& row : surfaceKinds()) {
    SCOPED_TRACE(std::string(row.name));
    const std::string text = "[surface]\nkind = \"" + std::string(row.name) + "\"\n";
    const SceneSpec spec = loadSceneText(text, "<table>");
    EXPECT_EQ(spec.surface.kind, row.kind);
    EXPECT_EQ(spec.path.kind, row.kind == SurfaceKind::Plane ? spec.path.kind : row.defaultPath);
    const model::RollingModel model = model::buildModel(spec);
    ASSERT_TRUE(model.surface && model.path);
    EXPECT_GT(model.path->length(), 0.0);
    const SceneSpec again = roundTrip(spec);
    EXPECT_EQ(again.surface.kind, row.kind);
    EXPECT_EQ(writeScene(again), writeScene(spec));
    // Every other kind's own key is rejected here, naming the key.
    for (const std::string& key : allSurfaceKeys()) {
      if (std::find(row.keys.begin(), row.keys.end(), key) != row.keys.end()) continue;
      const std::string bad = text + key + " = 1\n";
      try {
        (void)loadSceneText(bad, "<table>");
        ADD_FAILURE() << "surface." << key << " accepted on a " << row.name;
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("surface." + key), std::string::npos) << e.what();
      }
    }
  }
}

// Every surface key is declared with a default inside its own range, units
// and a meaning (what `rollspin keys` lists), and a scene that sets it to its
// default prints it back unchanged.
TEST(KindTables, EverySurfaceKeyIsDeclaredWithAValidDefault) {
  for (const SceneSurfaceKind& row : surfaceKinds()) {
    ASSERT_EQ(surfaceKeyDecls(row.kind).size(), row.keys.size());
    for (const ParamDecl& decl : surfaceKeyDecls(row.kind)) {
      SCOPED_TRACE(std::string(row.name) + "." + decl.key);
      EXPECT_FALSE(decl.meaning.empty());
      EXPECT_FALSE(decl.range().empty());
      switch (decl.type) {
        case ParamType::Number:
          EXPECT_GT(std::get<double>(decl.defaultValue), decl.lowerBound);
          EXPECT_FALSE(decl.units.empty());
          break;
        case ParamType::Choice:
          ASSERT_FALSE(decl.choices.empty());
          EXPECT_EQ(std::get<std::string>(decl.defaultValue), decl.choices.front());
          break;
        case ParamType::Direction: {
          const auto& v = std::get<std::array<double, 3>>(decl.defaultValue);
          EXPECT_DOUBLE_EQ(v[0] * v[0] + v[1] * v[1] + v[2] * v[2], 1.0);
          break;
        }
        case ParamType::Expression: EXPECT_FALSE(decl.variables.empty()); break;
      }
      const SceneSpec spec = loadSceneText("[surface]\nkind = \"" + std::string(row.name) + "\"\n", "<table>");
      EXPECT_EQ(spec.surface.params.at(decl.key), decl.defaultValue);
      EXPECT_NE(writeScene(spec).find("\n" + decl.key + " = "), std::string::npos);
    }
  }
}

// A value below a number key's range is refused at its file:line:col, naming
// the key and the range.
TEST(KindTables, ANumberKeyBelowItsRangeIsRefusedAtItsLocation) {
  for (const SceneSurfaceKind& row : surfaceKinds())
    for (const ParamDecl& decl : surfaceKeyDecls(row.kind)) {
      if (decl.type != ParamType::Number) continue;
      SCOPED_TRACE(std::string(row.name) + "." + decl.key);
      const std::string text = "[surface]\nkind = \"" + std::string(row.name) + "\"\n" + decl.key + " = " +
                               std::to_string(decl.lowerBound - 1.0) + "\n";
      try {
        (void)loadSceneText(text, "bad.toml");
        ADD_FAILURE() << "accepted";
      } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("bad.toml:3:"), std::string::npos) << m;
        EXPECT_NE(m.find("surface." + decl.key + ": expected " + decl.noun + " > "), std::string::npos) << m;
      }
    }
}

TEST(KindTables, EveryPathKindIsReachableOnEachSurfaceItLiesOnAndRoundTrips) {
  for (const PathKindRow& path : pathKinds()) {
    int surfaces = 0;
    for (const SceneSurfaceKind& surface : surfaceKinds()) {
      if (!liesOn(path.kind, surface.kind)) continue;
      // A parallel on a paraboloid needs a = b (a surface of revolution).
      SCOPED_TRACE(std::string(path.name) + " on " + std::string(surface.name));
      const std::string text = "[surface]\nkind = \"" + std::string(surface.name) + "\"\n[path]\nkind = \"" +
                               std::string(path.name) + "\"\n" + pathExtras(path.kind);
      const SceneSpec spec = loadSceneText(text, "<table>");
      EXPECT_EQ(spec.path.kind, path.kind);
      const model::RollingModel model = model::buildModel(spec);
      ASSERT_TRUE(model.path);
      const SceneSpec again = roundTrip(spec);
      EXPECT_EQ(writeScene(again), writeScene(spec));
      ++surfaces;
      // A key of this path kind that does not apply on this surface is rejected.
      for (const std::string& key : allPathKeys()) {
        if (pathKeyRule(key, path.kind, surface.kind).applies) continue;
        try {
          (void)loadSceneText(text + key + " = 1\n", "<table>");
          ADD_FAILURE() << "path." << key << " accepted for a " << path.name << " on a " << surface.name;
        } catch (const Error& e) {
          EXPECT_NE(std::string(e.what()).find("path." + key), std::string::npos) << e.what();
        }
      }
    }
    EXPECT_GT(surfaces, 0) << path.name << " lies on no surface";
  }
}

TEST(KindTables, APathOffItsSurfacesIsRejected) {
  for (const PathKindRow& path : pathKinds())
    for (const SceneSurfaceKind& surface : surfaceKinds()) {
      if (liesOn(path.kind, surface.kind)) continue;
      const std::string text = "[surface]\nkind = \"" + std::string(surface.name) + "\"\n[path]\nkind = \"" +
                               std::string(path.name) + "\"\n";
      EXPECT_THROW((void)loadSceneText(text, "<table>"), Error) << path.name << " on " << surface.name;
    }
}

TEST(KindTables, EverySolverMethodIsReachableFromASceneAndRoundTrips) {
  for (spin::Method m : spin::allMethods()) {
    const std::string name(spin::methodName(m));
    SCOPED_TRACE(name);
    const SceneSpec spec = loadSceneText("[solver]\nmethod = \"" + name + "\"\n", "<table>");
    const model::RollingModel model = model::buildModel(spec);
    EXPECT_EQ(motion::chooseSolver(spec, model).method, m);
    EXPECT_EQ(roundTrip(spec).solver.method, name);
  }
  EXPECT_THROW((void)loadSceneText("[solver]\nmethod = \"euler\"\n", "<table>"), Error);
}

}  // namespace
}  // namespace rollspin::scene
