#include "model/rolling_model.hpp"

#include "core/stage_log.hpp"
#include "scene/scene_loader.hpp"

#include <numbers>

#include "geometry/joined_path.hpp"
#include "geometry/surface_kinds.hpp"
#include "model/surface_builder.hpp"
#include "model/surface_model.hpp"
#include "spin/field.hpp"

namespace rollspin::model {

namespace {

// Where a plane path starts: the origin along its own direction (a scene's
// [path], a storyboard's first segment), or a point and a heading (the
// previous segment's end).
struct Placement {
  geometry::Vec3 start = geometry::Vec3::Zero();
  std::optional<geometry::Vec3> heading;
};

RollingModel buildPathModel(const scene::SceneSpec& spec, const Placement& place) {
  if (!isAnalyticScene(spec)) return buildSurfaceModel(spec);  // curved surfaces, any curve (surface_model.cpp)
  RollingModel model;
  model.ballRadius = spec.ball.radius;
  const double R = model.ballRadius;

  // The closed-form paths are laid by the surface kind's own row.
  model.surface = buildSurface(spec);
  const geometry::SurfaceKindRow& kindRow = *scene::sceneSurfaceKind(spec.surface.kind).geometry;
  auto closedForm = [&](geometry::ClosedFormCurve curve, const geometry::ClosedFormRequest& request) {
    return kindRow.closedForm(model.surface, curve, request);
  };
  geometry::ClosedFormRequest c;
  c.turns = spec.path.turns;
  c.counterClockwise = spec.path.counterClockwise;
  c.length = spec.path.length;
  if (spec.surface.kind == scene::SurfaceKind::Plane) {
    const geometry::Vec3 n = model.surface->normalAt(geometry::Vec3::Zero());  // the plane's normal
    const geometry::Vec3 e1 = place.heading               ? *place.heading
                              : spec.path.directionVector ? toVec(*spec.path.directionVector)
                                                          : geometry::defaultTangentFor(n);
    c.start = place.start;
    c.direction = e1;
    switch (spec.path.kind) {
      case scene::PathKind::Line: model.path = closedForm(geometry::ClosedFormCurve::Line, c); break;
      case scene::PathKind::Clothoid:
        c.curvatureStart = spec.path.curvatureStart;
        c.curvatureRate = spec.path.curvatureRate;
        model.path = closedForm(geometry::ClosedFormCurve::Clothoid, c);
        break;
      case scene::PathKind::Circle: {
        double radius = spec.path.radius;
        if (spec.plate) {
          // Brockett's plate translates on a circle of radius R1 while
          // touching the ball's top. The rolling constraint fixes the top
          // point's velocity relative to the contact point's; on a plane the
          // ratio is 2, so the contact circle has radius R1 / ratio.
          geometry::DarbouxSample probe;  // any contact frame on this plane
          probe.normal = n;
          probe.tangent = e1;
          probe.tangentNormal = probe.normal.cross(probe.tangent);
          PlateModel plate;
          plate.radius = spec.plate->radius;
          plate.contactSpeedRatio = spin::topPointVelocity(probe, R).norm();
          radius = plate.radius / plate.contactSpeedRatio;
          model.plate = plate;
        }
        c.radius = radius;
        if (place.heading) {
          // Start at the given point moving along the heading h: the circle
          // starts at centre + r e1 moving along σ n × e1, so e1 = σ h × n.
          const double sense = spec.path.counterClockwise ? 1.0 : -1.0;
          const geometry::Vec3 radial = sense * place.heading->cross(n);
          c.start = place.start - radius * radial;
          c.direction = radial;
          model.path = closedForm(geometry::ClosedFormCurve::Circle, c);
          break;
        }
        c.start = geometry::Vec3::Zero();
        model.path = closedForm(geometry::ClosedFormCurve::Circle, c);
        if (model.plate) model.plate->initialTopPoint = model.path->point(0.0) + 2.0 * R * n;
        break;
      }
      default: break;  // not on a plane: isAnalyticScene sent it to buildSurfaceModel
    }
  } else {
    c.colatitude = spec.path.colatitudeDeg * std::numbers::pi / 180.0;
    c.startAzimuth = spec.path.startAzimuthDeg * std::numbers::pi / 180.0;
    model.path = closedForm(geometry::ClosedFormCurve::Parallel, c);
  }
  return model;
}

// Segment `index` as a scene of its own: its path in place of [path], and
// its keys' locations under the names the path builders use ("path.…").
scene::SceneSpec segmentScene(const scene::SceneSpec& spec, std::size_t index) {
  scene::SceneSpec sub = spec;
  sub.segments.clear();
  sub.path = *spec.segments[index].path;
  sub.surface = spec.surfaceOf(index);
  // The segment's path keys, and its surface's when a segment gave it, under
  // the names the builders use.
  auto rename = [&](const std::string& from, const std::string& to) {
    if (from == to) return;
    for (auto it = sub.locations.begin(); it != sub.locations.end();)
      it = it->first.rfind(to, 0) == 0 ? sub.locations.erase(it) : std::next(it);
    for (const auto& [key, loc] : spec.locations)
      if (key.rfind(from, 0) == 0) sub.locations[to + key.substr(from.size())] = loc;
  };
  rename(scene::SceneSpec::segmentKey(index) + ".path", "path");
  rename(spec.surfaceKeyOf(index), "surface");
  return sub;
}

// Errors from a segment's path name the segment's own key; from its
// surface, the table that gave it.
Error forSegment(const Error& e, const scene::SceneSpec& spec, std::size_t index) {
  const std::string prefix = scene::SceneSpec::segmentKey(index);
  const std::string& m = e.message();
  if (m.rfind("path", 0) == 0) return Error(e.kind(), e.where(), prefix + "." + m);
  if (m.rfind("surface", 0) == 0) return Error(e.kind(), e.where(), spec.surfaceKeyOf(index) + m.substr(7));
  return Error(e.kind(), e.where(), prefix + ": " + m);
}

RollingModel buildStoryboardModel(const scene::SceneSpec& spec) {
  RollingModel model;
  model.ballRadius = spec.ball.radius;
  std::vector<std::unique_ptr<geometry::ContactPath>> pieces;
  std::optional<geometry::DarbouxSample> end;  // where the previous motion ended
  std::size_t endSegment = 0;
  double s = 0.0;
  for (std::size_t i = 0; i < spec.segments.size(); ++i) {
    const std::size_t surface = spec.surfaceIndexOf(i);
    if (!spec.segments[i].path) {
      model.segments.push_back({s, s, surface});
      continue;
    }
    // A new surface: the path starts where its own keys say, no join.
    if (surface + 1 > model.surfaces.size() && !model.surfaces.empty()) end.reset();
    scene::SceneSpec sub = segmentScene(spec, i);
    const scene::PathKind kind = sub.path.kind;
    const bool onPlane = sub.surface.kind == scene::SurfaceKind::Plane;
    const bool continues = onPlane && (kind == scene::PathKind::Line || kind == scene::PathKind::Circle ||
                                       kind == scene::PathKind::Clothoid);
    Placement place;
    if (end && continues) place = {end->point, end->tangent};
    if (end && kind == scene::PathKind::Geodesic) {
      if (!sub.path.startPoint) sub.path.startPoint = scene::Vec3{end->point.x(), end->point.y(), end->point.z()};
      if (!sub.path.directionVector)
        sub.path.directionVector = scene::Vec3{end->tangent.x(), end->tangent.y(), end->tangent.z()};
    }
    RollingModel part;
    try {
      part = buildPathModel(sub, place);
    } catch (const Error& e) {
      throw forSegment(e, spec, i);
    }
    if (end) {
      const geometry::Vec3 start = part.path->point(0.0);
      const double gap = (start - end->point).norm();
      if (!(gap <= kJoinTolerance * model.ballRadius)) {
        const std::string key = scene::SceneSpec::segmentKey(i) + ".path";
        throw badInput(spec.where(key),
                       "{}: starts at ({:.9g}, {:.9g}, {:.9g}), {:.3g} away from where {} ended ({:.9g}, {:.9g}, "
                       "{:.9g}); a {} path on a {} is placed by its own keys, so it must start where the previous "
                       "segment ended (within {:g} R)",
                       key, start.x(), start.y(), start.z(), gap, scene::SceneSpec::segmentKey(endSegment),
                       end->point.x(), end->point.y(), end->point.z(), scene::toString(kind),
                       scene::toString(sub.surface.kind), kJoinTolerance);
      }
    }
    const double length = part.path->length();
    end = part.path->at(length);
    endSegment = i;
    // ([surface] when no motion rolls on it: the first motion gave its own.)
    if (surface > model.surfaces.size()) model.surfaces.push_back(buildSurface(spec));
    if (surface + 1 > model.surfaces.size()) model.surfaces.push_back(part.surface);
    model.segments.push_back({s, s + length, surface});
    s += length;
    pieces.push_back(std::move(part.path));
  }
  if (pieces.empty())
    throw badInput(spec.where("segment"),
                   "segment: a storyboard needs at least one segment with a path (a motion); "
                   "all {} are holds",
                   spec.segments.size());
  model.surface = model.surfaces.front();
  model.path = std::make_unique<geometry::JoinedPath>(std::move(pieces));
  return model;
}

}  // namespace

RollingModel buildModel(const scene::SceneSpec& spec) {
  if (spec.isStoryboard()) return buildStoryboardModel(spec);
  RollingModel model = buildPathModel(spec, {});
  model.surfaces = {model.surface};
  return model;
}

scene::SceneSpec loadScene(const std::string& file, const std::vector<std::string>& overrides,
                           std::span<const scene::KeySetting> settings) {
  StageLog::instance().record("scene");
  return scene::loadSceneFile(file, overrides, settings);
}

RollingModel buildSceneModel(const scene::SceneSpec& spec) {
  StageLog::instance().record("model");
  return buildModel(spec);
}

}  // namespace rollspin::model
