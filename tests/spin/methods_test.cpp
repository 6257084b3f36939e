// The issue-6 methods: observed orders of cf4 (4), magnus6 (6), Dormand–Prince
// (5), the adaptive methods against their tolerance (also at samples and
// across curvature jumps), unitarity of the geometric methods over 1e6 steps,
// and non-finite values reported as a status.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/surface_paths.hpp"
#include "oracle_support.hpp"
#include "spin/adaptive_march.hpp"
#include "spin/field.hpp"
#include "support/sweep.hpp"
#include "support/test_paths.hpp"

using namespace rollspin;
using namespace rollspin::test;
using spin::Method;

namespace {
// Error against the closed form on one lollipop circuit (R = 1, r = 3).
double lollipopError(Method m, long long steps, double tolerance = 0.0) {
  const auto path = lollipopPath(3.0);
  const spin::Su2 exact = solveFinal(*path, 1.0, Method::Exact, 0);
  const auto st = spin::Propagator(*path, 1.0, m, steps, tolerance).solveFinal();
  EXPECT_EQ(st.status, spin::SolveStatus::Ok) << spin::methodName(m);
  return spin::spinorDistance(st.final, exact);
}

// A closed rounded square on the floor: straight legs and corner arcs of
// radius 0.05 (κ_g jumps 0 ↔ 20 at eight breakpoints). frame4 is exact on
// each piece (constant κ_g) and its grid lands on the breakpoints, so at any
// step count it is the reference.
std::unique_ptr<geometry::ContactPath> roundedSquare() {
  auto plane = std::make_shared<const geometry::Plane>(Eigen::Vector3d::UnitZ());
  const std::vector<geometry::Vec2> corners{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  return geometry::pointsPath(plane, corners, true, geometry::PointsInterpolation::Polyline, 0.05);
}
}  // namespace

TEST(Methods, NamesRoundTripAndOrders) {
  for (Method m : spin::allMethods()) EXPECT_EQ(spin::parseMethod(spin::methodName(m)), m);
  EXPECT_EQ(spin::methodOrder(Method::Cf4), 4);
  EXPECT_EQ(spin::methodOrder(Method::Magnus6), 6);
  EXPECT_TRUE(spin::isAdaptive(Method::Rk45));
  EXPECT_TRUE(spin::isAdaptive(Method::Frame6a));
  EXPECT_FALSE(spin::isGeometric(Method::Rk45));
}

TEST(Methods, ObservedOrderOfEachFixedStepMethod) {
  // log₂ of the error ratio per halved step, where the error is far above
  // round-off (1e-4 … 1e-11): 2, 4, 4, 4, 6.
  struct Case {
    Method m;
    double order;
    long long coarse;
  };
  for (const Case c : {Case{Method::Magnus2, 2, 64}, Case{Method::Magnus4, 4, 40}, Case{Method::Rk4, 4, 80},
                       Case{Method::Cf4, 4, 40}, Case{Method::Magnus6, 6, 24}}) {
    for (long long n : {c.coarse, 2 * c.coarse}) {
      const double observed = std::log2(lollipopError(c.m, n) / lollipopError(c.m, 2 * n));
      EXPECT_NEAR(observed, c.order, 0.25) << spin::methodName(c.m) << " n=" << n;
    }
  }
}

TEST(Methods, Frame4IsFourthOrderOnAVaryingPath) {
  // On the lollipop frame4 is exact; a loxodrome on a sphere (κ_g varies)
  // shows its order, against magnus6 on a fine grid.
  auto sphere = std::make_shared<const geometry::Sphere>(2.0, geometry::Side::Outside);
  const auto path = geometry::sphereLoxodrome(sphere, 1.2, 0.0, 0.4, 2.6);
  const spin::Su2 ref = solveFinal(*path, 0.7, Method::Magnus6, 4000);
  auto err = [&](long long n) { return spin::spinorDistance(solveFinal(*path, 0.7, Method::Frame4, n), ref); };
  for (long long n : {40, 80}) EXPECT_NEAR(std::log2(err(n) / err(2 * n)), 4.0, 0.3) << n;
}

TEST(Methods, Frame6aBaseStepIsSixthOrderOnAVaryingPath) {
  // frame6a's step (magnus6 on g in the Darboux frame) on a uniform grid,
  // no error control, on the loxodrome where κ_g varies.
  auto sphere = std::make_shared<const geometry::Sphere>(2.0, geometry::Side::Outside);
  const auto path = geometry::sphereLoxodrome(sphere, 1.2, 0.0, 0.4, 2.6);
  const spin::Su2 ref = solveFinal(*path, 0.7, Method::Magnus6, 4000);
  auto err = [&](int n) {
    spin::Su2 u;
    const double h = path->length() / n;
    for (int k = 0; k < n; ++k) u = spin::adaptiveStep(*path, 0.7, Method::Frame6a, u, k * h, h);
    return spin::spinorDistance(u, ref);
  };
  for (int n : {10, 20}) EXPECT_NEAR(std::log2(err(n) / err(2 * n)), 6.0, 0.4) << n;
}

TEST(Methods, DormandPrinceStepIsFifthOrder) {
  // The rk45 base step on a uniform grid (no error control): order 5 in the
  // raw quaternion. (The leading local error, (1/600 − 1/720)(h ω)⁶ for a
  // rotation, changes only the norm, so the angle alone would show order 6.)
  const auto path = lollipopPath(3.0, 0.37);
  const spin::Su2 exact = solveFinal(*path, 1.0, Method::Exact, 0);
  auto err = [&](int n) {
    spin::Su2 u;
    const double h = path->length() / n;
    for (int k = 0; k < n; ++k) u = spin::adaptiveStep(*path, 1.0, Method::Rk45, u, k * h, h);
    return std::hypot(u.w - exact.w, u.x - exact.x, u.y - exact.y) + std::abs(u.z - exact.z);
  };
  for (int n : {16, 32}) EXPECT_NEAR(std::log2(err(n) / err(2 * n)), 5.0, 0.3) << n;
}

TEST(Methods, AdaptiveMeetsItsToleranceFinalAndAtSamples) {
  const auto path = lollipopPath(3.0, 2.0);
  const std::vector<double> s = spin::uniformSamples(path->length(), 37);
  std::vector<spin::Su2> exact(s.size());
  (void)spin::Propagator(*path, 1.0, Method::Exact, 0).run(s, [&](std::size_t j, double, const spin::Su2& q) {
    exact[j] = q;
  });
  for (double tol : {1e-5, 1e-8, 1e-11}) {
    for (Method m : {Method::Frame6a, Method::Rk45}) {
      double worst = 0.0;
      const auto st = spin::Propagator(*path, 1.0, m, 0, tol).run(s, [&](std::size_t j, double, const spin::Su2& q) {
        worst = std::max(worst, spin::spinorDistance(q, exact[j]));
      });
      ASSERT_EQ(st.status, spin::SolveStatus::Ok);
      EXPECT_GT(st.steps, 0);
      if (m == Method::Frame6a) EXPECT_LE(worst, 10 * tol) << tol;  // the geometric method's promise
      else EXPECT_LE(worst, 1e4 * tol) << tol;  // rk45: a per-step tolerance, global error not promised
    }
  }
}

TEST(Methods, AdaptiveLandsOnCurvatureJumps) {
  const auto path = roundedSquare();
  ASSERT_GE(path->breakpoints().size(), 7u);  // 8 tangent points, one of them the start
  const spin::Su2 ref = solveFinal(*path, 0.3, Method::Frame4, 2000);
  EXPECT_LT(spin::spinorDistance(ref, solveFinal(*path, 0.3, Method::Frame4, 200)), 1e-12);  // exact per piece
  for (double tol : {1e-6, 1e-10}) {
    const auto st = spin::Propagator(*path, 0.3, Method::Frame6a, 0, tol).solveFinal();
    ASSERT_EQ(st.status, spin::SolveStatus::Ok);
    EXPECT_LE(spin::spinorDistance(st.final, ref), 10 * tol) << tol;
  }
}

TEST(Methods, GeometricMethodsDriftLessThan1e13Per1e6Steps) {
  // A varying field (loxodrome: no rigid kernel) and a rigid one (lollipop:
  // the vector kernel for magnus2/4), 1e6 steps each (a sweep: the
  // sanitizer pass runs a sample of the six).
  const auto lolli = lollipopPath(3.0, 100.0);
  auto sphere = std::make_shared<const geometry::Sphere>(2.0, geometry::Side::Outside);
  const auto lox = geometry::sphereLoxodrome(sphere, 1.2, 0.0, 0.4, 2.6);
  struct Run {
    const geometry::ContactPath* path;
    double R;
    Method method;
  };
  const std::vector<Run> runs{{lolli.get(), 1.0, Method::Magnus2}, {lolli.get(), 1.0, Method::Magnus4},
                              {lolli.get(), 1.0, Method::Cf4},     {lolli.get(), 1.0, Method::Magnus6},
                              {lox.get(), 0.7, Method::Magnus4},   {lox.get(), 0.7, Method::Frame4}};
  for (const Run& run : test::sweep(runs)) {
    const std::string name =
        std::string(run.path == lolli.get() ? "lollipop " : "loxodrome ") + std::string(spin::methodName(run.method));
    const auto st = spin::Propagator(*run.path, run.R, run.method, 1'000'000).solveFinal();
    EXPECT_EQ(st.steps, 1'000'000) << name;
    EXPECT_LE(st.unitarityError, 1e-13) << name;
  }
}

TEST(Methods, DivergenceIsAStatusNotANumber) {
  // R = 1e-6 on a unit circle with 64 steps: h|ω| ≈ 1e5, rk4's polynomial
  // overflows; the march stops with NonFinite. The geometric methods stay
  // finite and unitary.
  const auto path = lollipopPath(1.0);
  EXPECT_EQ(spin::Propagator(*path, 1e-6, Method::Rk4, 64).solveFinal().status, spin::SolveStatus::NonFinite);
  for (Method m : {Method::Magnus4, Method::Cf4, Method::Magnus6}) {
    const auto st = spin::Propagator(*path, 1e-6, m, 64).solveFinal();
    EXPECT_EQ(st.status, spin::SolveStatus::Ok);
    EXPECT_LE(st.unitarityError, 1e-14);
  }
  EXPECT_EQ(spin::Propagator(*path, 1.0, Method::Frame6a, 0, 0.0).solveFinal().status, spin::SolveStatus::BadTolerance);
}
