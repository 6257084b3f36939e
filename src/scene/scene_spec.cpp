#include "scene/scene_spec.hpp"

namespace rollspin::scene {

SourceLoc SceneSpec::where(const std::string& key) const {
  if (auto it = locations.find(key); it != locations.end()) return it->second;
  return SourceLoc{sourceFile.empty() ? std::string("<scene>") : sourceFile};
}

std::string toString(SurfaceKind k) { return k == SurfaceKind::Plane ? "plane" : "sphere"; }

std::string toString(PathKind k) {
  switch (k) {
    case PathKind::Line: return "line";
    case PathKind::Circle: return "circle";
    case PathKind::Parallel: return "parallel";
  }
  return "?";
}

}  // namespace rollspin::scene
