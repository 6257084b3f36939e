// Geometry of curves on surfaces: κ_n, κ_g, τ_g against closed forms, the
// identity τ_g² + κ_n² − 2Hκ_n + K = 0 at every sample of every case, the
// Darboux frame against finite differences of the surface's own point and
// normal, and arc length. (The torsion term's effect on the rolling is a
// solver test: tests/spin/surface_solver_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "geometry/analytic_paths.hpp"
#include "geometry/surface_paths.hpp"
#include "support/numbers.hpp"
#include "support/surface_cases.hpp"

using namespace rollspin;
using namespace rollspin::geometry;
using namespace rollspin::test;

namespace {

using rollspin::test::kDeg;
using rollspin::test::kPi;

std::vector<double> grid(double length, int n) {
  std::vector<double> s;
  for (int k = 0; k <= n; ++k) s.push_back(length * (k + 0.31) / (n + 1));
  return s;
}

TEST(Curvature, CylinderHelixMatchesClosedForms) {
  for (double a : {0.7, 2.0})
    for (double beta : {-50 * kDeg, 10 * kDeg, 35 * kDeg, 70 * kDeg})
      for (bool outside : {true, false}) {
        auto cyl = std::make_shared<const Cylinder>(a, Vec3(0, 0, 1), outside ? Side::Outside : Side::Inside);
        const auto path = cylinderHelix(cyl, beta, 0.0, 1.5, true);
        const double side = outside ? 1.0 : -1.0;
        for (double s : grid(path->length(), 40)) {
          const DarbouxSample f = path->at(s);
          EXPECT_NEAR(f.normalCurvature, -side * std::cos(beta) * std::cos(beta) / a, 1e-13);
          EXPECT_NEAR(std::abs(f.geodesicTorsion), std::abs(std::sin(beta) * std::cos(beta)) / a, 1e-13);
          EXPECT_NEAR(f.geodesicCurvature, 0.0, 1e-13);  // helices are geodesics of the cylinder
        }
      }
}

TEST(Curvature, TorusParallelsHaveNoTorsion) {
  const double A = 4.0, a = 1.5;
  for (bool outside : {true, false})
    for (double psi : {0.0, 40 * kDeg, 90 * kDeg, 150 * kDeg, 180 * kDeg}) {
      auto torus = std::make_shared<const Torus>(A, a, outside ? Side::Outside : Side::Inside);
      const auto path = torusParallel(torus, psi, 1.0, true);
      const double side = outside ? 1.0 : -1.0, rho = A + a * std::cos(psi);
      EXPECT_NEAR(path->length(), 2 * kPi * rho, 1e-12);
      for (double s : grid(path->length(), 30)) {
        const DarbouxSample f = path->at(s);
        EXPECT_NEAR(f.geodesicTorsion, 0.0, 1e-13);
        EXPECT_NEAR(f.normalCurvature, -side * std::cos(psi) / rho, 1e-13);
        EXPECT_NEAR(std::abs(f.geodesicCurvature), std::abs(std::sin(psi)) / rho, 1e-13);
      }
    }
}

TEST(Curvature, ParaboloidParallelsMatchClosedForms) {
  // z = ρ²/(2a): slope tan β = ρ/a; seen from above the bowl curves towards
  // the ball: κ_n = cos β / a along the parallel... in closed form
  // κ_n = 1/(a √(1 + ρ²/a²)), |κ_g| = 1/(ρ √(1 + ρ²/a²)), τ_g = 0.
  const double a = 3.0;
  for (bool above : {true, false})
    for (double rho : {0.5, 2.0, 5.0}) {
      const auto path = heightFieldParallel(HeightField::quadric(a, a, false, above), rho, 1.0, !above);
      const double q = std::sqrt(1 + rho * rho / (a * a)), side = above ? 1.0 : -1.0;
      for (double s : grid(path->length(), 30)) {
        const DarbouxSample f = path->at(s);
        EXPECT_NEAR(f.normalCurvature, side / (a * q), 1e-13);
        EXPECT_NEAR(std::abs(f.geodesicCurvature), 1.0 / (rho * q), 1e-13);
        EXPECT_NEAR(f.geodesicTorsion, 0.0, 1e-13);
      }
    }
}

TEST(Curvature, LoxodromeMatchesClosedForms) {
  // Heading α from the meridians on a sphere of radius r: κ_n = ∓1/r (every
  // direction is principal: τ_g = 0), |κ_g| = |sin α cot θ| / r.
  const double r = 3.0;
  for (bool outside : {true, false})
    for (double alpha : {-60 * kDeg, 20 * kDeg, 75 * kDeg}) {
      auto sphere = std::make_shared<const Sphere>(r, outside ? Side::Outside : Side::Inside);
      const auto path = sphereLoxodrome(sphere, alpha, 0.3, 25 * kDeg, 160 * kDeg);
      EXPECT_NEAR(path->length(), r * (135 * kDeg) / std::cos(alpha), 1e-12);
      for (double s : grid(path->length(), 30)) {
        const DarbouxSample f = path->at(s);
        const double theta = path->uvAt(s).x();
        EXPECT_NEAR(f.normalCurvature, (outside ? -1.0 : 1.0) / r, 1e-13);
        EXPECT_NEAR(f.geodesicTorsion, 0.0, 1e-13);
        EXPECT_NEAR(std::abs(f.geodesicCurvature), std::abs(std::sin(alpha) / std::tan(theta)) / r, 1e-12);
      }
    }
}

TEST(Curvature, GenericSphereParallelEqualsTheAnalyticPath) {
  for (bool outside : {true, false})
    for (double theta : {20 * kDeg, 90 * kDeg, 130 * kDeg}) {
      auto sphere = std::make_shared<const Sphere>(2.5, outside ? Side::Outside : Side::Inside);
      const auto generic = sphereParallel(sphere, theta, 1.0, false);
      const SphereParallelPath analytic(sphere, theta, 1.0, false);
      EXPECT_NEAR(generic->length(), analytic.length(), 1e-13);
      for (double s : grid(analytic.length(), 25)) {
        const DarbouxSample g = generic->at(s), h = analytic.at(s);
        EXPECT_LE((g.point - h.point).norm(), 1e-13);
        EXPECT_LE((g.tangent - h.tangent).norm(), 1e-13);
        EXPECT_LE((g.tangentNormal - h.tangentNormal).norm(), 1e-13);
        EXPECT_NEAR(g.normalCurvature, h.normalCurvature, 1e-13);
        EXPECT_NEAR(g.geodesicCurvature, h.geodesicCurvature, 1e-13);
        EXPECT_NEAR(g.geodesicTorsion, 0.0, 1e-13);
      }
    }
}

// Every case: the curvature identity, and the frame against differences of
// point(s) and normal(s) (fourth-order, h = 1e-4 inside breakpoint segments).
TEST(Curvature, IdentityAndFiniteDifferencesOnEveryCase) {
  for (const SurfaceCase& c : allSurfaceCases()) {
    const auto path = c.make();
    const auto* curve = dynamic_cast<const SurfaceCurvePath*>(path.get());
    ASSERT_NE(curve, nullptr);
    std::vector<double> cuts{0.0};
    for (double b : path->breakpoints()) cuts.push_back(b);
    cuts.push_back(path->length());
    double worstIdentity = 0.0, worstFrame = 0.0, worstSpeed = 0.0;
    for (double s : grid(path->length(), 200)) {
      const DarbouxSample f = path->at(s);
      const SurfaceShape shape = shapeAt(curve->surface(), curve->uvAt(s));
      const double identity = f.geodesicTorsion * f.geodesicTorsion + f.normalCurvature * f.normalCurvature -
                              2 * shape.meanCurvature * f.normalCurvature + shape.gaussCurvature;
      worstIdentity = std::max(worstIdentity, std::abs(identity));
      // Stencil inside the segment.
      std::size_t seg = 0;
      while (seg + 2 < cuts.size() && s >= cuts[seg + 1]) ++seg;
      const double h = 1e-4;
      if (s - 2 * h <= cuts[seg] || s + 2 * h >= cuts[seg + 1]) continue;
      auto d = [&](auto fn) {
        return ((-fn(s + 2 * h) + 8 * fn(s + h) - 8 * fn(s - h) + fn(s - 2 * h)) / (12 * h)).eval();
      };
      const Vec3 dP = d([&](double x) { return path->point(x); });
      const Vec3 dN = d([&](double x) { return path->normal(x); });
      worstSpeed = std::max(worstSpeed, std::abs(dP.norm() - 1.0));
      worstFrame = std::max({worstFrame, (dP - f.tangent).norm(), (f.normal - path->normal(s)).norm(),
                             std::abs(-dN.dot(f.tangent) - f.normalCurvature),
                             std::abs(-dN.dot(f.tangentNormal) - f.geodesicTorsion)});
    }
    EXPECT_LE(worstIdentity, 1e-12) << c.name;
    EXPECT_LE(worstFrame, 1e-8) << c.name;
    EXPECT_LE(worstSpeed, 1e-8) << c.name;
  }
}

// Geodesics are integrated (RK4 in arc length, then Chebyshev panels), not
// chords: their geodesic curvature stays at the integration error.
TEST(Geodesic, GeodesicCurvatureVanishes) {
  for (const SurfaceCase& c : allSurfaceCases()) {
    if (c.name.find("geodesic") == std::string::npos) continue;
    const auto path = c.make();
    double worst = 0.0;
    for (double s : grid(path->length(), 400)) worst = std::max(worst, std::abs(path->at(s).geodesicCurvature));
    if (std::getenv("ROLLSPIN_VERBOSE")) std::printf("%-20s max |κ_g| %.1e\n", c.name.c_str(), worst);
    EXPECT_LE(worst, 3e-8) << c.name;  // measured ≤ 7.2e-9 (sphere, torus)
  }
}

TEST(ArcLength, InverseMapIsExactToRoundOff) {
  for (const SurfaceCase& c : allSurfaceCases()) {
    const auto path = c.make();
    const auto* curve = dynamic_cast<const SurfaceCurvePath*>(path.get());
    double worst = 0.0;
    for (double s : grid(path->length(), 300))
      worst = std::max(worst, std::abs(curve->arcLengthAt(curve->parameterAt(s)) - s) / (1.0 + s));
    EXPECT_LE(worst, 1e-13) << c.name;
  }
}

}  // namespace
