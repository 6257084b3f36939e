// Surface kinds: the one table of what a scene's [surface] can be. Each row
// is a kind's name, its own keys (core/param_table.hpp: type, default, range,
// units, meaning), and the functions that build its Surface from those keys
// (pbrt-v4's Shape::Create(name, params, loc)), check them against the ball,
// and lay its named curves (parallel, meridian, helix, loxodrome) on it. The
// scene loader, the scene printer and model/ read only this table; a new kind
// is its geometry class plus one row in surface_kinds.cpp.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/param_table.hpp"
#include "geometry/surface.hpp"
#include "geometry/surface_curve.hpp"

namespace rollspin::geometry {

// The scene's placement keys of a named curve, in radians and lengths.
struct CurveRequest {
  double turns = 1.0;
  bool counterClockwise = true;
  double height = 0.0;                                // cylinder: start height along the axis
  double tubeAngle = 0.0;                             // torus: ψ
  double radius = 3.0;                                // height field of revolution: ρ of the parallel
  double azimuth = 0.0;                               // φ0
  double colatitudeStart = 0.0, colatitudeEnd = 0.0;  // sphere: θ0, θ1
  double length = 10.0;
  double pitchAngle = 0.0;    // helix: β
  double heading = 0.0;       // loxodrome: α
  double startAzimuth = 0.0;  // parallel: the azimuth it starts at
};
enum class CurveFamily { Parallel, Meridian, Helix, Loxodrome };

// The foundation's closed-form paths (analytic_paths.hpp, clothoid_path.hpp):
// a line, circle or clothoid on a plane, a parallel on a sphere.
enum class ClosedFormCurve { Line, Circle, Clothoid, Parallel };
struct ClosedFormRequest {
  Vec3 start = Vec3::Zero();       // line, clothoid: the start; circle: the centre
  Vec3 direction = Vec3::UnitX();  // line, clothoid: the start's tangent; circle: centre → start
  double length = 10.0;
  double radius = 3.0;  // circle
  double turns = 1.0;
  bool counterClockwise = true;
  double curvatureStart = 0.0, curvatureRate = 0.0;  // clothoid: κ_g = κ₀ + α s
  double colatitude = 0.0;                           // parallel: θ
  double startAzimuth = 0.0;                         // parallel: the azimuth it starts at
};

// A scene value that the kind refuses: the message, and the keys to blame
// (full keys, "surface.radius"); the loader names the first one the scene
// gave, else the last.
struct SurfaceProblem {
  std::vector<std::string> keys;
  std::string message;
};

struct SurfaceKindRow {
  std::string name;
  std::vector<ParamDecl> params;  // its own keys of [surface] (besides kind), in the order printed
  bool ofRevolution = false;      // parallels lie on it (the paraboloid: only when revolutionProblem is empty)
  std::string defaultPath;        // [path] without a kind: a path kind's name
  // The Surface; a formula that does not parse throws ExpressionError.
  std::function<std::shared_ptr<const Surface>(const ParamSet&)> create;
  // A value the kind refuses for a ball of radius R (empty: none).
  std::function<std::optional<SurfaceProblem>(const ParamSet&, double ballRadius)> check;
  // Why parallels do not lie on it after all (e.g. a paraboloid with a ≠ b); unset: never.
  std::function<std::optional<SurfaceProblem>(const ParamSet&)> revolutionProblem;
  std::optional<double> parallelRadius;  // a parallel's ρ when the path gives none (height fields)
  // A named curve on the surface that create() built; nullptr where the family has none here.
  std::function<std::unique_ptr<SurfaceCurvePath>(const std::shared_ptr<const Surface>&, CurveFamily,
                                                  const CurveRequest&)>
      curve;
  // A closed-form path on the surface that create() built; nullptr where the kind has none.
  std::function<std::unique_ptr<ContactPath>(const std::shared_ptr<const Surface>&, ClosedFormCurve,
                                             const ClosedFormRequest&)>
      closedForm;
};

[[nodiscard]] std::span<const SurfaceKindRow> surfaceKindTable();
// The row named `name`; nullptr when there is none.
[[nodiscard]] const SurfaceKindRow* findSurfaceKind(std::string_view name);

}  // namespace rollspin::geometry
