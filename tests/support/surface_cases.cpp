#include "support/surface_cases.hpp"

#include "geometry/surface_paths.hpp"
#include "support/numbers.hpp"

namespace rollspin::test {

using namespace geometry;

namespace {
std::shared_ptr<const Expression> expr(const std::string& text, std::vector<std::string> vars) {
  return std::make_shared<const Expression>(text, std::move(vars));
}
std::vector<Vec2> loopAround(double cx, double cy, double a, double b) {
  return {{cx + a, cy}, {cx + 0.3 * a, cy + b}, {cx - 0.8 * a, cy + 0.6 * b}, {cx - a, cy - 0.4 * b}, {cx, cy - b}};
}
}  // namespace

std::vector<SurfaceCase> allSurfaceCases() {
  auto plane = std::make_shared<const Plane>(Vec3(1.0, -0.5, 2.0));
  auto sphereOut = std::make_shared<const Sphere>(3.0, Side::Outside);
  auto sphereIn = std::make_shared<const Sphere>(3.0, Side::Inside);
  auto cylOut = std::make_shared<const Cylinder>(2.0, Vec3(0.2, 0.1, 1.0), Side::Outside);
  auto cylIn = std::make_shared<const Cylinder>(2.0, Vec3(0.0, 0.0, 1.0), Side::Inside);
  auto torusOut = std::make_shared<const Torus>(4.0, 1.5, Side::Outside);
  auto torusIn = std::make_shared<const Torus>(4.0, 1.5, Side::Inside);
  std::shared_ptr<const HeightField> bowl = HeightField::quadric(3.0, 3.0, false, true);
  std::shared_ptr<const HeightField> dome = HeightField::quadric(2.0, 2.0, false, false);
  std::shared_ptr<const HeightField> saddle = HeightField::quadric(3.0, 2.0, true, true);
  std::shared_ptr<const HeightField> bumps = HeightField::fromExpression(expr("0.3*sin(x)*cos(y)", {"x", "y"}), true);
  const double deg = kPi / 180.0;
  using P = std::unique_ptr<ContactPath>;
  return {
      // plane
      {"plane uv",
       [=]() -> P {
         return uvExpressionPath(plane, expr("2*cos(t)+0.5*cos(3*t)", {"t"}), expr("1.5*sin(t)", {"t"}), 0.0, 2 * kPi);
       },
       1.0},
      {"plane spline closed",
       [=]() -> P { return pointsPath(plane, loopAround(0, 0, 3, 2), true, PointsInterpolation::CubicSpline, 0); },
       1.0},
      {"plane spline open",
       [=]() -> P {
         return pointsPath(plane, {{0, 0}, {1, 1}, {2, 0.5}, {3, 2}}, false, PointsInterpolation::CubicSpline, 0);
       },
       0.7},
      {"plane polyline rounded",
       [=]() -> P {
         return pointsPath(plane, {{0, 0}, {3, 0}, {3, 2}, {0, 2}}, true, PointsInterpolation::Polyline, 0.5);
       },
       1.0},
      {"plane geodesic", [=]() -> P { return geodesicPath(plane, Vec2(0.5, 0.2), Vec3(1, 1, 0), 5.0); }, 1.0},
      // sphere
      {"sphere parallel (generic)", [=]() -> P { return sphereParallel(sphereOut, 60 * deg, 1.0, true); }, 1.0},
      {"sphere inside parallel", [=]() -> P { return sphereParallel(sphereIn, 50 * deg, 1.0, false); }, 1.0},
      {"sphere meridian", [=]() -> P { return sphereMeridian(sphereOut, 20 * deg, 20 * deg, 150 * deg); }, 1.0},
      {"sphere loxodrome", [=]() -> P { return sphereLoxodrome(sphereOut, 60 * deg, 0.0, 30 * deg, 140 * deg); }, 1.0},
      {"sphere inside loxodrome", [=]() -> P { return sphereLoxodrome(sphereIn, -50 * deg, 1.0, 120 * deg, 40 * deg); },
       0.8},
      {"sphere geodesic", [=]() -> P { return geodesicPath(sphereOut, Vec2(1.0, 0.3), Vec3(0.3, 1.0, 0.5), 9.0); },
       1.0},
      {"sphere uv",
       [=]() -> P {
         return uvExpressionPath(sphereOut, expr("1.2+0.4*sin(2*t)", {"t"}), expr("t", {"t"}), 0.0, 2 * kPi);
       },
       1.0},
      {"sphere points",
       [=]() -> P {
         return pointsPath(sphereIn, loopAround(1.5, 0.5, 0.6, 0.8), true, PointsInterpolation::CubicSpline, 0);
       },
       1.0},
      // cylinder
      {"cylinder parallel", [=]() -> P { return cylinderParallel(cylOut, 0.5, 1.0, true); }, 1.0},
      {"cylinder inside parallel", [=]() -> P { return cylinderParallel(cylIn, 0.0, 1.0, false); }, 1.5},
      {"cylinder meridian", [=]() -> P { return cylinderMeridian(cylOut, 0.3, -1.0, 6.0); }, 1.0},
      {"cylinder helix", [=]() -> P { return cylinderHelix(cylOut, 25 * deg, 0.0, 1.0, true); }, 1.0},
      {"cylinder inside helix", [=]() -> P { return cylinderHelix(cylIn, -40 * deg, 0.0, 1.0, true); }, 1.2},
      {"cylinder geodesic", [=]() -> P { return geodesicPath(cylOut, Vec2(0.0, 0.0), Vec3(0.0, 1.0, 0.4), 10.0); },
       1.0},
      {"cylinder uv",
       [=]() -> P { return uvExpressionPath(cylIn, expr("t", {"t"}), expr("0.5*sin(2*t)", {"t"}), 0.0, 2 * kPi); },
       1.0},
      {"cylinder points",
       [=]() -> P {
         return pointsPath(cylOut, loopAround(0.0, 0.0, 1.0, 1.5), true, PointsInterpolation::CubicSpline, 0);
       },
       1.0},
      // torus
      {"torus parallel", [=]() -> P { return torusParallel(torusOut, 60 * deg, 0.5, true); }, 1.0},
      {"torus inner-equator parallel", [=]() -> P { return torusParallel(torusOut, kPi, 1.0, false); }, 1.0},
      {"torus inside parallel", [=]() -> P { return torusParallel(torusIn, 30 * deg, 0.4, true); }, 0.6},
      {"torus meridian", [=]() -> P { return torusMeridian(torusOut, 0.4, 0.0, 1.0, true); }, 1.0},
      {"torus inside meridian", [=]() -> P { return torusMeridian(torusIn, 0.4, 0.0, 1.0, false); }, 0.6},
      {"torus geodesic", [=]() -> P { return geodesicPath(torusOut, Vec2(0.0, 0.5), Vec3(0.2, 1.0, 0.6), 12.0); }, 1.0},
      {"torus uv (torus knot)",
       [=]() -> P { return uvExpressionPath(torusOut, expr("2*t", {"t"}), expr("3*t", {"t"}), 0.0, 0.8 * kPi); }, 0.8},
      {"torus points",
       [=]() -> P {
         return pointsPath(torusIn, loopAround(0.5, 1.0, 0.8, 1.2), true, PointsInterpolation::CubicSpline, 0);
       },
       0.6},
      // quadric height fields
      {"paraboloid parallel", [=]() -> P { return heightFieldParallel(bowl, 2.0, 1.0, true); }, 1.0},
      {"dome parallel", [=]() -> P { return heightFieldParallel(dome, 1.5, 1.0, false); }, 1.0},
      {"paraboloid meridian", [=]() -> P { return heightFieldMeridian(bowl, 0.7, 6.0); }, 1.0},
      {"paraboloid geodesic", [=]() -> P { return geodesicPath(bowl, Vec2(-2.0, -1.0), Vec3(1.0, 0.3, 0.0), 6.0); },
       1.0},
      {"paraboloid uv",
       [=]() -> P { return uvExpressionPath(bowl, expr("t", {"t"}), expr("0.5*t^2-1", {"t"}), -2.0, 2.0); }, 1.0},
      {"paraboloid points",
       [=]() -> P {
         return pointsPath(dome, loopAround(0.3, 0.0, 1.5, 1.0), true, PointsInterpolation::CubicSpline, 0);
       },
       1.0},
      {"saddle meridian", [=]() -> P { return heightFieldMeridian(saddle, 0.5, 5.0); }, 1.0},
      {"saddle geodesic", [=]() -> P { return geodesicPath(saddle, Vec2(-2.0, 0.5), Vec3(1.0, -0.2, 0.0), 5.0); }, 1.0},
      {"saddle uv",
       [=]() -> P {
         return uvExpressionPath(saddle, expr("1.5*cos(t)", {"t"}), expr("1.5*sin(t)", {"t"}), 0.0, 2 * kPi);
       },
       1.0},
      {"saddle polyline rounded",
       [=]() -> P {
         return pointsPath(saddle, {{-2, -1}, {1, -1.5}, {2, 1}, {-1, 1.5}}, true, PointsInterpolation::Polyline, 0.6);
       },
       1.0},
      // expression height field
      {"height meridian", [=]() -> P { return heightFieldMeridian(bumps, 0.3, 6.0); }, 0.8},
      {"height geodesic", [=]() -> P { return geodesicPath(bumps, Vec2(-2.0, 0.3), Vec3(1.0, 0.4, 0.0), 5.0); }, 0.8},
      {"height uv",
       [=]() -> P { return uvExpressionPath(bumps, expr("2*cos(t)", {"t"}), expr("1.5*sin(t)", {"t"}), 0.0, 2 * kPi); },
       0.8},
      {"height points",
       [=]() -> P {
         return pointsPath(bumps, {{-2, -1}, {0, -1.2}, {1.5, 0}, {1, 1.5}, {-1, 1}}, false,
                           PointsInterpolation::CubicSpline, 0);
       },
       0.8},
  };
}

}  // namespace rollspin::test
