#include "app/scene_model.hpp"

#include "core/stage_log.hpp"
#include "scene/scene_loader.hpp"

#include <numbers>

#include "app/surface_model.hpp"
#include "geometry/analytic_paths.hpp"
#include "geometry/clothoid_path.hpp"
#include "spin/field.hpp"

namespace rollspin::app {

namespace {
geometry::Vec3 toVec(const scene::Vec3& v) { return {v[0], v[1], v[2]}; }
}  // namespace

RollingModel buildModel(const scene::SceneSpec& spec) {
  if (!isAnalyticScene(spec)) return buildSurfaceModel(spec);  // curved surfaces, any curve (surface_model.cpp)
  RollingModel model;
  model.ballRadius = spec.ball.radius;
  const double R = model.ballRadius;

  if (spec.surface.kind == scene::SurfaceKind::Plane) {
    auto plane = std::make_shared<const geometry::Plane>(toVec(spec.surface.normal));
    model.surface = plane;
    const geometry::Vec3 e1 = spec.path.directionVector ? toVec(*spec.path.directionVector)
                                                        : geometry::defaultTangentFor(plane->normal());
    switch (spec.path.kind) {
      case scene::PathKind::Line:
        model.path = std::make_unique<geometry::PlaneLinePath>(plane, geometry::Vec3::Zero(), e1, spec.path.length);
        break;
      case scene::PathKind::Clothoid:
        model.path = std::make_unique<geometry::PlaneClothoidPath>(plane, geometry::Vec3::Zero(), e1,
                                                                   spec.path.curvatureStart, spec.path.curvatureRate,
                                                                   spec.path.length);
        break;
      case scene::PathKind::Circle: {
        double radius = spec.path.radius;
        if (spec.plate) {
          // Brockett's plate translates on a circle of radius R1 while
          // touching the ball's top. The rolling constraint fixes the top
          // point's velocity relative to the contact point's; on a plane the
          // ratio is 2, so the contact circle has radius R1 / ratio.
          geometry::DarbouxSample probe;  // any contact frame on this plane
          probe.normal = plane->normal();
          probe.tangent = e1;
          probe.tangentNormal = probe.normal.cross(probe.tangent);
          PlateModel plate;
          plate.radius = spec.plate->radius;
          plate.contactSpeedRatio = spin::topPointVelocity(probe, R).norm();
          radius = plate.radius / plate.contactSpeedRatio;
          model.plate = plate;
        }
        model.path = std::make_unique<geometry::PlaneCirclePath>(plane, geometry::Vec3::Zero(), e1, radius,
                                                                 spec.path.turns, spec.path.counterClockwise);
        if (model.plate) model.plate->initialTopPoint = model.path->point(0.0) + 2.0 * R * plane->normal();
        break;
      }
      default: break;  // not on a plane: isAnalyticScene sent it to buildSurfaceModel
    }
  } else {
    auto sphere = std::make_shared<const geometry::Sphere>(
        spec.surface.radius,
        spec.surface.side == scene::SurfaceSide::Outside ? geometry::Side::Outside : geometry::Side::Inside);
    model.surface = sphere;
    model.path = std::make_unique<geometry::SphereParallelPath>(
        sphere, spec.path.colatitudeDeg * std::numbers::pi / 180.0, spec.path.turns, spec.path.counterClockwise);
  }
  return model;
}

scene::SceneSpec loadScene(const std::string& file, const std::vector<std::string>& overrides) {
  StageLog::instance().record("scene");
  return scene::loadSceneFile(file, overrides);
}

RollingModel buildSceneModel(const scene::SceneSpec& spec) {
  StageLog::instance().record("model");
  return buildModel(spec);
}

}  // namespace rollspin::app
