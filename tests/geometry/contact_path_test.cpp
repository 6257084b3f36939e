// geometry/contact_path: the Darboux vector, describeNumber's "%g" and describeTurns' plural, the default tangent and a
// path's defaults.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <string>

#include "geometry/contact_path.hpp"
#include "geometry/surface_paths.hpp"
#include "support/numbers.hpp"
#include "support/test_paths.hpp"

namespace rollspin::geometry {
namespace {

// A right-handed Darboux frame: (t, u, n) the columns of a rotation.
DarbouxSample frameSampleFrom(const Eigen::Matrix3d& rotation, double kn, double kg, double tau) {
  DarbouxSample f;
  f.tangent = rotation.col(0);
  f.tangentNormal = rotation.col(1);
  f.normal = rotation.col(2);
  f.normalCurvature = kn;
  f.geodesicCurvature = kg;
  f.geodesicTorsion = tau;
  return f;
}

// dX/ds = d × X for X ∈ {t, u, n} is the header's Darboux equations written
// out, whatever the frame's attitude and the three curvatures:
//   dt/ds = κ_g u + κ_n n,   du/ds = −κ_g t + τ_g n,   dn/ds = −κ_n t − τ_g u.
TEST(DarbouxVector, CrossingItWithEachFrameVectorGivesTheDarbouxEquations) {
  const Eigen::Matrix3d attitudes[] = {
      Eigen::Matrix3d::Identity(),
      Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()).toRotationMatrix(),
      Eigen::AngleAxisd(2.9, Vec3(-0.3, 0.1, 1).normalized()).toRotationMatrix(),
  };
  const double curvatures[][3] = {{0.5, 0.0, 0.0}, {0.0, -1.5, 0.0}, {0.0, 0.0, 0.8}, {-0.4, 2.5, -0.9}};
  for (const Eigen::Matrix3d& q : attitudes)
    for (const auto& c : curvatures) {
      const double kn = c[0], kg = c[1], tau = c[2];
      const DarbouxSample f = frameSampleFrom(q, kn, kg, tau);
      const Vec3 d = darbouxVector(f);
      const Vec3 &t = f.tangent, &u = f.tangentNormal, &n = f.normal;
      EXPECT_NEAR((d.cross(t) - (kg * u + kn * n)).norm(), 0.0, 1e-14) << kn << " " << kg << " " << tau;
      EXPECT_NEAR((d.cross(u) - (-kg * t + tau * n)).norm(), 0.0, 1e-14) << kn << " " << kg << " " << tau;
      EXPECT_NEAR((d.cross(n) - (-kn * t - tau * u)).norm(), 0.0, 1e-14) << kn << " " << kg << " " << tau;
    }
}

// Along real curves the frame turns at d: differences of at(s)'s own
// t, u and n (fourth order, h = 1e-3) against d × X. A helix has κ_n and τ_g
// (no κ_g), a torus parallel off the crest κ_n and κ_g (no τ_g), a
// loxodrome all three.
TEST(DarbouxVector, IsTheRateAtWhichAPathsFrameTurns) {
  using test::kDeg;
  auto cylinder = std::make_shared<const Cylinder>(1.3, Vec3(0, 0, 1), Side::Outside);
  auto torus = std::make_shared<const Torus>(4.0, 1.5, Side::Inside);
  auto sphere = std::make_shared<const Sphere>(2.0, Side::Outside);
  const std::unique_ptr<ContactPath> paths[] = {
      cylinderHelix(cylinder, 35 * kDeg, 0.0, 1.0, true),
      torusParallel(torus, 50 * kDeg, 1.0, false),
      sphereLoxodrome(sphere, 60 * kDeg, 0.0, 40 * kDeg, 130 * kDeg),
  };
  for (const auto& path : paths) {
    double turning = 0.0;  // the largest |d| seen: a path with no turning would check nothing
    const double h = 1e-3, length = path->length();
    for (int k = 1; k < 20; ++k) {
      const double s = length * k / 20.0;
      const DarbouxSample f = path->at(s);
      const Vec3 d = darbouxVector(f);
      turning = std::max(turning, d.norm());
      auto rate = [&](Vec3 DarbouxSample::*x) {
        return ((-(path->at(s + 2 * h).*x) + 8 * (path->at(s + h).*x) - 8 * (path->at(s - h).*x) +
                 (path->at(s - 2 * h).*x)) /
                (12 * h))
            .eval();
      };
      EXPECT_NEAR((rate(&DarbouxSample::tangent) - d.cross(f.tangent)).norm(), 0.0, 1e-9) << path->describe();
      EXPECT_NEAR((rate(&DarbouxSample::tangentNormal) - d.cross(f.tangentNormal)).norm(), 0.0, 1e-9)
          << path->describe();
      EXPECT_NEAR((rate(&DarbouxSample::normal) - d.cross(f.normal)).norm(), 0.0, 1e-9) << path->describe();
    }
    EXPECT_GT(turning, 0.1) << path->describe();
  }
}

TEST(DescribeNumber, PrintsANumberAsPercentGDoes) {
  EXPECT_EQ(describeNumber(0.0), "0");
  EXPECT_EQ(describeNumber(2.0), "2");
  EXPECT_EQ(describeNumber(-0.25), "-0.25");
  EXPECT_EQ(describeNumber(1.0 / 3.0), "0.333333");  // six significant digits
  EXPECT_EQ(describeNumber(100000.0), "100000");
  EXPECT_EQ(describeNumber(1234567.0), "1.23457e+06");
  EXPECT_EQ(describeNumber(1e-7), "1e-07");
  EXPECT_EQ(describeNumber(-1.5e300), "-1.5e+300");
}

// One turn is singular, every other count plural ("0.5 turns" as English
// writes it), and a path's description uses the same words.
TEST(DescribeTurns, OneTurnIsSingularAndEveryOtherCountPlural) {
  EXPECT_EQ(describeTurns(1.0), "1 turn");
  EXPECT_EQ(describeTurns(2.0), "2 turns");
  EXPECT_EQ(describeTurns(0.5), "0.5 turns");
  EXPECT_EQ(describeTurns(1.25), "1.25 turns");
  const std::string one = test::lollipopPath(3.0, 1.0, true)->describe();
  EXPECT_NE(one.find("(1 turn, ccw)"), std::string::npos) << one;
  const std::string two = test::lollipopPath(3.0, 2.0, false)->describe();
  EXPECT_NE(two.find("(2 turns, cw)"), std::string::npos) << two;
}

// ẑ × n, normalised, for any length of n: horizontal and perpendicular to n.
TEST(DefaultTangent, IsTheUnitHorizontalZCrossNWhenNIsNotVertical) {
  struct Case {
    Vec3 n, expected;
  };
  const double r2 = std::sqrt(0.5);
  const Case cases[] = {
      {Vec3(1, 0, 0), Vec3(0, 1, 0)},   {Vec3(0, -2, 0), Vec3(1, 0, 0)},   {Vec3(1, 1, 1), Vec3(-r2, r2, 0)},
      {Vec3(0, 3, -4), Vec3(-1, 0, 0)}, {Vec3(1e-6, 0, 1), Vec3(0, 1, 0)},  // tilted by 1e-6: still a horizontal ẑ × n
  };
  for (const Case& c : cases) {
    const Vec3 t = defaultTangentFor(c.n);
    EXPECT_NEAR((t - c.expected).norm(), 0.0, 1e-12) << c.n.transpose();
    EXPECT_NEAR(t.norm(), 1.0, 1e-15) << c.n.transpose();
    EXPECT_NEAR(t.dot(c.n), 0.0, 1e-15) << c.n.transpose();
    EXPECT_EQ(t.z(), 0.0) << c.n.transpose();
  }
}

// Up or down (or tilted by less than ~1e-8), ẑ × n has no direction: x̂.
TEST(DefaultTangent, IsXWhenNIsVertical) {
  for (const Vec3& n : {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(0, 0, 7), Vec3(1e-10, -1e-10, 1), Vec3(0, 1e-9, -2)})
    EXPECT_EQ(defaultTangentFor(n), Vec3::UnitX()) << n.transpose();
}

TEST(DarbouxSample, DefaultsToARightHandedFrameAndTheCentreLiesAlongTheNormal) {
  DarbouxSample f;
  EXPECT_EQ(f.normal.cross(f.tangent), f.tangentNormal);  // u = n × t
  f.point = Vec3(1.0, -2.0, 0.5);
  f.normal = Vec3(0.0, 0.6, 0.8);
  EXPECT_NEAR((f.centre(2.5) - Vec3(1.0, -0.5, 2.5)).norm(), 0.0, 1e-15);
  EXPECT_EQ(f.centre(0.0), f.point);
}

// The fewest overrides a path needs: what ContactPath itself says about it.
class OnePieceTestPath final : public ContactPath {
 public:
  [[nodiscard]] double length() const override { return 2.0; }
  [[nodiscard]] DarbouxSample at(double s) const override {
    DarbouxSample f;
    f.s = s;
    f.point = Vec3(s, 0, 0);
    return f;
  }
  [[nodiscard]] Vec3 point(double s) const override { return Vec3(s, 0, 0); }
  [[nodiscard]] Vec3 normal(double) const override { return Vec3::UnitZ(); }
  [[nodiscard]] bool hasConstantCurvatures() const override { return true; }
  [[nodiscard]] std::string describe() const override { return "test line"; }
};

TEST(ContactPathDefaults, AnOpenPathOfOnePieceHasNoBreakpointsTurnsPiecesOrFinerApproximation) {
  const OnePieceTestPath path;
  EXPECT_TRUE(path.breakpoints().empty());
  EXPECT_EQ(path.turns(), 0.0);
  EXPECT_TRUE(path.pieces().empty());
  EXPECT_EQ(path.finerApproximation(), nullptr);
}

}  // namespace
}  // namespace rollspin::geometry
