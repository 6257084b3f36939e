#include "scene/scene_spec.hpp"

namespace rollspin::scene {

SourceLoc SceneSpec::where(const std::string& key) const {
  if (auto it = locations.find(key); it != locations.end()) return it->second;
  return SourceLoc{sourceFile.empty() ? std::string("<scene>") : sourceFile};
}

std::string toString(SurfaceKind k) {
  switch (k) {
    case SurfaceKind::Plane: return "plane";
    case SurfaceKind::Sphere: return "sphere";
    case SurfaceKind::Cylinder: return "cylinder";
    case SurfaceKind::Torus: return "torus";
    case SurfaceKind::Paraboloid: return "paraboloid";
    case SurfaceKind::Saddle: return "saddle";
    case SurfaceKind::Height: return "height";
  }
  return "?";
}

std::string toString(PathKind k) {
  switch (k) {
    case PathKind::Line: return "line";
    case PathKind::Circle: return "circle";
    case PathKind::Parallel: return "parallel";
    case PathKind::Meridian: return "meridian";
    case PathKind::Helix: return "helix";
    case PathKind::Loxodrome: return "loxodrome";
    case PathKind::Geodesic: return "geodesic";
    case PathKind::Uv: return "uv";
    case PathKind::Points: return "points";
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
