#include "scene/surface_kinds.hpp"

#include <algorithm>
#include <cassert>

#include "scene/path_kinds.hpp"

namespace rollspin::scene {

namespace {
SurfaceKindRow kindRow(std::string_view name, std::vector<std::string> keys, bool ofRevolution, bool heightField,
                       PathKind defaultPath) {
  return {SurfaceKind{name}, name, std::move(keys), ofRevolution, heightField, defaultPath};
}

const std::vector<SurfaceKindRow>& surfaceTable() {
  static const std::vector<SurfaceKindRow> rows{
      kindRow("plane", {"normal"}, false, false, PathKind::Circle),
      kindRow("sphere", {"radius", "side"}, true, false, PathKind::Parallel),
      kindRow("cylinder", {"radius", "side", "axis"}, true, false, PathKind::Parallel),
      kindRow("torus", {"side", "major_radius", "minor_radius"}, true, false, PathKind::Parallel),
      kindRow("paraboloid", {"side", "a", "b"}, true, true, PathKind::Parallel),
      kindRow("saddle", {"side", "a", "b"}, false, true, PathKind::Meridian),
      kindRow("height", {"side", "z"}, false, true, PathKind::Meridian),
  };
  return rows;
}
}  // namespace

std::span<const SurfaceKindRow> surfaceKinds() { return surfaceTable(); }

const SurfaceKindRow& surfaceKindRow(SurfaceKind kind) {
  for (const auto& row : surfaceTable())
    if (row.kind == kind) return row;
  assert(false && "every SurfaceKind has a row");
  return surfaceTable().front();
}

const std::vector<std::string>& allSurfaceKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> out;
    for (const auto& row : surfaceTable())
      for (const auto& key : row.keys)
        if (std::find(out.begin(), out.end(), key) == out.end()) out.push_back(key);
    return out;
  }();
  return keys;
}

}  // namespace rollspin::scene
