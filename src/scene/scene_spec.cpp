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

std::string toString(RenderLayout l) {
  switch (l) {
    case RenderLayout::SideBySide: return "side-by-side";
    case RenderLayout::Inset: return "inset";
    case RenderLayout::Ball: return "ball";
    case RenderLayout::Twin: return "twin";
  }
  return "?";
}

}  // namespace rollspin::scene
