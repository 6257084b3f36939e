// ContactPath::finerApproximation: a geodesic's second, finer approximation
// (marched at half the step with compensated sums, taken in arc length as it
// is) against the closed-form geodesic of a tilted cylinder (a helix, linear
// in (φ, z)); paths in closed form have none; a joined path replaces only
// its geodesic pieces.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <memory>
#include <utility>

#include "geometry/joined_path.hpp"
#include "geometry/surface_paths.hpp"

using namespace rollspin::geometry;

namespace {

struct TiltedCylinderGeodesic {
  std::shared_ptr<const Cylinder> cylinder = std::make_shared<Cylinder>(2.0, Vec3(1, 0, 1), Side::Outside);
  Vec2 startUv{0.3, -0.2};
  Vec3 direction{0.3, 1.0, 0.2};
  double length = 12.0;
  // The helix x(u0 + s u', v0 + s v') at unit speed, (u', v') from the
  // direction: its point and unit tangent x_u u' + x_v v'.
  [[nodiscard]] std::pair<Vec3, Vec3> exact(double s) const {
    const SurfaceJet j0 = cylinder->jet(startUv);
    const Vec3 n = j0.xu.cross(j0.xv).normalized();
    const Vec3 unit = (direction - direction.dot(n) * n).normalized();
    Eigen::Matrix2d metric;
    metric << j0.xu.dot(j0.xu), j0.xu.dot(j0.xv), j0.xu.dot(j0.xv), j0.xv.dot(j0.xv);
    const Vec2 rate = metric.inverse() * Vec2(j0.xu.dot(unit), j0.xv.dot(unit));
    const SurfaceJet j = cylinder->jet(startUv + s * rate);
    return {j.x, j.xu * rate.x() + j.xv * rate.y()};
  }
};

// The fitted geodesic ends 3.9e-13 short of its length (the march's
// rounding over 6,000 equal steps) and lies up to 1.4e-12 off the helix at
// equal s; the finer one is exactly its length and measured within 3e-15,
// so the two differ by the fitted one's error.
TEST(FinerApproximation, AGeodesicsFinerPathIsCloserToTheTrueGeodesic) {
  const TiltedCylinderGeodesic g;
  const auto fitted = geodesicPath(g.cylinder, g.startUv, g.direction, g.length);
  const std::unique_ptr<ContactPath> finer = fitted->finerApproximation();
  ASSERT_NE(finer, nullptr);
  EXPECT_EQ(finer->length(), g.length);
  EXPECT_GT(std::abs(fitted->length() - g.length), 1e-13);
  double fittedOff = 0.0, finerOff = 0.0;
  for (int k = 0; k <= 400; ++k) {
    const double s = g.length * k / 400.0;
    const auto [point, tangent] = g.exact(s);
    fittedOff = std::max(fittedOff, (fitted->point(std::min(s, fitted->length())) - point).norm());
    finerOff = std::max(finerOff, (finer->point(s) - point).norm());
    EXPECT_NEAR((finer->at(s).tangent - tangent).norm(), 0.0, 1e-13) << s;
    EXPECT_NEAR(finer->at(s).geodesicCurvature, 0.0, 1e-12) << s;
  }
  EXPECT_LE(finerOff, 1e-14);
  EXPECT_GT(fittedOff, 1e-13);
}

TEST(FinerApproximation, PathsInClosedFormHaveNone) {
  const auto cylinder = std::make_shared<Cylinder>(2.0, Vec3(0, 0, 1), Side::Outside);
  EXPECT_EQ(cylinderHelix(cylinder, 0.5, 0.0, 1.0, true)->finerApproximation(), nullptr);
  EXPECT_EQ(cylinderParallel(cylinder, 0.0, 1.0, true, 0.0)->finerApproximation(), nullptr);
  // A great circle on a sphere is a geodesic in closed form.
  const auto sphere = std::make_shared<Sphere>(2.0, Side::Outside);
  EXPECT_EQ(geodesicPath(sphere, Vec2(1.0, 0.2), Vec3(0, 1, 0.3), 3.0)->finerApproximation(), nullptr);
}

TEST(FinerApproximation, AJoinedPathReplacesOnlyItsGeodesics) {
  const TiltedCylinderGeodesic g;
  std::vector<std::unique_ptr<ContactPath>> pieces;
  pieces.push_back(cylinderParallel(g.cylinder, 0.0, 0.25, true, 0.0));
  pieces.push_back(geodesicPath(g.cylinder, g.startUv, g.direction, g.length));
  const JoinedPath joined(std::move(pieces));
  const std::unique_ptr<ContactPath> finer = joined.finerApproximation();
  ASSERT_NE(finer, nullptr);
  ASSERT_EQ(finer->pieces().size(), 2u);
  const ContactPath& parallel = *joined.pieces()[0].path;
  for (double s : {0.0, 0.7, parallel.length()})
    EXPECT_EQ(finer->pieces()[0].path->point(s), parallel.point(s));  // borrowed as it is
  EXPECT_EQ(finer->pieces()[1].path->length(), g.length);
  std::vector<std::unique_ptr<ContactPath>> closed;
  closed.push_back(cylinderParallel(g.cylinder, 0.0, 0.25, true, 0.0));
  EXPECT_EQ(JoinedPath(std::move(closed)).finerApproximation(), nullptr);
}

}  // namespace
