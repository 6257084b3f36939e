// Path kinds: the one table of what a scene's [path] (or a segment's path)
// can be — each kind's name, the surfaces it lies on and its kind-specific
// keys, each key on the surfaces where it applies. The loader, the printer
// and the messages read it; model/path_kinds.cpp builds the geometry.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/surface_kinds.hpp"

namespace rollspin::scene {

enum class PathKind { Line, Circle, Parallel, Meridian, Helix, Loxodrome, Geodesic, Uv, Points, Clothoid };

// Which surfaces a path kind lies on.
enum class LiesOn { Plane, Revolution, Curved, Cylinder, Sphere, Any };

struct PathKey {
  std::string key;
  std::vector<SurfaceKind> on;  // empty: on every surface the path lies on
};

struct PathKindRow {
  PathKind kind;
  std::string_view name;
  LiesOn liesOn;
  std::vector<PathKey> keys;
};

[[nodiscard]] std::span<const PathKindRow> pathKinds();
[[nodiscard]] const PathKindRow& pathKindRow(PathKind kind);
[[nodiscard]] bool liesOn(PathKind path, SurfaceKind surface);
// "plane", "sphere, cylinder, torus or paraboloid", …: for messages.
[[nodiscard]] std::string describe(LiesOn where);
// Every kind-specific path key, in the table's order (no duplicates).
[[nodiscard]] const std::vector<std::string>& allPathKeys();

}  // namespace rollspin::scene
