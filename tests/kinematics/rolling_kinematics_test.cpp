// The independent oracle on its own: the rigid-body integration
//   dQ/ds = [ω]× Q,  ω = (1/R) n × dC/ds,  C = P + R n,  Q(0) = 1
// (kinematics/rolling_kinematics.hpp) against closed forms derived here from
// that equation alone, never from the spinor solver or the paper: a line on
// a plane, a parallel of a sphere (either side), the rotation staying in
// SO(3), and the order of its RK4 step.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <vector>

#include "geometry/analytic_paths.hpp"
#include "geometry/surface.hpp"
#include "kinematics/rolling_kinematics.hpp"
#include "support/numbers.hpp"
#include "support/test_paths.hpp"

namespace rollspin::kinematics {
namespace {

using test::kPi;
using test::rotationMatrixDistance;

Mat3 rotation(const Vec3& axisTimesAngle) {
  const double angle = axisTimesAngle.norm();
  if (angle == 0.0) return Mat3::Identity();
  return Eigen::AngleAxisd(angle, axisTimesAngle / angle).toRotationMatrix();
}

// A straight line of length L along t on a plane with normal n: C = P + R n
// moves with dC/ds = t, so ω = (1/R) n × t is constant and Q(s) =
// exp(s/R [n × t]×) — a turn by L/R about n × t, whatever the plane's tilt.
// The differences of a linear C are exact; RK4 on a constant ω errs by
// (h|ω|)⁵/120 a step, below 1e-17 at 20000 steps, so only the round-off of
// 20000 steps remains (3e-12 measured).
TEST(RollingKinematics, ALineOnAPlaneTurnsByLengthOverRadiusAboutNormalCrossTangent) {
  for (const Vec3& normal : {Vec3(0, 0, 1), Vec3(1.0, -0.5, 2.0).normalized(), Vec3(0, -1, 0)}) {
    for (double R : {0.4, 1.0, 2.5}) {
      const double L = 7.3;
      const auto path = test::planeLine(normal, L);
      const Vec3 t = (path->point(L) - path->point(0.0)) / L;
      ASSERT_NEAR(t.dot(normal), 0.0, 1e-15);  // the line lies in the plane
      const RollingKinematics kin(*path, R, {20000, 0.0});
      const std::vector<double> s{0.0, 0.3 * L, L};
      const std::vector<Mat3> q = kin.orientations(s);
      for (std::size_t k = 0; k < s.size(); ++k)
        EXPECT_LE(rotationMatrixDistance(q[k], rotation(s[k] / R * normal.cross(t))), 1e-11)
            << "n = " << normal.transpose() << ", R = " << R << ", s = " << s[k];
      EXPECT_NEAR((kin.omega(0.5 * L) - normal.cross(t) / R).norm(), 0.0, 1e-9);
    }
  }
}

// A parallel at colatitude θ of a sphere of radius a, the ball (radius R)
// outside (σ = +1) or inside (σ = −1). With φ the azimuth, P = a(sinθ cosφ,
// sinθ sinφ, cosθ), n = σ P/a, t = (−sinφ, cosφ, 0), ds = a sinθ dφ:
//   C = P + R n = (a + σR) P/a,  dC/ds = (a + σR)/a t,
//   ω = (1/R) n × dC/ds = σ (a + σR)/(aR) m(φ),  m = (P/a) × t
//     = (−cosθ cosφ, −cosθ sinφ, sinθ) = Rz(φ) m₀.
// So dQ/dφ = [Rz(φ) w₀]× Q with w₀ = a sinθ σ (a + σR)/(aR) m₀. Writing
// Q = Rz(φ) B: Rz [ẑ]× B + Rz B' = Rz [w₀]× B, i.e. B' = [w₀ − ẑ]× B with a
// constant vector, hence
//   Q(φ) = Rz(φ) exp(φ [w₀ − ẑ]×).
TEST(RollingKinematics, ASphereParallelFollowsTheRotatingFrameClosedForm) {
  const double a = 3.0;
  for (bool outside : {true, false})
    for (double theta : {35 * test::kDeg, 90 * test::kDeg, 140 * test::kDeg}) {
      const double R = outside ? 1.0 : 0.8, sigma = outside ? 1.0 : -1.0;
      const double turns = 0.7;
      const auto path = test::sphereParallel(a, outside, theta, turns, true);
      const double rho = a * std::sin(theta);
      const double L = 2 * kPi * rho * turns;
      ASSERT_NEAR(path->length(), L, 1e-12);
      const Vec3 m0(-std::cos(theta), 0.0, std::sin(theta));
      const Vec3 w0 = rho * sigma * (a + sigma * R) / (a * R) * m0;
      std::vector<double> s;
      for (int k = 0; k <= 7; ++k) s.push_back(L * k / 7.0);
      const std::vector<Mat3> q = RollingKinematics(*path, R, {20000, 0.0}).orientations(s);
      for (std::size_t k = 0; k < s.size(); ++k) {
        const double phi = s[k] / rho;
        // The path is the parallel this derivation assumes: starts at φ = 0, φ grows.
        ASSERT_NEAR((path->point(s[k]) -
                     a * Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)))
                        .norm(),
                    0.0, 1e-12);
        const Mat3 expected =
            Eigen::AngleAxisd(phi, Vec3::UnitZ()).toRotationMatrix() * rotation(phi * (w0 - Vec3::UnitZ()));
        EXPECT_LE(rotationMatrixDistance(q[k], expected), 1e-10)
            << (outside ? "outside" : "inside") << " θ = " << theta << " s = " << s[k];
      }
    }
}

