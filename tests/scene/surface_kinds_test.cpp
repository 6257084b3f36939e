// scene/surface_kinds: the scene's view of geometry's surface-kind table.
// One row per geometry row, in its order, under its name; each row's keys
// are the kind's own declarations; its default path is the path kind
// geometry names and lies on the surface; a kind is "of revolution" exactly
// when a parallel lies on it; the named constants each find their own row;
// allSurfaceKeys is every kind's keys, once each, in the table's order.
#include "scene/surface_kinds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "geometry/surface_kinds.hpp"
#include "scene/path_kinds.hpp"

namespace rollspin::scene::surface_kinds_tests {
namespace {

TEST(SceneSurfaceKinds, OneRowPerGeometryRowInItsOrderUnderItsName) {
  const std::span<const geometry::SurfaceKindRow> geometryRows = geometry::surfaceKindTable();
  const std::span<const SceneSurfaceKind> rows = surfaceKinds();
  ASSERT_EQ(rows.size(), geometryRows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].name, geometryRows[i].name);
    EXPECT_EQ(rows[i].kind.name(), geometryRows[i].name);
    EXPECT_EQ(rows[i].geometry, &geometryRows[i]) << "its keys' declarations and factory are geometry's own";
    EXPECT_EQ(rows[i].ofRevolution, geometryRows[i].ofRevolution);
  }
}

TEST(SceneSurfaceKinds, EachNamedKindFindsItsOwnRow) {
  for (const SurfaceKind kind : {SurfaceKind::Plane, SurfaceKind::Sphere, SurfaceKind::Cylinder, SurfaceKind::Torus,
                                 SurfaceKind::Paraboloid, SurfaceKind::Saddle, SurfaceKind::Height}) {
    const SceneSurfaceKind& row = sceneSurfaceKind(kind);
    EXPECT_EQ(row.kind, kind);
    EXPECT_EQ(row.name, kind.name());
  }
  // The default kind is a plane, as SurfaceSpec's default is.
  EXPECT_EQ(SurfaceKind{}, SurfaceKind::Plane);
  EXPECT_FALSE(SurfaceKind::Sphere == SurfaceKind::Cylinder);
}

TEST(SceneSurfaceKinds, ARowsKeysAreItsKindsOwnDeclarationsInOrder) {
  for (const SceneSurfaceKind& row : surfaceKinds()) {
    const std::vector<ParamDecl>& decls = surfaceKeyDecls(row.kind);
    EXPECT_EQ(&decls, &row.geometry->params);
    ASSERT_EQ(row.keys.size(), decls.size()) << row.name;
    for (std::size_t i = 0; i < decls.size(); ++i) EXPECT_EQ(row.keys[i], decls[i].key) << row.name;
    EXPECT_EQ(std::find(row.keys.begin(), row.keys.end(), "kind"), row.keys.end()) << "besides kind";
  }
}

TEST(SceneSurfaceKinds, TheDefaultPathIsTheOneGeometryNamesAndLiesOnTheSurface) {
  for (const SceneSurfaceKind& row : surfaceKinds()) {
    EXPECT_EQ(pathKindRow(row.defaultPath).name, row.geometry->defaultPath) << row.name;
    EXPECT_TRUE(liesOn(row.defaultPath, row.kind)) << row.name << ": [path] without a kind must lie on it";
  }
  // The ones the docs name: a circle on a plane, a parallel on a sphere.
  EXPECT_EQ(sceneSurfaceKind(SurfaceKind::Plane).defaultPath, PathKind::Circle);
  EXPECT_EQ(sceneSurfaceKind(SurfaceKind::Sphere).defaultPath, PathKind::Parallel);
}

TEST(SceneSurfaceKinds, AKindIsOfRevolutionExactlyWhereAParallelLiesOnIt) {
  for (const SceneSurfaceKind& row : surfaceKinds())
    EXPECT_EQ(row.ofRevolution, liesOn(PathKind::Parallel, row.kind)) << row.name;
  EXPECT_TRUE(sceneSurfaceKind(SurfaceKind::Sphere).ofRevolution);
  EXPECT_FALSE(sceneSurfaceKind(SurfaceKind::Plane).ofRevolution);
  EXPECT_FALSE(sceneSurfaceKind(SurfaceKind::Saddle).ofRevolution);
}

TEST(SceneSurfaceKinds, AllSurfaceKeysIsEveryKindsKeysOnceInTableOrder) {
  const std::vector<std::string>& all = allSurfaceKeys();
  // Once each.
  EXPECT_EQ(std::set<std::string>(all.begin(), all.end()).size(), all.size());
  // Exactly the union.
  std::set<std::string> expected;
  for (const SceneSurfaceKind& row : surfaceKinds()) expected.insert(row.keys.begin(), row.keys.end());
  EXPECT_EQ(std::set<std::string>(all.begin(), all.end()), expected);
  // In the order first met, row by row.
  std::vector<std::string> firstMet;
  for (const SceneSurfaceKind& row : surfaceKinds())
    for (const std::string& key : row.keys)
      if (std::find(firstMet.begin(), firstMet.end(), key) == firstMet.end()) firstMet.push_back(key);
  EXPECT_EQ(all, firstMet);
  // A key two kinds share (a sphere's and a cylinder's radius) is there once.
  EXPECT_EQ(std::count(all.begin(), all.end(), "radius"), 1);
}

}  // namespace
}  // namespace rollspin::scene::surface_kinds_tests
