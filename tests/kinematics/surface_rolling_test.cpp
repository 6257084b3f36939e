// The surface oracle on its own (kinematics/surface_rolling.hpp): rolling
// along helices on cylinders against the closed form of the screw motion,
// derived here from dQ/ds = [ω]× Q alone, never from the spinor solver.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "geometry/surfaces.hpp"
#include "geometry/uv_curve.hpp"
#include "kinematics/surface_rolling.hpp"
#include "support/numbers.hpp"

namespace rollspin::kinematics {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

double distance(const Mat3& a, const Mat3& b) { return Eigen::AngleAxisd(a.transpose() * b).angle(); }

// A helix on a cylinder of radius a about the unit axis â, run at unit speed
// with φ' = c, is carried into itself by the screw motion (a turn about â by
// c Δs and a shift along â), so n(s) = Rot(â, cs) n₀, t(s) = Rot(â, cs) t₀,
// dn/ds = c â × n, and ω = (1/R) n × (t + R dn/ds) = Rot(â, cs) ω₀ with
// ω₀ = (1/R) n₀ × (t₀ + R c â × n₀). Writing Q = Rot(â, cs) B:
// [câ]× Q + Rot B' = [Rot ω₀]× Q, i.e. B' = [ω₀ − câ]× B, a constant vector:
//   Q(s) = Rot(â, cs) exp(s [ω₀ − câ]×).
Mat3 screwMotion(const geometry::Cylinder& cylinder, const Vec2& startUv, const Vec2& rate, double ballRadius,
                 double length) {
  const geometry::SurfaceJet j = cylinder.jet(startUv);
  const Vec3 axis = j.xv.normalized(), n0 = cylinder.normal(startUv), t0 = j.xu * rate.x() + j.xv * rate.y();
  const double c = rate.x();
  const Vec3 w0 = n0.cross(t0 + ballRadius * c * axis.cross(n0)) / ballRadius;
  const Vec3 body = w0 - c * axis;
  return Eigen::AngleAxisd(c * length, axis).toRotationMatrix() *
         Eigen::AngleAxisd(body.norm() * length, body.normalized()).toRotationMatrix();
}

// Tilted axes, both sides, pitch angles from nearly a parallel to steep; the
// geodesic integrated from its start, and the same helix given as a curve
// run at twice the speed (the rotation may not depend on the parameter).
// Measured: at most 7e-15 from the closed form and a bound of at most 9e-15
// (both round-off: ROLLSPIN_VERBOSE=1 prints them), 0.3 s for all 18.
TEST(SurfaceRolling, HelicesOnACylinderFollowTheScrewMotion) {
  for (const Vec3& axis : {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(-0.3, 1, 0.2)})
    for (const geometry::Side side : {geometry::Side::Outside, geometry::Side::Inside})
      for (const double pitch : {5.0, 35.0, 80.0}) {
        const double a = 2.0, R = side == geometry::Side::Outside ? 0.5 : 1.2, L = 9.0;
        const geometry::Cylinder cylinder(a, axis, side);
        const Vec2 startUv(0.3, -0.4);
        const Vec2 rate(std::cos(pitch * test::kDeg) / a, std::sin(pitch * test::kDeg));
        const geometry::SurfaceJet j = cylinder.jet(startUv);
        const Mat3 expected = screwMotion(cylinder, startUv, rate, R, L);
        const SurfaceRolling geodesic =
            rollAlongGeodesic(cylinder, startUv, j.xu * rate.x() + j.xv * rate.y(), L, R, 4000);
        const geometry::FunctionUvCurve curve(
            [&](const geometry::Jet& sigma) {
              return std::array<geometry::Jet, 2>{startUv.x() + 0.5 * rate.x() * sigma,
                                                  startUv.y() + 0.5 * rate.y() * sigma};
            },
            0.0, 2.0 * L, "helix at half speed");
        const SurfaceRolling given = rollAlongCurve(cylinder, curve, R, 4000);
        if (std::getenv("ROLLSPIN_VERBOSE"))
          std::printf("pitch %4.0f: geodesic %.1e (bound %.1e), curve %.1e (bound %.1e)\n", pitch,
                      distance(geodesic.orientation, expected), geodesic.ownError,
                      distance(given.orientation, expected), given.ownError);
        EXPECT_LE(distance(geodesic.orientation, expected), 1e-13) << axis.transpose() << " pitch " << pitch;
        EXPECT_LE(distance(given.orientation, expected), 1e-13) << axis.transpose() << " pitch " << pitch;
        EXPECT_LE(geodesic.ownError, 1e-13);
        EXPECT_LE(given.ownError, 1e-13);
      }
}

// The reported bound holds where truncation, not round-off, rules: on a
// coarse grid (N = 40 over 9 units, RK4 far from converged) the result is
// off by more than round-off, yet by less than the bound it reports.
TEST(SurfaceRolling, ItsOwnErrorBoundsItsError) {
  const geometry::Cylinder cylinder(2.0, Vec3(1, 0, 1), geometry::Side::Outside);
  const Vec2 startUv(0.1, 0.2), rate(0.6 / 2.0, 0.8);
  const geometry::SurfaceJet j = cylinder.jet(startUv);
  const SurfaceRolling coarse = rollAlongGeodesic(cylinder, startUv, j.xu * rate.x() + j.xv * rate.y(), 9.0, 0.5, 40);
  const double error = distance(coarse.orientation, screwMotion(cylinder, startUv, rate, 0.5, 9.0));
  EXPECT_GT(error, 1e-9);
  EXPECT_LE(error, coarse.ownError);
}

}  // namespace
}  // namespace rollspin::kinematics
