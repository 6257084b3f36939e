// The spinor solver on curved surfaces where one term of the field decides
// the answer: the geodesic torsion τ_g on a helix (dropping it is visible
// against the kinematic oracle), and ω → 0 as 1 − κ_n R → 0 inside a
// cylinder (nothing divides by it). Moved here from the geometry suite,
// which no longer links spin/.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "geometry/surface_paths.hpp"
#include "kinematics/rolling_kinematics.hpp"
#include "support/numbers.hpp"
#include "surface_support.hpp"

using namespace rollspin;
using namespace rollspin::geometry;
using namespace rollspin::test;

namespace {

using rollspin::test::kDeg;

// The helix is not a line of curvature, so τ_g ≠ 0 enters ω. Dropping it
// changes the rolling by far more than 1e-3; keeping it matches the kinematics.
class WithoutTorsion final : public ContactPath {
 public:
  explicit WithoutTorsion(const ContactPath& p) : p_(p) {}
  double length() const override { return p_.length(); }
  DarbouxSample at(double s) const override {
    DarbouxSample f = p_.at(s);
    f.geodesicTorsion = 0.0;
    return f;
  }
  Vec3 point(double s) const override { return p_.point(s); }
  Vec3 normal(double s) const override { return p_.normal(s); }
  bool hasConstantCurvatures() const override { return p_.hasConstantCurvatures(); }
  std::string describe() const override { return p_.describe() + " (τ dropped)"; }

 private:
  const ContactPath& p_;
};

TEST(Torsion, DroppingItOnAHelixChangesTheResult) {
  auto cyl = std::make_shared<const Cylinder>(2.0, Vec3(0, 0, 1), Side::Outside);
  const auto helix = cylinderHelix(cyl, 30 * kDeg, 0.0, 1.0, true);
  const double R = 1.0;
  const Eigen::Matrix3d truth = kinematics::RollingKinematics(*helix, R, {40000, 0.0}).finalOrientation();
  const spin::Su2 with = spin::Propagator(*helix, R, spin::Method::Magnus4, 8000).solveFinal().final;
  const WithoutTorsion dropped(*helix);
  const spin::Su2 without = spin::Propagator(dropped, R, spin::Method::Magnus4, 8000).solveFinal().final;
  const double gapWith = rotationGap(with, truth), gapWithout = rotationGap(without, truth);
  EXPECT_LE(gapWith, 1e-10);
  EXPECT_GT(gapWithout, 1e-3);
  if (std::getenv("ROLLSPIN_VERBOSE")) std::printf("helix: with τ_g %.2e, without %.3e rad\n", gapWith, gapWithout);
  RecordProperty("gap_with_torsion", std::to_string(gapWith));
  RecordProperty("gap_without_torsion", std::to_string(gapWithout));
}

TEST(ContactValidity, OmegaVanishingIsFiniteAndCorrect) {
  // Inside a cylinder of radius a with R → a: 1 − κ_n R = 1 − R/a → 0 on a
  // parallel, so ω → τ_g t = 0; nothing divides by it.
  const double a = 2.0, R = a * (1.0 - 1e-13);
  auto cyl = std::make_shared<const Cylinder>(a, Vec3(0, 0, 1), Side::Inside);
  const auto path = cylinderParallel(cyl, 0.0, 1.0, true);
  ASSERT_TRUE(checkSingleContact(*path, R).ok);
  for (auto m : {spin::Method::Exact, spin::Method::Magnus4, spin::Method::Frame4}) {
    const spin::SolveStats st = spin::Propagator(*path, R, m, 400).solveFinal();
    ASSERT_EQ(st.status, spin::SolveStatus::Ok);
    // |ω| L = 2πa (1/R − 1/a) ≈ 2π·1e-13: the ball barely turns.
    EXPECT_LE(spin::rotationAngleAxis(st.final).angle, 1e-11) << spin::methodName(m);
  }
}

}  // namespace
