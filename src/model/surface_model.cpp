#include "model/surface_model.hpp"

#include <numbers>

#include "geometry/surface_paths.hpp"

namespace rollspin::model {

namespace {

using geometry::Vec2;
using geometry::Vec3;
constexpr double kDeg = std::numbers::pi / 180.0;

Vec3 toVec(const scene::Vec3& v) { return {v[0], v[1], v[2]}; }

geometry::Side sideOf(const scene::SurfaceSpec& s) {
  return s.side == scene::SurfaceSide::Outside ? geometry::Side::Outside : geometry::Side::Inside;
}

// Parses an expression; a parse error points into the TOML string itself
// (column of the opening quote + 1 + position) when the key came from a file.
std::shared_ptr<const geometry::Expression> compile(const scene::SceneSpec& spec, const std::string& key,
                                                    const std::string& text, std::vector<std::string> variables) {
  try {
    return std::make_shared<const geometry::Expression>(text, std::move(variables));
  } catch (const geometry::ExpressionError& e) {
    SourceLoc loc = spec.where(key);
    if (loc.line > 0) loc.column += 1 + e.position();
    throw badInput(loc, "{}: cannot parse \"{}\" at character {}: {}", key, text, e.position() + 1, e.what());
  }
}

std::shared_ptr<const geometry::Surface> buildSurface(const scene::SceneSpec& spec) {
  const scene::SurfaceSpec& s = spec.surface;
  const bool above = s.side == scene::SurfaceSide::Outside;
  switch (s.kind) {
    case scene::SurfaceKind::Plane: return std::make_shared<const geometry::Plane>(toVec(s.normal));
    case scene::SurfaceKind::Sphere: return std::make_shared<const geometry::Sphere>(s.radius, sideOf(s));
    case scene::SurfaceKind::Cylinder:
      return std::make_shared<const geometry::Cylinder>(s.radius, toVec(s.axis), sideOf(s));
    case scene::SurfaceKind::Torus:
      return std::make_shared<const geometry::Torus>(s.majorRadius, s.minorRadius, sideOf(s));
    case scene::SurfaceKind::Paraboloid: return geometry::HeightField::quadric(s.a, s.b, false, above);
    case scene::SurfaceKind::Saddle: return geometry::HeightField::quadric(s.a, s.b, true, above);
    case scene::SurfaceKind::Height:
      return geometry::HeightField::fromExpression(compile(spec, "surface.z", s.z, {"x", "y"}), above);
  }
  return nullptr;
}

// A point on the surface to start a geodesic from when the scene gives none.
Vec3 defaultStart(const scene::SceneSpec& spec, const geometry::Surface& surface) {
  const scene::SurfaceSpec& s = spec.surface;
  switch (s.kind) {
    case scene::SurfaceKind::Sphere: return s.radius * Vec3(std::sin(60 * kDeg), 0.0, std::cos(60 * kDeg));
    case scene::SurfaceKind::Cylinder: return surface.position(Vec2(0.0, 0.0));
    case scene::SurfaceKind::Torus: return {s.majorRadius + s.minorRadius, 0.0, 0.0};
    default: return surface.position(Vec2(0.0, 0.0));
  }
}

Vec2 parametersOf(const scene::SceneSpec& spec, const geometry::Surface& surface, const Vec3& point,
                  const std::string& key) {
  const auto uv = surface.parametersOf(point);
  if (!uv) throw badInput(spec.where(key), "{}: the point ({}, {}, {}) has no surface parameters here ({})", key,
                          point.x(), point.y(), point.z(), surface.parameterNames());
  return *uv;
}

std::unique_ptr<geometry::SurfaceCurvePath> buildPath(const scene::SceneSpec& spec,
                                                      const std::shared_ptr<const geometry::Surface>& surface) {
  using scene::PathKind;
  using scene::SurfaceKind;
  const scene::PathSpec& p = spec.path;
  const SurfaceKind sk = spec.surface.kind;
  auto sphere = std::dynamic_pointer_cast<const geometry::Sphere>(surface);
  auto cylinder = std::dynamic_pointer_cast<const geometry::Cylinder>(surface);
  auto torus = std::dynamic_pointer_cast<const geometry::Torus>(surface);
  auto field = std::dynamic_pointer_cast<const geometry::HeightField>(surface);
  switch (p.kind) {
    case PathKind::Parallel:
      if (cylinder) return geometry::cylinderParallel(cylinder, p.height, p.turns, p.counterClockwise);
      if (torus) return geometry::torusParallel(torus, p.tubeAngleDeg * kDeg, p.turns, p.counterClockwise);
      if (field) return geometry::heightFieldParallel(field, p.radius, p.turns, p.counterClockwise);
      break;
    case PathKind::Meridian:
      if (sphere)
        return geometry::sphereMeridian(sphere, p.azimuthDeg * kDeg, p.colatitudeStartDeg * kDeg,
                                        p.colatitudeEndDeg * kDeg);
      if (torus)
        return geometry::torusMeridian(torus, p.azimuthDeg * kDeg, p.tubeAngleDeg * kDeg, p.turns,
                                       p.counterClockwise);
      if (cylinder) return geometry::cylinderMeridian(cylinder, p.azimuthDeg * kDeg, p.height, p.length);
      if (field) return geometry::heightFieldMeridian(field, p.azimuthDeg * kDeg, p.length);
      break;
    case PathKind::Helix:
      if (cylinder)
        return geometry::cylinderHelix(cylinder, p.pitchAngleDeg * kDeg, p.height, p.turns, p.counterClockwise);
      break;
    case PathKind::Loxodrome:
      if (sphere)
        return geometry::sphereLoxodrome(sphere, p.headingDeg * kDeg, p.azimuthDeg * kDeg,
                                         p.colatitudeStartDeg * kDeg, p.colatitudeEndDeg * kDeg);
      break;
    case PathKind::Geodesic: {
      const Vec3 start = p.startPoint ? toVec(*p.startPoint) : defaultStart(spec, *surface);
      const Vec2 uv = parametersOf(spec, *surface, start, "path.start_point");
      Vec3 direction = p.directionVector ? toVec(*p.directionVector) : Vec3(0.0, 1.0, 0.0);
      const Vec3 n = surface->normal(uv);
      if (!p.directionVector && std::abs(direction.dot(n)) > 0.99) direction = Vec3(1.0, 0.0, 0.0);
      if ((direction - direction.dot(n) * n).norm() < 1e-9)
        throw badInput(spec.where("path.direction_vector"),
                       "path.direction_vector: perpendicular to the surface at the start point; expected a "
                       "direction with a tangential part");
      return geometry::geodesicPath(surface, uv, direction, p.length);
    }
    case PathKind::Uv:
      return geometry::uvExpressionPath(surface, compile(spec, "path.u", p.u, {"t"}),
                                        compile(spec, "path.v", p.v, {"t"}), p.tStart, p.tEnd);
    case PathKind::Points: {
      std::vector<Vec2> uv;
      for (const auto& q : p.points)
        uv.push_back(q.size() == 2 ? Vec2(q[0], q[1])
                                   : parametersOf(spec, *surface, Vec3(q[0], q[1], q[2]), "path.points"));
      return geometry::pointsPath(surface, uv, p.closed,
                                  p.interpolation == "polyline" ? geometry::PointsInterpolation::Polyline
                                                                : geometry::PointsInterpolation::CubicSpline,
                                  p.cornerRadius);
    }
    case PathKind::Line:
    case PathKind::Circle:
    case PathKind::Clothoid: break;  // plane paths, built by buildModel
  }
  throw badInput(spec.where("path.kind"), "path.kind: a {} path is not available on a {}", scene::toString(p.kind),
                 scene::toString(sk));
}

// The scene key a geometry error is best blamed on.
std::string keyForPathError(const scene::SceneSpec& spec) {
  switch (spec.path.kind) {
    case scene::PathKind::Points: return "path.points";
    case scene::PathKind::Uv: return "path.u";
    case scene::PathKind::Geodesic: return spec.locations.contains("path.length") ? "path.length" : "path.kind";
    default: return "path.kind";
  }
}

}  // namespace

bool isAnalyticScene(const scene::SceneSpec& spec) {
  const auto sk = spec.surface.kind;
  const auto pk = spec.path.kind;
  return (sk == scene::SurfaceKind::Plane &&
          (pk == scene::PathKind::Line || pk == scene::PathKind::Circle || pk == scene::PathKind::Clothoid)) ||
         (sk == scene::SurfaceKind::Sphere && pk == scene::PathKind::Parallel);
}

RollingModel buildSurfaceModel(const scene::SceneSpec& spec) {
  RollingModel model;
  model.ballRadius = spec.ball.radius;
  model.surface = buildSurface(spec);
  std::unique_ptr<geometry::SurfaceCurvePath> path;
  try {
    path = buildPath(spec, model.surface);
  } catch (const geometry::GeometryError& e) {
    const std::string key = keyForPathError(spec);
    throw badInput(spec.where(key), "{}: {}", key, e.what());
  }
  const geometry::ContactCheck check = geometry::checkSingleContact(*path, model.ballRadius);
  if (!check.ok) throw badInput(spec.where("ball.radius"), "ball.radius: {}", check.reason);
  model.path = std::move(path);
  return model;
}

}  // namespace rollspin::model
