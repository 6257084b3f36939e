#include "model/surface_kinds.hpp"

#include <array>
#include <cassert>
#include <cmath>
#include <functional>
#include <numbers>

#include "geometry/surfaces.hpp"

namespace rollspin::model {

namespace {

using geometry::Vec2;
using geometry::Vec3;
using Spec = scene::SurfaceSpec;

geometry::Side sideOf(const Spec& s) {
  return s.side == scene::SurfaceSide::Outside ? geometry::Side::Outside : geometry::Side::Inside;
}
bool above(const Spec& s) { return s.side == scene::SurfaceSide::Outside; }
// Most surfaces start a geodesic at their parameters (0, 0).
Vec3 atOrigin(const Spec&, const geometry::Surface& surface) { return surface.position(Vec2(0.0, 0.0)); }

struct SurfaceFactory {
  scene::SurfaceKind kind;
  std::function<std::shared_ptr<const geometry::Surface>(const scene::SceneSpec&)> build;
  std::function<Vec3(const Spec&, const geometry::Surface&)> geodesicStart;
};

const std::vector<SurfaceFactory>& factories() {
  using K = scene::SurfaceKind;
  static const std::vector<SurfaceFactory> rows{
      {K::Plane,
       [](const scene::SceneSpec& sc) { return std::make_shared<const geometry::Plane>(toVec(sc.surface.normal)); },
       atOrigin},
      {K::Sphere,
       [](const scene::SceneSpec& sc) {
         return std::make_shared<const geometry::Sphere>(sc.surface.radius, sideOf(sc.surface));
       },
       [](const Spec& s, const geometry::Surface&) {
         return Vec3(s.radius * Vec3(std::sin(radians(60)), 0.0, std::cos(radians(60))));
       }},
      {K::Cylinder,
       [](const scene::SceneSpec& sc) {
         return std::make_shared<const geometry::Cylinder>(sc.surface.radius, toVec(sc.surface.axis), sideOf(sc.surface));
       },
       atOrigin},
      {K::Torus,
       [](const scene::SceneSpec& sc) {
         return std::make_shared<const geometry::Torus>(sc.surface.majorRadius, sc.surface.minorRadius,
                                                        sideOf(sc.surface));
       },
       [](const Spec& s, const geometry::Surface&) { return Vec3(s.majorRadius + s.minorRadius, 0.0, 0.0); }},
      {K::Paraboloid,
       [](const scene::SceneSpec& sc) {
         return geometry::HeightField::quadric(sc.surface.a, sc.surface.b, false, above(sc.surface));
       },
       atOrigin},
      {K::Saddle,
       [](const scene::SceneSpec& sc) {
         return geometry::HeightField::quadric(sc.surface.a, sc.surface.b, true, above(sc.surface));
       },
       atOrigin},
      {K::Height,
       [](const scene::SceneSpec& sc) {
         return geometry::HeightField::fromExpression(compileExpression(sc, "surface.z", sc.surface.z, {"x", "y"}),
                                                      above(sc.surface));
       },
       atOrigin},
  };
  return rows;
}

const SurfaceFactory& factoryOf(scene::SurfaceKind kind) {
  for (const auto& row : factories())
    if (row.kind == kind) return row;
  assert(false && "every SurfaceKind has a factory");
  return factories().front();
}

}  // namespace

std::shared_ptr<const geometry::Expression> compileExpression(const scene::SceneSpec& spec, const std::string& key,
                                                              const std::string& text,
                                                              std::vector<std::string> variables) {
  try {
    return std::make_shared<const geometry::Expression>(text, std::move(variables));
  } catch (const geometry::ExpressionError& e) {
    SourceLoc loc = spec.where(key);
    if (loc.line > 0) loc.column += 1 + e.position();
    throw badInput(loc, "{}: cannot parse \"{}\" at character {}: {}", key, text, e.position() + 1, e.what());
  }
}

std::shared_ptr<const geometry::Surface> buildSurface(const scene::SceneSpec& spec) {
  return factoryOf(spec.surface.kind).build(spec);
}

Vec3 defaultGeodesicStart(const scene::SceneSpec& spec, const geometry::Surface& surface) {
  return factoryOf(spec.surface.kind).geodesicStart(spec.surface, surface);
}

}  // namespace rollspin::model
