// Physical validity along a path: the ball touches at one point only while
// R k1 < 1 (k1 the largest principal curvature towards the ball); the first
// failing s is reported with the numbers (that the solver stays finite as
// 1 − κ_n R → 0 is tests/spin/surface_solver_test.cpp).
// Curves that leave the domain, stop, or have corners are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/surface_paths.hpp"
#include "support/numbers.hpp"
#include "support/surface_cases.hpp"

using namespace rollspin;
using namespace rollspin::geometry;

namespace {

using rollspin::test::kPi;

TEST(ContactValidity, BallTooBigInsideACylinder) {
  auto cyl = std::make_shared<const Cylinder>(2.0, Vec3(0, 0, 1), Side::Inside);
  const auto path = cylinderParallel(cyl, 0.0, 1.0, true);
  EXPECT_TRUE(checkSingleContact(*path, 1.9).ok);
  const ContactCheck bad = checkSingleContact(*path, 2.1);
  ASSERT_FALSE(bad.ok);
  EXPECT_NEAR(bad.s, 0.0, 1e-12);
  EXPECT_NEAR(bad.curvature, 0.5, 1e-12);
  EXPECT_NE(bad.reason.find("ball.radius < 2"), std::string::npos) << bad.reason;
}

TEST(ContactValidity, SaddleReportsTheFirstFailingArcLength) {
  // z = (x² − y²/2)/2 seen from above: k1 = 1 at the origin (radius 1),
  // falling off away from it. A ball of radius 1.2 fits at the ends of this
  // section through the origin but not near the middle.
  auto saddle = HeightField::quadric(1.0, 2.0, true, true);
  const auto path = heightFieldMeridian(saddle, 0.5 * kPi, 6.0);
  const double R = 1.2;
  const ContactCheck check = checkSingleContact(*path, R);
  ASSERT_FALSE(check.ok);
  auto k1 = [&](double s) { return shapeAt(*saddle, path->uvAt(s)).maxCurvature; };
  EXPECT_LT(R * k1(check.s - 1e-6), 1.0);
  EXPECT_GE(R * k1(check.s), 1.0 - 1e-12);
  EXPECT_GT(check.s, 0.5);
  EXPECT_LT(check.s, 0.5 * path->length());
  EXPECT_NE(check.reason.find("arc length s = "), std::string::npos) << check.reason;
}

TEST(ContactValidity, InsideTheTorusTube) {
  auto torus = std::make_shared<const Torus>(4.0, 1.5, Side::Inside);
  const auto path = torusMeridian(torus, 0.0, 0.0, 1.0, true);
  EXPECT_TRUE(checkSingleContact(*path, 1.45).ok);
  EXPECT_FALSE(checkSingleContact(*path, 1.55).ok);
}

TEST(CurveErrors, LeavingTheDomainIsReported) {
  auto sphere = std::make_shared<const Sphere>(3.0, Side::Outside);
  EXPECT_THROW((void)sphereMeridian(sphere, 0.0, 0.5, 3.5), GeometryError);  // through the pole θ = π
  auto cap = HeightField::fromExpression(
      std::make_shared<const Expression>("sqrt(4-x^2-y^2)", std::vector<std::string>{"x", "y"}), true);
  try {
    (void)geodesicPath(cap, Vec2(0.0, 0.0), Vec3(1, 0, 0), 5.0);
    ADD_FAILURE() << "a geodesic off the cap was accepted";
  } catch (const GeometryError& e) {
    // At the cap's rim the height itself has no value (a NaN, not a
    // domain bound): the message says where the surface is undefined.
    const std::string what = e.what();
    EXPECT_TRUE(what.find("leaves the surface") != std::string::npos ||
                what.find("the surface is undefined where the geodesic reaches") != std::string::npos)
        << what;
  }
}

// A smooth curve that turns too often for its segment's 2^16 panels (an
// ellipse wound 16 000 times) is refused with both causes named and the
// panel's width, not called "a kink or cusp" alone.
TEST(CurveErrors, CurvesTooLongForTheirPanelsNameTheRange) {
  auto plane = std::make_shared<const Plane>(Vec3(0, 0, 1));
  auto e = [](const char* t) { return std::make_shared<const Expression>(t, std::vector<std::string>{"t"}); };
  try {
    (void)uvExpressionPath(plane, e("cos(t)"), e("2*sin(t)"), 0.0, 1e5);
    ADD_FAILURE() << "a curve wound 16 000 times was fitted";
  } catch (const GeometryError& err) {
    const std::string what = err.what();
    EXPECT_NE(what.find("parameter step of 1.52588 (1/65536 of its segment)"), std::string::npos) << what;
    EXPECT_NE(what.find("shorten its parameter range"), std::string::npos) << what;
    EXPECT_NE(what.find("kink or cusp"), std::string::npos) << what;
  }
}

TEST(CurveErrors, KinksInExpressionsAreRefused) {
  auto plane = std::make_shared<const Plane>(Vec3(0, 0, 1));
  auto e = [](const char* t) { return std::make_shared<const Expression>(t, std::vector<std::string>{"t"}); };
  try {
    (void)uvExpressionPath(plane, e("t"), e("abs(t-0.3)"), -1.0, 1.0);
    ADD_FAILURE() << "a kink was accepted";
  } catch (const GeometryError& err) {
    EXPECT_NE(std::string(err.what()).find("corner at curve parameter 0.3"), std::string::npos) << err.what();
  }
  // A crease in the surface under a smooth curve: the normal jumps.
  auto creased = HeightField::fromExpression(
      std::make_shared<const Expression>("0.5*abs(x-0.2)", std::vector<std::string>{"x", "y"}), true);
  EXPECT_THROW((void)uvExpressionPath(creased, e("t"), e("0.3*t"), -1.0, 1.0), GeometryError);
  // A cusp: zero speed at t = 0.
  EXPECT_THROW((void)uvExpressionPath(plane, e("t^3"), e("t^2"), -1.0, 1.0), GeometryError);
}

TEST(CurveErrors, CornersNeedARadius) {
  const std::vector<Vec2> square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  try {
    (void)SplineUvCurve::roundedPolyline(square, false, 0.0);
    ADD_FAILURE();
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("corner at point 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)SplineUvCurve::roundedPolyline(square, true, 1.5), GeometryError);  // too large
  const auto rounded = SplineUvCurve::roundedPolyline(square, true, 0.5);
  EXPECT_EQ(rounded->breakpoints().size(), 7u);  // 4 legs + 4 arcs, minus the ends
  EXPECT_THROW((void)SplineUvCurve::cubic({{0, 0}, {0, 0}, {1, 1}}, false), GeometryError);
}

}  // namespace
