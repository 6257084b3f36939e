// The stress suite's promises: the adaptive geometric method meets its
// tolerance (≤ 10×) on every stress case; exact and the Darboux-frame methods
// stay within 10× the round-off floor ε∫|B|ds on the stiff plane and sphere
// cases, whatever h|B|; the clothoid's frame and point agree with the
// independent kinematics, and its Landau–Zener probability approaches
// exp(−π/(2αR²)) like 1/S.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "geometry/clothoid_path.hpp"
#include "kinematics/rolling_kinematics.hpp"
#include "report/report_support.hpp"
#include "report/stress_cases.hpp"
#include "spin/field.hpp"
#include "support/sweep.hpp"

using namespace rollspin;
using spin::Method;

namespace {
spin::Su2 reference(const report::StressCase& c) {
  return report::makeReference(*c.path, c.ballRadius, 2, 0,
                               c.referenceMethod == Method::Exact ? Method::Magnus6 : c.referenceMethod)
      .samples.back();
}
}  // namespace

TEST(Stress, AdaptiveMeetsItsToleranceOnEveryStressCase) {
  for (const report::StressCase& c : report::stressCases()) {
    const spin::Su2 ref = reference(c);
    const auto st = spin::Propagator(*c.path, c.ballRadius, Method::Frame6a, 0, c.tolerance).solveFinal();
    ASSERT_EQ(st.status, spin::SolveStatus::Ok) << c.name;
    EXPECT_LE(spin::spinorDistance(st.final, ref), 10.0 * c.tolerance) << c.name;
  }
}

TEST(Stress, ExactAndFrameMethodsWithinTenTimesTheFloorOnStiffCases) {
  int stiff = 0;
  for (const report::StressCase& c : report::stressCases()) {
    if (!c.stiff) continue;
    ++stiff;
    const double floor = report::kEpsilon * spin::integratedFieldStrength(*c.path, c.ballRadius);
    const spin::Su2 exact = spin::Propagator(*c.path, c.ballRadius, Method::Exact, 0).solveFinal().final;
    // frame4 on the case's own coarse grid (h|B| up to 1e5) and frame6a asked
    // for the floor itself: both integrate only κ_g, constant here.
    const auto f4 = spin::Propagator(*c.path, c.ballRadius, Method::Frame4, c.fixedSteps).solveFinal();
    const auto f6 = spin::Propagator(*c.path, c.ballRadius, Method::Frame6a, 0, floor).solveFinal();
    ASSERT_EQ(f4.status, spin::SolveStatus::Ok);
    ASSERT_EQ(f6.status, spin::SolveStatus::Ok);
    // The closed form against the same closed form built independently of
    // the propagator's cached rates is round-off by construction; compare it
    // with frame6a instead, and both frame methods with it.
    EXPECT_LE(spin::spinorDistance(f4.final, exact), 10 * floor) << c.name;
    EXPECT_LE(spin::spinorDistance(f6.final, exact), 10 * floor) << c.name;
  }
  EXPECT_EQ(stiff, 3);  // plane R/r = 1e-6, 1e-3, sphere outside R/r = 1e-6
}

TEST(Clothoid, FrameAndPointAgreeWithTheKinematics) {
  const auto path = geometry::PlaneClothoidPath::symmetricSweep(0.5, 12.0);
  // dP/ds = t and |dP/ds| = 1 along the tabulated Fresnel integrals.
  for (double s : {0.0, 1.3, 5.9, 6.0, 11.2, 12.0}) {
    const double h = 1e-4, a = std::max(0.0, s - h), b = std::min(12.0, s + h);
    const Eigen::Vector3d d = (path->point(b) - path->point(a)) / (b - a);
    EXPECT_LT((d - path->at(0.5 * (a + b)).tangent).norm(), 1e-6) << s;  // central difference: O(h²κ²)
  }
  const spin::Su2 u = spin::Propagator(*path, 0.8, Method::Frame6a, 0, 1e-12).solveFinal().final;
  const Eigen::Quaterniond k(kinematics::RollingKinematics(*path, 0.8, {40000, 0.0}).finalOrientation());
  EXPECT_LT(spin::rotationDistance(u, spin::Su2{k.w(), k.x(), k.y(), k.z()}), 1e-9);
}

TEST(Clothoid, LandauZenerProbabilityApproachesTheAsymptoteLikeOneOverS) {
  const double alpha = 1.0, R = 1.0, pLz = report::landauZener(alpha, R);
  EXPECT_NEAR(pLz, std::exp(-M_PI / 2), 1e-15);
  for (double S : {20.0, 40.0}) {
    const auto path = geometry::PlaneClothoidPath::symmetricSweep(alpha, 2 * S);
    const auto st = spin::Propagator(*path, R, Method::Frame6a, 0, 1e-10).solveFinal();
    ASSERT_EQ(st.status, spin::SolveStatus::Ok);
    EXPECT_LT(std::abs(report::stayProbability(st.final) - pLz), 0.5 / S) << S;  // measured S·|ΔP| ≤ 0.21
  }
}

// The a posteriori estimate (spin::estimateError) on the stress suite: the
// error against the case's reference is at most 3× the estimate + 1e-13, and
// the estimate at most 1000× the error where that is above 1e-12. For the
// methods the suite expects to resolve each case: frame4 on the case's grid
// and frame6a at its tolerance everywhere, exact where the curvatures are
// constant, magnus4 on the case's grid where it is not stiff.
TEST(Stress, ErrorEstimateIsConservativeAndNotWildlyPessimistic) {
  for (const report::StressCase& c : test::sweep(report::stressCases())) {
    const spin::Su2 ref = reference(c);
    std::vector<std::pair<Method, bool>> runs{{Method::Frame4, false}, {Method::Frame6a, true}};
    if (c.path->hasConstantCurvatures() && c.path->pieces().empty()) runs.push_back({Method::Exact, false});
    if (!c.stiff) runs.push_back({Method::Magnus4, false});
    for (const auto& [method, adaptive] : runs) {
      const long long steps = adaptive ? 0 : c.fixedSteps;
      const double tolerance = adaptive ? c.tolerance : 0.0;
      spin::SolveStats st = spin::Propagator(*c.path, c.ballRadius, method, steps, tolerance).solveFinal();
      ASSERT_EQ(st.status, spin::SolveStatus::Ok) << c.name;
      spin::estimateError(*c.path, c.ballRadius, method, steps, tolerance, st);
      const double error = spin::rotationDistance(st.final, ref);
      if (std::getenv("ROLLSPIN_VERBOSE"))
        std::printf("%-28s %-8s error %.2e estimate %.2e\n", c.name.c_str(),
                    std::string(spin::methodName(method)).c_str(), error, st.errorEstimate);
      EXPECT_LE(error, 3.0 * st.errorEstimate + 1e-13) << c.name << " " << spin::methodName(method);
      if (error > 1e-12) {
        EXPECT_LE(st.errorEstimate, 1000.0 * error) << c.name << " " << spin::methodName(method);
      }
    }
  }
}
