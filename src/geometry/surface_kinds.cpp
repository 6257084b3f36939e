#include "geometry/surface_kinds.hpp"

#include <fmt/format.h>
#include <cmath>
#include <numbers>

#include "geometry/analytic_paths.hpp"
#include "geometry/clothoid_path.hpp"
#include "geometry/surface_paths.hpp"
#include "geometry/surfaces.hpp"

// Rows name only the members they set (designated initialisers); the others
// keep their defaults, which gcc 12's -Wextra would flag member by member.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace rollspin::geometry {

namespace {

Vec3 toVec(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }

// The keys several kinds share, declared once.
ParamDecl sideKey() {
  return {.key = "side",
          .type = ParamType::Choice,
          .defaultValue = std::string("outside"),
          .units = "",
          .meaning = "the ball's side: away from the axis or centre (outside) or towards it (inside)",
          .choices = {"outside", "inside"}};
}
ParamDecl heightSideKey() {
  return {.key = "side",
          .type = ParamType::Choice,
          .defaultValue = std::string("above"),
          .units = "",
          .meaning = "the ball's side of the height field z = f(x, y)",
          .choices = {"above", "below"}};
}
ParamDecl positiveKey(std::string key, double value, std::string meaning, std::string noun = "a value") {
  return {.key = std::move(key),
          .type = ParamType::Number,
          .defaultValue = value,
          .units = "length",
          .meaning = std::move(meaning),
          .lowerBound = 0.0,
          .noun = std::move(noun)};
}
ParamDecl directionKey(std::string key, std::string meaning) {
  return {.key = std::move(key),
          .type = ParamType::Direction,
          .defaultValue = std::array<double, 3>{0.0, 0.0, 1.0},
          .units = "",
          .meaning = std::move(meaning)};
}

Side sideOf(const ParamSet& p) { return p.text("side") == "outside" ? Side::Outside : Side::Inside; }
bool above(const ParamSet& p) { return p.text("side") == "above"; }

// A ball inside a closed surface must be smaller than the surface's radius
// there. Blames ball.radius when the scene gave it, else the surface's key.
std::optional<SurfaceProblem> mustFit(double R, double limit, const std::string& what, const std::string& key) {
  if (R < limit) return std::nullopt;
  return SurfaceProblem{
      {"ball.radius", "surface." + key},
      fmt::format("a ball of radius {} does not fit inside {} (needs ball.radius < {})", R, what, limit)};
}

template <typename Concrete>
std::shared_ptr<const Concrete> as(const std::shared_ptr<const Surface>& surface) {
  return std::static_pointer_cast<const Concrete>(surface);  // the row's own create() built it
}

const std::vector<SurfaceKindRow>& rows() {
  static const std::vector<SurfaceKindRow> table{
      {.name = "plane",
       .params = {directionKey("normal", "unit normal on the ball's side (a plane through the origin)")},
       .ofRevolution = false,
       .defaultPath = "circle",
       .create = [](const ParamSet& p) { return std::make_shared<const Plane>(toVec(p.vector("normal"))); },
       .closedForm = [](const std::shared_ptr<const Surface>& s, ClosedFormCurve curve,
                        const ClosedFormRequest& c) -> std::unique_ptr<ContactPath> {
         switch (curve) {
           case ClosedFormCurve::Line:
             return std::make_unique<PlaneLinePath>(as<Plane>(s), c.start, c.direction, c.length);
           case ClosedFormCurve::Circle:
             return std::make_unique<PlaneCirclePath>(as<Plane>(s), c.start, c.direction, c.radius, c.turns,
                                                      c.counterClockwise);
           case ClosedFormCurve::Clothoid:
             return std::make_unique<PlaneClothoidPath>(as<Plane>(s), c.start, c.direction, c.curvatureStart,
                                                        c.curvatureRate, c.length);
           case ClosedFormCurve::Parallel: return nullptr;
         }
         return nullptr;
       }},
      {.name = "sphere",
       .params = {positiveKey("radius", 3.0, "the sphere's radius r (centred at the origin)", "a radius"), sideKey()},
       .ofRevolution = true,
       .defaultPath = "parallel",
       .create = [](const ParamSet& p) { return std::make_shared<const Sphere>(p.number("radius"), sideOf(p)); },
       .check = [](const ParamSet& p, double R) -> std::optional<SurfaceProblem> {
         if (sideOf(p) != Side::Inside) return std::nullopt;
         const double r = p.number("radius");
         return mustFit(R, r, fmt::format("a sphere of radius {}", r), "radius");
       },
       .curve = [](const std::shared_ptr<const Surface>& s, CurveFamily family,
                   const CurveRequest& c) -> std::unique_ptr<SurfaceCurvePath> {
         if (family == CurveFamily::Meridian)
           return sphereMeridian(as<Sphere>(s), c.azimuth, c.colatitudeStart, c.colatitudeEnd);
         if (family == CurveFamily::Loxodrome)
           return sphereLoxodrome(as<Sphere>(s), c.heading, c.azimuth, c.colatitudeStart, c.colatitudeEnd);
         return nullptr;
       },
       .closedForm = [](const std::shared_ptr<const Surface>& s, ClosedFormCurve curve,
                        const ClosedFormRequest& c) -> std::unique_ptr<ContactPath> {
         if (curve != ClosedFormCurve::Parallel) return nullptr;
         return std::make_unique<SphereParallelPath>(as<Sphere>(s), c.colatitude, c.turns, c.counterClockwise,
                                                     c.startAzimuth);
       }},
      {.name = "cylinder",
       .params = {positiveKey("radius", 3.0, "the cylinder's radius a", "a radius"), sideKey(),
                  directionKey("axis", "direction of the axis through the origin")},
       .ofRevolution = true,
       .defaultPath = "parallel",
       .create =
           [](const ParamSet& p) {
             return std::make_shared<const Cylinder>(p.number("radius"), toVec(p.vector("axis")), sideOf(p));
           },
       .check = [](const ParamSet& p, double R) -> std::optional<SurfaceProblem> {
         if (sideOf(p) != Side::Inside) return std::nullopt;
         const double r = p.number("radius");
         return mustFit(R, r, fmt::format("a cylinder of radius {}", r), "radius");
       },
       .curve = [](const std::shared_ptr<const Surface>& s, CurveFamily family,
                   const CurveRequest& c) -> std::unique_ptr<SurfaceCurvePath> {
         switch (family) {
           case CurveFamily::Parallel:
             return cylinderParallel(as<Cylinder>(s), c.height, c.turns, c.counterClockwise, c.startAzimuth);
           case CurveFamily::Meridian: return cylinderMeridian(as<Cylinder>(s), c.azimuth, c.height, c.length);
           case CurveFamily::Helix:
             return cylinderHelix(as<Cylinder>(s), c.pitchAngle, c.height, c.turns, c.counterClockwise);
           case CurveFamily::Loxodrome: return nullptr;
         }
         return nullptr;
       }},
      {.name = "torus",
       .params = {sideKey(), positiveKey("major_radius", 3.0, "distance A from the z axis to the tube's centre"),
                  positiveKey("minor_radius", 1.0, "the tube's radius a (a ring torus: a < A)")},
       .ofRevolution = true,
       .defaultPath = "parallel",
       .create =
           [](const ParamSet& p) {
             return std::make_shared<const Torus>(p.number("major_radius"), p.number("minor_radius"), sideOf(p));
           },
       .check = [](const ParamSet& p, double R) -> std::optional<SurfaceProblem> {
         const double A = p.number("major_radius"), a = p.number("minor_radius");
         if (!(a < A))
           return SurfaceProblem{
               {"surface.minor_radius", "surface.major_radius"},
               fmt::format("expected minor_radius < major_radius (a ring torus), got {} and {}", a, A)};
         if (sideOf(p) != Side::Inside) return std::nullopt;
         return mustFit(R, a, fmt::format("a torus tube of radius {}", a), "minor_radius");
       },
       .curve = [](const std::shared_ptr<const Surface>& s, CurveFamily family,
                   const CurveRequest& c) -> std::unique_ptr<SurfaceCurvePath> {
         if (family == CurveFamily::Parallel)
           return torusParallel(as<Torus>(s), c.tubeAngle, c.turns, c.counterClockwise, c.startAzimuth);
         if (family == CurveFamily::Meridian)
           return torusMeridian(as<Torus>(s), c.azimuth, c.tubeAngle, c.turns, c.counterClockwise);
         return nullptr;
       }},
      {.name = "paraboloid",
       .params = {heightSideKey(), positiveKey("a", 4.0, "z = (x²/a + y²/b)/2: curvature radius along x"),
                  positiveKey("b", 4.0, "z = (x²/a + y²/b)/2: curvature radius along y")},
       .ofRevolution = true,
       .defaultPath = "parallel",
       .create = [](const ParamSet& p) { return HeightField::quadric(p.number("a"), p.number("b"), false, above(p)); },
       .revolutionProblem = [](const ParamSet& p) -> std::optional<SurfaceProblem> {
         if (p.number("a") == p.number("b")) return std::nullopt;
         return SurfaceProblem{{"surface.a"},
                               fmt::format("a parallel needs a surface of revolution; this paraboloid has a = {} != "
                                           "b = {}",
                                           p.number("a"), p.number("b"))};
       },
       .parallelRadius = 2.0,
       .curve = [](const std::shared_ptr<const Surface>& s, CurveFamily family,
                   const CurveRequest& c) -> std::unique_ptr<SurfaceCurvePath> {
         if (family == CurveFamily::Parallel)
           return heightFieldParallel(as<HeightField>(s), c.radius, c.turns, c.counterClockwise, c.startAzimuth);
         if (family == CurveFamily::Meridian) return heightFieldMeridian(as<HeightField>(s), c.azimuth, c.length);
         return nullptr;
       }},
      {.name = "saddle",
       .params = {heightSideKey(), positiveKey("a", 4.0, "z = (x²/a − y²/b)/2: curvature radius along x"),
                  positiveKey("b", 4.0, "z = (x²/a − y²/b)/2: curvature radius along y")},
       .ofRevolution = false,
       .defaultPath = "meridian",
       .create = [](const ParamSet& p) { return HeightField::quadric(p.number("a"), p.number("b"), true, above(p)); },
       .curve = [](const std::shared_ptr<const Surface>& s, CurveFamily family,
                   const CurveRequest& c) -> std::unique_ptr<SurfaceCurvePath> {
         if (family == CurveFamily::Meridian) return heightFieldMeridian(as<HeightField>(s), c.azimuth, c.length);
         return nullptr;
       }},
      {.name = "height",
       .params = {heightSideKey(),
                  {.key = "z",
                   .type = ParamType::Expression,
                   .defaultValue = std::string("0"),
                   .units = "length",
                   .meaning = "the height z = f(x, y), a muparser formula",
                   .variables = {"x", "y"}}},
       .ofRevolution = false,
       .defaultPath = "meridian",
       .create =
           [](const ParamSet& p) {
             return HeightField::fromExpression(
                 std::make_shared<const Expression>(p.text("z"), std::vector<std::string>{"x", "y"}), above(p));
           },
       .curve = [](const std::shared_ptr<const Surface>& s, CurveFamily family,
                   const CurveRequest& c) -> std::unique_ptr<SurfaceCurvePath> {
         if (family == CurveFamily::Meridian) return heightFieldMeridian(as<HeightField>(s), c.azimuth, c.length);
         return nullptr;
       }},
  };
  return table;
}

}  // namespace

std::span<const SurfaceKindRow> surfaceKindTable() { return rows(); }

const SurfaceKindRow* findSurfaceKind(std::string_view name) {
  for (const auto& row : rows())
    if (row.name == name) return &row;
  return nullptr;
}

}  // namespace rollspin::geometry
