// scene/path_kinds.hpp: the path-kind table — one row a kind, the surfaces each lies on, its keys and their surfaces.
#include "scene/path_kinds.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace rollspin::scene {
namespace {

constexpr PathKind kEveryPathKind[] = {PathKind::Line,   PathKind::Circle,    PathKind::Parallel, PathKind::Meridian,
                                       PathKind::Helix,  PathKind::Loxodrome, PathKind::Geodesic, PathKind::Uv,
                                       PathKind::Points, PathKind::Clothoid};

// The surfaces (by name) a path kind lies on, in surfaceKinds()'s order.
std::vector<std::string> surfacesUnder(PathKind path) {
  std::vector<std::string> out;
  for (const SceneSurfaceKind& s : surfaceKinds())
    if (liesOn(path, s.kind)) out.emplace_back(s.name);
  return out;
}

TEST(PathKinds, EachKindHasOneRowUnderItsOwnName) {
  EXPECT_EQ(pathKinds().size(), std::size(kEveryPathKind));
  std::set<std::string_view> names;
  for (const PathKind kind : kEveryPathKind) {
    const PathKindRow& row = pathKindRow(kind);
    EXPECT_EQ(row.kind, kind) << row.name;
    EXPECT_TRUE(names.insert(row.name).second) << row.name << " names two kinds";
  }
  EXPECT_EQ(pathKindRow(PathKind::Line).name, "line");
  EXPECT_EQ(pathKindRow(PathKind::Loxodrome).name, "loxodrome");
  EXPECT_EQ(pathKindRow(PathKind::Clothoid).name, "clothoid");
}

TEST(PathKinds, EachKindLiesOnTheSurfacesItsRowNames) {
  using Names = std::vector<std::string>;
  const Names curved{"sphere", "cylinder", "torus", "paraboloid", "saddle", "height"};
  const Names every{"plane", "sphere", "cylinder", "torus", "paraboloid", "saddle", "height"};
  ASSERT_EQ(surfacesUnder(PathKind::Geodesic), every) << "the surface table changed: update this test";
  EXPECT_EQ(surfacesUnder(PathKind::Line), Names{"plane"});
  EXPECT_EQ(surfacesUnder(PathKind::Circle), Names{"plane"});
  EXPECT_EQ(surfacesUnder(PathKind::Clothoid), Names{"plane"});
  EXPECT_EQ(surfacesUnder(PathKind::Parallel), (Names{"sphere", "cylinder", "torus", "paraboloid"}));
  EXPECT_EQ(surfacesUnder(PathKind::Meridian), curved);
  EXPECT_EQ(surfacesUnder(PathKind::Helix), Names{"cylinder"});
  EXPECT_EQ(surfacesUnder(PathKind::Loxodrome), Names{"sphere"});
  EXPECT_EQ(surfacesUnder(PathKind::Uv), every);
  EXPECT_EQ(surfacesUnder(PathKind::Points), every);
}

TEST(PathKinds, DescribeNamesTheSurfacesForMessages) {
  EXPECT_EQ(describe(LiesOn::Plane), "plane");
  EXPECT_EQ(describe(LiesOn::Revolution), "sphere, cylinder, torus or paraboloid");
  EXPECT_EQ(describe(LiesOn::Curved), "curved surface");
  EXPECT_EQ(describe(LiesOn::Cylinder), "cylinder");
  EXPECT_EQ(describe(LiesOn::Sphere), "sphere");
  EXPECT_EQ(describe(LiesOn::Any), "surface");
}

// A key limited to some surfaces names only surfaces its path lies on (else no scene could use it there).
TEST(PathKinds, AKeysSurfacesAreOnesItsPathLiesOn) {
  for (const PathKindRow& row : pathKinds())
    for (const PathKey& key : row.keys)
      for (const SurfaceKind surface : key.on)
        EXPECT_TRUE(liesOn(row.kind, surface))
            << row.name << "." << key.key << " applies on a " << surface.name() << ", where no " << row.name << " lies";
}

TEST(PathKinds, AllPathKeysListsEveryRowsKeysOnceInTableOrder) {
  // Where each key first appears in the table: (row, place in the row).
  std::map<std::string, std::pair<std::size_t, std::size_t>> first;
  const std::span<const PathKindRow> rows = pathKinds();
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t k = 0; k < rows[r].keys.size(); ++k) first.try_emplace(rows[r].keys[k].key, r, k);
  const std::vector<std::string>& all = allPathKeys();
  EXPECT_EQ(all.size(), first.size()) << "a key missing or listed twice";
  for (std::size_t i = 0; i < all.size(); ++i) {
    ASSERT_TRUE(first.contains(all[i])) << all[i] << " is the key of no row";
    if (i > 0) {
      EXPECT_LT(first[all[i - 1]], first[all[i]]) << all[i - 1] << " before " << all[i];
    }
  }
  // The line's keys first, then those of the circle that the line has not.
  ASSERT_GE(all.size(), 5U);
  EXPECT_EQ(std::vector<std::string>(all.begin(), all.begin() + 5),
            (std::vector<std::string>{"length", "direction_vector", "turns", "direction", "radius"}));
}

}  // namespace
}  // namespace rollspin::scene
