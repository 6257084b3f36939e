// frame4 (Magnus in the Darboux frame, composed exactly with the frame):
// exact for constant curvatures at any step count (even one step per turn); fourth order when κ_g varies; and
// on curves with large geodesic curvature far more accurate than space-frame
// magnus4 at equal steps, because the fast turning of ω is the frame's own
// rotation, which frame4 takes exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "support/numbers.hpp"
#include "surface_support.hpp"

using namespace rollspin;
using namespace rollspin::geometry;
using namespace rollspin::test;

namespace {

using rollspin::test::kPi;

spin::Su2 finalOf(const ContactPath& path, double R, spin::Method m, long long steps) {
  const spin::SolveStats st = spin::Propagator(path, R, m, steps).solveFinal();
  EXPECT_EQ(st.status, spin::SolveStatus::Ok);
  return st.final;
}

TEST(Frame4, ExactOnConstantCurvaturesAtAnyStepCount) {
  auto torus = std::make_shared<const Torus>(4.0, 1.5, Side::Inside);
  auto cyl = std::make_shared<const Cylinder>(2.0, Vec3(0, 0, 1), Side::Outside);
  const std::unique_ptr<ContactPath> paths[] = {torusParallel(torus, 1.0, 1.0, true),
                                                cylinderHelix(cyl, 0.5, 0.0, 2.0, false)};
  for (const auto& path : paths) {
    const spin::Su2 exact = finalOf(*path, 0.9, spin::Method::Exact, 0);
    for (long long steps : {1LL, 2LL, 5LL, 17LL})
      EXPECT_LE(spin::spinorDistance(finalOf(*path, 0.9, spin::Method::Frame4, steps), exact), 1e-12)
          << path->describe() << " steps " << steps;
  }
}

// A tight spiral on the floor, five times round, radius 0.2 + growth·t
// against R = 1: κ_g ≈ 5, varying slowly.
std::unique_ptr<ContactPath> tightSpiral(double growth) {
  auto plane = std::make_shared<const Plane>(Vec3(0, 0, 1));
  auto e = [](const std::string& t) { return std::make_shared<const Expression>(t, std::vector<std::string>{"t"}); };
  const std::string radius = "(0.2+" + std::to_string(growth) + "*t)";
  return uvExpressionPath(plane, e(radius + "*cos(t)"), e(radius + "*sin(t)"), 0.0, 10 * kPi);
}

TEST(Frame4, FourthOrderWhenGeodesicCurvatureVaries) {
  const auto path = tightSpiral(0.01);  // κ_g from 5 down to 2
  const spin::Su2 reference = finalOf(*path, 1.0, spin::Method::Frame4, 64000);
  double previous = 0.0;
  for (long long steps : {250LL, 500LL, 1000LL}) {
    const double err = spin::spinorDistance(finalOf(*path, 1.0, spin::Method::Frame4, steps), reference);
    if (previous > 0.0) {
      const double ratio = previous / err;
      EXPECT_GT(ratio, 12.0) << "steps " << steps;
      EXPECT_LT(ratio, 20.0) << "steps " << steps;
    }
    previous = err;
  }
}

TEST(Frame4, FarMoreAccurateThanMagnus4AtEqualStepsWhenKappaGIsLarge) {
  const auto path = tightSpiral(0.002);  // κ_g from 5 down to 3.9
  const spin::Su2 reference = finalOf(*path, 1.0, spin::Method::Frame4, 64000);
  for (long long steps : {150LL, 300LL}) {
    const double frameErr = spin::spinorDistance(finalOf(*path, 1.0, spin::Method::Frame4, steps), reference);
    const double spaceErr = spin::spinorDistance(finalOf(*path, 1.0, spin::Method::Magnus4, steps), reference);
    if (std::getenv("ROLLSPIN_VERBOSE"))
      std::printf("steps %lld: frame4 %.2e magnus4 %.2e (ratio %.0f)\n", steps, frameErr, spaceErr,
                  spaceErr / frameErr);
    EXPECT_LT(100.0 * frameErr, spaceErr) << "steps " << steps;
  }
  // And the reference itself agrees with the kinematics.
  EXPECT_LE(compareWithKinematics(*path, 1.0, spin::Method::Frame4, 8000, 60000, 5).worstGap, 1e-10);
}

}  // namespace
