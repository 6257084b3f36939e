#include "model/surface_model.hpp"

#include <cmath>
#include <numbers>

#include "geometry/surface_kinds.hpp"
#include "geometry/surface_paths.hpp"
#include "model/surface_builder.hpp"

namespace rollspin::model {

namespace {

using geometry::Vec2;
using geometry::Vec3;

Vec2 parametersOf(const scene::SceneSpec& spec, const geometry::Surface& surface, const Vec3& point,
                  const std::string& key) {
  const auto uv = surface.parametersOf(point);
  if (!uv)
    throw badInput(spec.where(key), "{}: the point ({}, {}, {}) has no surface parameters here ({})", key, point.x(),
                   point.y(), point.z(), surface.parameterNames());
  return *uv;
}

std::unique_ptr<geometry::SurfaceCurvePath> buildPath(const scene::SceneSpec& spec,
                                                      const std::shared_ptr<const geometry::Surface>& surface) {
  using scene::PathKind;
  const scene::PathSpec& p = spec.path;
  const scene::SurfaceKind sk = spec.surface.kind;
  // The named curves (parallel, meridian, helix, loxodrome) are laid by the
  // surface kind's own row; nullptr where the kind has no such curve.
  auto named = [&](geometry::CurveFamily family) {
    geometry::CurveRequest c;
    c.turns = p.turns;
    c.counterClockwise = p.counterClockwise;
    c.height = p.height;
    c.tubeAngle = radians(p.tubeAngleDeg);
    c.radius = p.radius;
    c.azimuth = radians(p.azimuthDeg);
    c.colatitudeStart = radians(p.colatitudeStartDeg);
    c.colatitudeEnd = radians(p.colatitudeEndDeg);
    c.length = p.length;
    c.pitchAngle = radians(p.pitchAngleDeg);
    c.heading = radians(p.headingDeg);
    c.startAzimuth = radians(p.startAzimuthDeg);
    const geometry::SurfaceKindRow& row = *scene::sceneSurfaceKind(sk).geometry;
    return row.curve ? row.curve(surface, family, c) : nullptr;
  };
  switch (p.kind) {
    case PathKind::Parallel:
      if (auto path = named(geometry::CurveFamily::Parallel)) return path;
      break;
    case PathKind::Meridian:
      if (auto path = named(geometry::CurveFamily::Meridian)) return path;
      break;
    case PathKind::Helix:
      if (auto path = named(geometry::CurveFamily::Helix)) return path;
      break;
    case PathKind::Loxodrome:
      if (auto path = named(geometry::CurveFamily::Loxodrome)) return path;
      break;
    case PathKind::Geodesic: {
      const Vec3 start = p.startPoint ? toVec(*p.startPoint) : surface->defaultStart();
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
      return geometry::uvExpressionPath(surface, compileExpression(spec, "path.u", p.u, {"t"}),
                                        compileExpression(spec, "path.v", p.v, {"t"}), p.tStart, p.tEnd);
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
  model.surface = buildSurface(spec);  // surface_kinds.cpp
  std::unique_ptr<geometry::SurfaceCurvePath> path;
  try {
    path = buildPath(spec, model.surface);
  } catch (const geometry::SurfaceUndefinedError& e) {
    // The surface's own formula has no value where the path goes: blame it
    // (surface.z at its line:col), with the point, not the path's keys.
    const std::string formula = surfaceFormulaKey(spec);
    if (formula.empty()) {
      const std::string key = keyForPathError(spec);
      throw badInput(spec.where(key), "{}: {}", key, e.what());
    }
    const std::string key = "surface." + formula;
    const std::string names = model.surface->parameterNames();  // "(x, y): the horizontal coordinates"
    throw badInput(
        spec.where(key),
        "{}: \"{}\" is undefined (not finite, or its slope is not) at {} = ({}, {}), "
        "where the path goes{}; the path must stay where the formula is defined",
        key, spec.surface.params.text(formula), names.substr(0, names.find(':')), geometry::describeNumber(e.at().x()),
        geometry::describeNumber(e.at().y()),
        std::isfinite(e.arcLength()) ? " (arc length ≈ " + geometry::describeNumber(e.arcLength()) + ")" : "");
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
