#include "scene/surface_kinds.hpp"

#include <algorithm>
#include <cassert>

#include "scene/path_kinds.hpp"

namespace rollspin::scene {

namespace {
PathKind pathKindNamed(std::string_view name) {
  for (const auto& row : pathKinds())
    if (row.name == name) return row.kind;
  assert(false && "a surface kind's default path is a path kind");
  return PathKind::Circle;
}

// geometry's rows, with their names as SurfaceKinds and their default paths as PathKinds.
const std::vector<SceneSurfaceKind>& surfaceTable() {
  static const std::vector<SceneSurfaceKind> rows = [] {
    std::vector<SceneSurfaceKind> out;
    for (const geometry::SurfaceKindRow& g : geometry::surfaceKindTable()) {
      std::vector<std::string> keys;
      for (const ParamDecl& d : g.params) keys.push_back(d.key);
      out.push_back({SurfaceKind{g.name}, g.name, std::move(keys), g.ofRevolution, pathKindNamed(g.defaultPath), &g});
    }
    return out;
  }();
  return rows;
}
}  // namespace

std::span<const SceneSurfaceKind> surfaceKinds() { return surfaceTable(); }

const SceneSurfaceKind& sceneSurfaceKind(SurfaceKind kind) {
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

const std::vector<ParamDecl>& surfaceKeyDecls(SurfaceKind kind) { return sceneSurfaceKind(kind).geometry->params; }

}  // namespace rollspin::scene