// RK4 on the nine entries of Q does not keep QᵀQ = 1 by construction: the
// drift is the method's own error (O(h⁴) per unit length), so at the default
// step counts it stays far below the 1e-10 the reports compare at.
TEST(RollingKinematics, TheRotationStaysOrthonormal) {
  const auto circle = test::lollipopPath(2.0, 3.0);
  const auto parallel = test::sphereParallel(3.0, false, 50 * test::kDeg, 2.0, true);
  for (const geometry::ContactPath* path : {circle.get(), parallel.get()}) {
    std::vector<double> s;
    for (int k = 0; k <= 20; ++k) s.push_back(path->length() * k / 20.0);
    for (const Mat3& q : RollingKinematics(*path, 0.9).orientations(s)) {
      EXPECT_LE((q.transpose() * q - Mat3::Identity()).norm(), 1e-11) << path->describe();
      EXPECT_NEAR(q.determinant(), 1.0, 1e-11) << path->describe();
    }
  }
}

// Classical RK4 is fourth order: halving the step divides the error of Q(L)
// by 2⁴ = 16. On a circle ω turns with the tangent, so the steps do not
// commute and the error is the method's, not zero. The finite-difference
// spacing is fixed, so the reference (64× the steps) shares its error and
// only the step's error remains.
TEST(RollingKinematics, ItsStepIsFourthOrder) {
  const auto path = test::lollipopPath(1.5, 1.0);
  const double R = 0.7, h = 1e-3;
  auto finalAt = [&](long long steps) { return RollingKinematics(*path, R, {steps, h}).finalOrientation(); };
  const Mat3 reference = finalAt(64 * 40);
  std::vector<double> errors;
  for (long long steps : {40LL, 80LL, 160LL}) errors.push_back(rotationMatrixDistance(finalAt(steps), reference));
  for (std::size_t k = 0; k + 1 < errors.size(); ++k) {
    const double order = std::log2(errors[k] / errors[k + 1]);
    EXPECT_GT(order, 3.7) << "errors " << errors[k] << " → " << errors[k + 1];
    EXPECT_LT(order, 4.3) << "errors " << errors[k] << " → " << errors[k + 1];
  }
  EXPECT_GT(errors.front(), 1e-9);  // large enough to measure, not round-off
}

}  // namespace
}  // namespace rollspin::kinematics
