// spin/frame_propagator: the frame's spinor, g = Fᵀ(ω − d), and one frame4 step against closed forms and the oracle.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "geometry/surface_paths.hpp"
#include "kinematics/rolling_kinematics.hpp"
#include "spin/frame_propagator.hpp"
#include "support/numbers.hpp"
#include "support/test_paths.hpp"

namespace rollspin::spin {
namespace {

// The spinor of the rotation by |v| about v̂, from its half angle: exactly
// (cos |v|/2, sin |v|/2 v̂), so a vector of length 2π gives −1 (no sign is
// normalised: a closed form built from it keeps the 4π story).
Su2 halfAngleSpinorOf(const Vec3& v) {
  const double angle = v.norm();
  if (angle == 0.0) return Su2::identity();
  const Vec3 axis = v / angle;
  return {std::cos(0.5 * angle), std::sin(0.5 * angle) * axis.x(), std::sin(0.5 * angle) * axis.y(),
          std::sin(0.5 * angle) * axis.z()};
}

// A path of constant κ_n, κ_g, τ_g has a Darboux vector d fixed in space
// (d' = d × d = 0) and ω = (1/R) n × dC/ds = τ_g t + (1/R − κ_n) u, whose
// components in the frame are constant: ω(s) = Rot(d, s|d|) ω(0), a rigidly
// turning field. Q' = [ω]× Q is then solved by Q(s) = A(s) B(s),
// A = Rot(d, s|d|), B = Rot(ω(0) − d, s|ω(0) − d|):
//   Q' = [d]× A B + A [ω(0) − d]× B = [d + A ω(0) − A d]× Q = [ω(s)]× Q
// (A d = d), and with ω(0) − d = u/R − κ_g n. As spinors,
//   U(s) = e(s d) e(s (u(0)/R − κ_g n(0))),  e = halfAngleSpinorOf,
// continuous in s from U(0) = 1: the sign too.
Su2 constantCurvatureSpinor(const geometry::ContactPath& path, double R, double s) {
  const geometry::DarbouxSample f0 = path.at(0.0);
  const Vec3 d =
      f0.geodesicTorsion * f0.tangent - f0.normalCurvature * f0.tangentNormal + f0.geodesicCurvature * f0.normal;
  return halfAngleSpinorOf(s * d) * halfAngleSpinorOf(s * (f0.tangentNormal / R - f0.geodesicCurvature * f0.normal));
}

Mat3 frameColumnsOf(const geometry::DarbouxSample& f) {
  Mat3 m;
  m.col(0) = f.tangent;
  m.col(1) = f.tangentNormal;
  m.col(2) = f.normal;
  return m;
}

geometry::DarbouxSample frameOfRotation(const Mat3& r) {
  geometry::DarbouxSample f;
  f.tangent = r.col(0);
  f.tangentNormal = r.col(1);
  f.normal = r.col(2);
  return f;
}

// R(Φ) takes x̂, ŷ, ẑ to t, u, n, and the sign is the one with w ≥ 0: at and
// near a half turn, about axes whose largest component is negative too (where
// a matrix-to-quaternion conversion may come out with w < 0).
TEST(FrameSpinor, RotatesTheAxesOntoTheFrameWithWNotNegative) {
  std::vector<Mat3> frames = {Mat3::Identity()};
  for (const Vec3& axis : {Vec3(1, 2, 3), Vec3(-1, -2, -3), Vec3(0.2, -3, 0.5), Vec3(0, 0, -1), Vec3(-1, 0, 0)})
    for (double angle : {0.4, 2.0, 3.0, 3.1, test::kPi})
      frames.push_back(Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix());
  for (const Mat3& r : frames) {
    const Su2 phi = frameSpinor(frameOfRotation(r));
    EXPECT_GE(phi.w, 0.0) << r;
    EXPECT_NEAR(phi.norm(), 1.0, 1e-14) << r;
    EXPECT_NEAR((phi.rotate(Vec3::UnitX()) - r.col(0)).norm(), 0.0, 1e-14) << r;
    EXPECT_NEAR((phi.rotate(Vec3::UnitY()) - r.col(1)).norm(), 0.0, 1e-14) << r;
    EXPECT_NEAR((phi.rotate(Vec3::UnitZ()) - r.col(2)).norm(), 0.0, 1e-14) << r;
  }
}

// The header's derivation: in frame axes the ball turns at g = Fᵀ(ω − d),
// ω from the kinematic oracle (finite differences of the centre, no
// curvature) and d the frame's own turn. The paths have every curvature.
TEST(FrameAngularVelocity, IsTheRollingRateLessTheFramesTurnInFrameAxes) {
  using test::kDeg;
  auto sphere = std::make_shared<const geometry::Sphere>(2.0, geometry::Side::Outside);
  auto torus = std::make_shared<const geometry::Torus>(4.0, 1.5, geometry::Side::Inside);
  auto cylinder = std::make_shared<const geometry::Cylinder>(1.3, Vec3(0, 0, 1), geometry::Side::Outside);
  const std::unique_ptr<geometry::ContactPath> paths[] = {
      geometry::sphereLoxodrome(sphere, 60 * kDeg, 0.0, 40 * kDeg, 130 * kDeg),
      geometry::torusParallel(torus, 50 * kDeg, 1.0, false),
      geometry::cylinderHelix(cylinder, 35 * kDeg, 0.0, 1.0, true),
  };
  for (const auto& path : paths)
    for (double R : {0.3, 0.8}) {
      const kinematics::RollingKinematics oracle(*path, R);
      for (int k = 1; k < 10; ++k) {
        const double s = path->length() * k / 10.0;
        const geometry::DarbouxSample f = path->at(s);
        const Vec3 g = frameColumnsOf(f).transpose() * (oracle.omega(s) - geometry::darbouxVector(f));
        EXPECT_NEAR((frameAngularVelocity(f, R) - g).norm(), 0.0, 1e-8) << path->describe() << " R " << R;
      }
    }
}

// Constant curvatures: one step of any length, from anywhere, is U(s + h)
// U(s)† of the closed form above, sign included; a step may take in three
// whole turns of the circle (the frame's own turn D = ±1 decided by the
// Magnus estimate of the frame's turn alone).
TEST(Frame4Element, OneStepOfAnyLengthIsExactOnConstantCurvatures) {
  using test::kDeg;
  auto torus = std::make_shared<const geometry::Torus>(4.0, 1.5, geometry::Side::Outside);
  auto cylinder = std::make_shared<const geometry::Cylinder>(2.0, Vec3(0, 0, 1), geometry::Side::Inside);
  const std::unique_ptr<geometry::ContactPath> paths[] = {
      test::lollipopPath(3.0, 3.0, true),
      test::lollipopPath(0.7, 1.0, false),
      test::sphereParallel(5.0, true, 50 * kDeg, 2.0, true),
      test::sphereParallel(3.0, false, 70 * kDeg),
      geometry::torusParallel(torus, 30 * kDeg, 1.0, true),
      geometry::cylinderHelix(cylinder, 25 * kDeg, 0.0, 2.0, false),
  };
  const double R = 0.9;
  for (const auto& path : paths) {
    const double L = path->length();
    for (double start : {0.0, 0.3 * L})
      for (double h : {L / 17, L / 3, L - start}) {
        const Su2 expected =
            constantCurvatureSpinor(*path, R, start + h) * constantCurvatureSpinor(*path, R, start).conjugate();
        EXPECT_LE(spinorDistance(frame4Element(*path, R, start, h), expected), 1e-12)
            << path->describe() << " from " << start << " by " << h;
      }
  }
}

// Where κ_g varies (a loxodrome: κ_g ∝ cot θ), steps of frame4 marched over
// the path converge to the kinematic oracle at fourth order, and to its
// spinor: the oracle's rotations lifted by continuity from U(0) = 1.
TEST(Frame4Element, MarchedStepsConvergeToTheKinematicsAtFourthOrder) {
  using test::kDeg;
  auto sphere = std::make_shared<const geometry::Sphere>(2.0, geometry::Side::Outside);
  const auto path = geometry::sphereLoxodrome(sphere, 70 * kDeg, 0.0, 30 * kDeg, 150 * kDeg);
  const double R = 0.6, L = path->length();
  // Lifted through 1000 samples: neighbours differ by far less than π (the
  // ball turns by about 20 rad in all).
  std::vector<double> lift;
  for (int k = 0; k <= 1000; ++k) lift.push_back(L * k / 1000.0);
  const std::vector<Mat3> q = kinematics::RollingKinematics(*path, R, {8000, 0.0}).orientations(lift);
  Su2 truth = Su2::identity();
  for (const Mat3& m : q) {
    const Eigen::Quaterniond e(m);
    Su2 next{e.w(), e.x(), e.y(), e.z()};
    if (next.w * truth.w + next.x * truth.x + next.y * truth.y + next.z * truth.z < 0.0) next = -next;
    truth = next;
  }
  std::vector<double> errors;
  for (int steps : {12, 24, 48}) {
    Su2 u = Su2::identity();
    for (int k = 0; k < steps; ++k) {
      const double s = L * k / steps, end = L * (k + 1) / steps;
      u = frame4Element(*path, R, s, end - s, end) * u;
    }
    errors.push_back(spinorDistance(u, truth));
    if (std::getenv("ROLLSPIN_VERBOSE")) std::printf("frame4 steps %d: %.3e\n", steps, errors.back());
  }
  // Measured 3.4e-3, 2.1e-4, 1.3e-5: far above the oracle's own error (~1e-10).
  EXPECT_GT(errors.back(), 1e-7) << "the path must be hard enough that the order shows above the oracle's error";
  for (std::size_t k = 1; k < errors.size(); ++k) {
    EXPECT_GT(errors[k - 1] / errors[k], 12.0) << k;
    EXPECT_LT(errors[k - 1] / errors[k], 20.0) << k;
  }
}

}  // namespace
}  // namespace rollspin::spin
